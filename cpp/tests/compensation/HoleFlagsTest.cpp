// What is flagged: the neighbour check of the corrections, and the flags of a compensation with
// their reasons.
#include "Fixtures.h"

#include <gtest/gtest.h>

using namespace aeronc::compensation;
using namespace aeronc::compensation::test;

namespace {

Vec3 linearField(const Vec3& p) {
    Mat3 a;
    a << 2e-4, -1e-3, 3e-4, 1e-3, 4e-4, -2e-4, 5e-4, 1e-4, 1e-4;
    return a * p + Vec3(0.5, -0.3, 0.2);
}

std::vector<Vec3> positionsOf(const Pattern& p) { return p.points; }

}  // namespace

TEST(HoleFlags, ALinearCorrectionFieldDepartsFromNoNeighbour) {
    for (const Pattern& p : {flatSkin(), curvedSkin(), flatSkin(1, 21)}) {
        std::vector<Vec3> c;
        for (const auto& x : p.points) c.push_back(linearField(x));
        const auto d = neighbourDepartures(positionsOf(p), c);
        ASSERT_EQ(d.size(), p.points.size());
        // Exact on the flat skin and along one row; on the curved skin the holes' plane leaves out
        // the skin's sag between neighbours (about 1.6 mm x the field's 1e-3 slope).
        const double limit = p.name == "curved skin" ? 5e-3 : 1e-10;
        EXPECT_LT(*std::max_element(d.begin(), d.end()), limit) << p.name << " " << p.points.size();
    }
}

TEST(HoleFlags, ACorrectionOutOfLineIsFoundAtItsHole) {
    for (const Pattern& p : {flatSkin(), flatSkin(1, 21)}) {
        std::vector<Vec3> c;
        for (const auto& x : p.points) c.push_back(linearField(x));
        const size_t spike = p.rows[0][10];
        c[spike] += Vec3(0.0, 0.2, 0.1);
        const auto d = neighbourDepartures(positionsOf(p), c);
        EXPECT_NEAR(d[spike], std::sqrt(0.05), 1e-9) << p.name;
        for (size_t i = 0; i < d.size(); ++i)
            if (i != spike) EXPECT_LT(d[i], 0.6 * d[spike]) << p.name << " hole " << i;
    }
    // Too few holes to have a trend.
    EXPECT_EQ(neighbourDepartures({Vec3::Zero(), Vec3::UnitX()}, {Vec3::Zero(), Vec3::UnitY()}),
              (std::vector<double>{0.0, 0.0}));
}

// The case: 180 holes moved 0.62 mm by the assembly, a datum reading 0.8 mm off. The
// flags say what happened: the datum hole left out, then the holes beyond the tolerance.
TEST(HoleFlags, FlagsSayWhatToLookAtAndWhy) {
    const Pattern p = fiveByFortyOne();
    const int bad = p.rows[2][20];
    CompensationInput in;
    in.datums = measuredDatums(p, assemblyOffset);
    addNoise(in.datums, 0.01, 5);
    misread(in.datums, bad, 0.8 * alongRow(p, bad));
    in.holes = drillingHoles(p);
    auto r = compensate(in);
    ASSERT_EQ(r.holes.size(), 180u);
    ASSERT_FALSE(r.flags.empty());
    EXPECT_EQ(r.flags.front().kind, FlagKind::DatumLeftOut);
    EXPECT_EQ(r.flags.front().id, datumId(bad));
    EXPECT_EQ(flagKindName(r.flags.front().kind), "datum left out");
    EXPECT_NE(r.flags.front().reason.find(") from where the other datum holes put it"), std::string::npos);
    int beyond = 0, against = 0;
    for (const auto& f : r.flags) {
        beyond += f.kind == FlagKind::BeyondTolerance;
        against += f.kind == FlagKind::AgainstNeighbours;
        if (f.kind == FlagKind::BeyondTolerance)
            EXPECT_NE(f.reason.find("beyond the 0.500 mm tolerance"), std::string::npos) << f.reason;
    }
    EXPECT_EQ(beyond, 180);  // |(0.5, -0.3, 0.2)| = 0.62 mm: every hole moves farther than 0.5 mm
    EXPECT_EQ(against, 0);   // a rigid fit moves the holes alike
    EXPECT_EQ(r.flaggedHoles, 180);
    in.tolerance = 0.7;
    r = compensate(in);
    EXPECT_EQ(r.flaggedHoles, 0);
    EXPECT_EQ(r.flags.size(), 1u);

    // The reading put back and a spline through it: the holes round it are pulled out of line
    // with their neighbours, and flagged for it; the rigid fit moves them all a little instead.
    in.keep = {datumId(bad)};
    r = compensate(in, Method::RigidTps);
    std::vector<std::string> pulled;
    for (const auto& f : r.flags)
        if (f.kind == FlagKind::AgainstNeighbours) {
            pulled.push_back(f.id);
            EXPECT_NE(f.reason.find("from its neighbours'"), std::string::npos) << f.reason;
            EXPECT_GT(f.value, f.limit);
        }
    ASSERT_FALSE(pulled.empty());
    for (const auto& h : r.holes)
        if (h.againstNeighbours) EXPECT_LT((h.nominal - p.points[static_cast<size_t>(bad)]).norm(), 60.0) << h.id;
    int flagged = 0;
    for (const auto& h : r.holes) flagged += h.againstNeighbours || h.exceedsTolerance;
    EXPECT_EQ(r.flaggedHoles, flagged);
    EXPECT_GE(flagged, static_cast<int>(pulled.size()));
    r = compensate(in, Method::Rigid);
    for (const auto& h : r.holes) EXPECT_FALSE(h.againstNeighbours) << h.id;
}
