// The plotted map must agree with the solver: no feasible grid point below the optimum, the
// feasibility mask equal to the limits, and the region's corners feasible and in order.
#include "Fixtures.h"

#include <aeronc/core/Error.h>
#include <aeronc/optimise/ObjectiveMap.h>

#include <cmath>

namespace aeronc::optimise::test {

TEST(ObjectiveMap, AgreesWithTheSolverOnTheSeedExample) {
    const Problem p = seedProblem();
    const Solution s = solve(p);
    const auto m = objectiveMap(p, s, {});
    const auto& ns = m.at("n_rpm");
    const auto& fzs = m.at("f_z_mm");
    ASSERT_EQ(ns.size(), 61u);
    ASSERT_EQ(fzs.size(), 61u);
    EXPECT_NEAR(ns.front().get<double>(), s.combined.n / 3, 1e-9 * s.combined.n);
    EXPECT_NEAR(fzs.back().get<double>(), s.combined.fz * 3, 1e-12);

    const Posynomial f = combinedObjective(p, s.time.objective, s.cost.objective);
    const auto cs = constraintsOf(p);
    int feasibleCount = 0, infeasibleCount = 0;
    for (std::size_t i = 0; i < fzs.size(); ++i)
        for (std::size_t j = 0; j < ns.size(); ++j) {
            const double n = ns[j], fz = fzs[i];
            const double v = m["objective"][i][j];
            EXPECT_DOUBLE_EQ(v, f(n, fz));
            bool ok = true;
            for (const auto& c : cs) ok = ok && c.utilisation(n, fz) <= 1 + kFeasibilityTolerance;
            ASSERT_EQ(m["feasible"][i][j].get<bool>(), ok) << n << " " << fz;
            if (ok) {
                ++feasibleCount;
                EXPECT_GE(v, s.combined.objective * (1 - 1e-9)) << "grid point beats the optimum at " << n << ", " << fz;
            } else {
                ++infeasibleCount;
            }
        }
    // Power and roughness are active: the box around the optimum holds both kinds of point.
    EXPECT_GT(feasibleCount, 100);
    EXPECT_GT(infeasibleCount, 100);

    const auto& region = m.at("region");
    ASSERT_GE(region.size(), 3u);
    const Region r = Region::of(p);
    double turn = 0;
    for (std::size_t k = 0; k < region.size(); ++k) {
        const auto& a = region[k];
        const auto& b = region[(k + 1) % region.size()];
        const auto& c = region[(k + 2) % region.size()];
        EXPECT_TRUE(r.contains(a[0], a[1]));
        const double ux = std::log(b[0].get<double>() / a[0].get<double>()),
                     uy = std::log(b[1].get<double>() / a[1].get<double>());
        const double vx = std::log(c[0].get<double>() / b[0].get<double>()),
                     vy = std::log(c[1].get<double>() / b[1].get<double>());
        turn = ux * vy - uy * vx;
        EXPECT_GT(turn, 0) << "corners are not in counter-clockwise order at " << k;
    }
    EXPECT_EQ(m.at("limits").size(), cs.size());
    EXPECT_DOUBLE_EQ(m["optimum"]["n_rpm"].get<double>(), s.combined.n);
}

TEST(ObjectiveMap, AGearboxShowsItsStepsAndNoPolygon) {
    Problem p = seedProblem();
    p.machine.spindleSteps = x5032Steps();
    const auto m = objectiveMap(p, solve(p), {});
    EXPECT_EQ(m.at("spindle_steps_rpm").size(), 18u);
    EXPECT_TRUE(m.at("region").empty());
}

TEST(ObjectiveMap, RefusesAnEmptyBoxOrGrid) {
    const Problem p = seedProblem();
    const Solution s = solve(p);
    MapBox box;
    box.nCount = 1;
    EXPECT_THROW(objectiveMap(p, s, box), Error);
    box = {};
    box.nLow = 500, box.nHigh = 400;
    EXPECT_THROW(objectiveMap(p, s, box), Error);
}

}  // namespace aeronc::optimise::test
