// The synthetic-distortion checks: a known hole pattern on a flat and on a curved skin, moved
// by a rigid offset, a scale, an affine distortion and a smooth bending; the datum holes
// measured where the distortion put them; every method compensates the drilling holes and
// its error against the distorted positions is printed.
#include "Fixtures.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>

using namespace aeronc::compensation;
using namespace aeronc::compensation::test;

namespace {

struct Figures {
    std::map<Method, HoleError> error;
    std::map<Method, double> loo;
    std::optional<Method> proposed;
};

Figures run(const Pattern& p, const NamedDistortion& d) {
    Figures f;
    CompensationInput in;
    in.datums = measuredDatums(p, d.apply);
    in.holes = drillingHoles(p);
    for (Method m : allMethods()) {
        const auto r = compensate(in, m);
        f.error[m] = holeError(r, d.apply);
        f.proposed = r.proposed;
        for (const auto& l : r.leaveOneOut)
            if (l.method == m) f.loo[m] = l.rms;
    }
    std::printf("%-12s %-15s", p.name.c_str(), d.name.c_str());
    for (Method m : allMethods()) std::printf(" %9.2e", f.error[m].rms);
    std::printf("  proposed %s\n", f.proposed ? methodName(*f.proposed).c_str() : "-");
    return f;
}

double bestInterpolated(const Figures& f) {
    double best = INFINITY;
    for (Method m : {Method::RigidIdw, Method::SimilarityIdw, Method::RigidTps, Method::SimilarityTps})
        best = std::min(best, f.error.at(m).rms);
    return best;
}

}  // namespace

TEST(Distortions, EachMethodsErrorOnTheDrillingHoles) {
    std::printf("RMS error on the drilling holes (mm), %d datum holes per row at both ends and the middle\n", 3);
    std::printf("%-12s %-15s", "skin", "distortion");
    for (Method m : allMethods()) std::printf(" %9s", methodName(m).c_str());
    std::printf("\n");
    for (const Pattern& p : {flatSkin(), curvedSkin()}) {
        for (const auto& d : distortions(p)) {
            const Figures f = run(p, d);
            if (d.name == "rigid offset" || d.name == "scale") {
                // A similarity fit is exact for rigid and scale errors, and is proposed (the rigid
                // fit for a rigid offset, earlier in the order).
                EXPECT_LT(f.error.at(Method::Similarity).max, 1e-9) << p.name << " " << d.name;
                EXPECT_LT(f.loo.at(Method::Similarity), 1e-9);
                ASSERT_TRUE(f.proposed);
                EXPECT_EQ(*f.proposed, d.name == "scale" ? Method::Similarity : Method::Rigid) << p.name;
            }
            if (d.name == "rigid offset") EXPECT_LT(f.error.at(Method::Rigid).max, 1e-9);
            if (d.name == "scale") EXPECT_GT(f.error.at(Method::Rigid).max, 1e-3);
            if (d.name == "affine") {
                // What a similarity leaves of an affine distortion, the spline takes up.
                EXPECT_LT(f.error.at(Method::SimilarityTps).rms, 0.5 * f.error.at(Method::Similarity).rms) << p.name;
            }
            if (!d.linear) {
                // The best-fit methods do better than the seed's on the non-linear distortion,
                // and the proposal is an interpolated residual.
                EXPECT_LT(bestInterpolated(f), f.error.at(Method::Seed).rms) << p.name;
                EXPECT_LT(bestInterpolated(f), 0.5 * f.error.at(Method::Similarity).rms) << p.name;
                ASSERT_TRUE(f.proposed);
                EXPECT_NE(*f.proposed, Method::Seed);
                EXPECT_NE(*f.proposed, Method::Rigid);
                EXPECT_NE(*f.proposed, Method::Similarity);
            }
        }
    }
}

// The seed's method is exact for linear distortions along straight rows (flat skin), not along
// the curved rows of the curved skin, where the row is not a straight line in the part frame.
TEST(Distortions, SeedIsExactAlongStraightRowsOnly) {
    const Pattern fp = flatSkin(), cp = curvedSkin();
    const auto rigid = distortions(fp)[0].apply;
    CompensationInput flat, curved;
    flat.datums = measuredDatums(fp, rigid);
    flat.holes = drillingHoles(fp);
    curved.datums = measuredDatums(cp, rigid);
    curved.holes = drillingHoles(cp);
    EXPECT_LT(holeError(compensate(flat, Method::Seed), rigid).max, 1e-9);
    EXPECT_GT(holeError(compensate(curved, Method::Seed), rigid).max, 1e-4);
}
