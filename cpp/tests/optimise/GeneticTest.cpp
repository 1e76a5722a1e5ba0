// The genetic algorithm, the comparison option: a fixed seed repeats, and it lands near the
// deterministic optimum without beating it.
#include "Fixtures.h"

#include <aeronc/core/Error.h>
#include <aeronc/optimise/Genetic.h>

using namespace aeronc::optimise;

TEST(Genetic, FixedSeedRepeats) {
    const Problem p = test::seedProblem();
    const Solution a = solveGenetic(p), b = solveGenetic(p);
    EXPECT_EQ(a.combined.n, b.combined.n);
    EXPECT_EQ(a.combined.fz, b.combined.fz);
    GeneticOptions other;
    other.seed = 2;
    const Solution c = solveGenetic(p, other);
    EXPECT_TRUE(c.combined.n != a.combined.n || c.combined.fz != a.combined.fz);
}

TEST(Genetic, LandsNearTheDeterministicOptimumWithoutBeatingIt) {
    const Problem p = test::seedProblem();
    const Solution d = solve(p);
    for (std::uint64_t seed : {1, 2, 3, 4, 5}) {
        GeneticOptions o;
        o.seed = seed;
        const Solution g = solveGenetic(p, o);
        ASSERT_TRUE(g.combined.feasible) << seed;
        EXPECT_GE(g.time.objective, d.time.objective * (1 - 1e-9));
        EXPECT_GE(g.cost.objective, d.cost.objective * (1 - 1e-9));
        // Within 1 % of the optimal objective and 3 % of its speed and feed.
        EXPECT_LT(g.time.objective, d.time.objective * 1.01) << seed;
        EXPECT_NEAR(g.combined.n, d.combined.n, 0.03 * d.combined.n) << seed;
        EXPECT_NEAR(g.combined.fz, d.combined.fz, 0.03 * d.combined.fz) << seed;
    }
}

TEST(Genetic, SteppedSpindleGivesAStep) {
    Problem p = test::seedProblem();
    p.machine.spindleSteps = test::x5032Steps();
    const Solution g = solveGenetic(p), d = solve(p);
    ASSERT_TRUE(g.combined.feasible);
    EXPECT_EQ(g.combined.n, d.combined.n);  // 18 steps are few enough to find the right one
    EXPECT_NEAR(g.combined.fz, d.combined.fz, 0.03 * d.combined.fz);
}

TEST(Genetic, RefusesAnEmptyPopulation) {
    GeneticOptions o;
    o.population = 1;
    EXPECT_THROW(solveGenetic(test::seedProblem(), o), aeronc::Error);
}
