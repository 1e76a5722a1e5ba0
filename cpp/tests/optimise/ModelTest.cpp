// The physical model and its monomial/posynomial forms agree, and the formulas give the
// numbers a hand calculation gives.
#include "Fixtures.h"

#include <aeronc/optimise/Constraints.h>
#include <aeronc/optimise/CuttingModel.h>
#include <aeronc/optimise/Objective.h>

#include <cmath>
#include <random>

using namespace aeronc::optimise;

TEST(CuttingModel, ForceAndPowerByHand) {
    const Problem p = test::seedProblem();
    // 9.81*825*3^1*0.169^0.75*100^1.1*4 / (125^1.3*396.1^0.2) * 0.935, term by term.
    const double byHand = 9.81 * 825 * 3 * std::pow(0.169, 0.75) * std::pow(100, 1.1) * 4 /
                          (std::pow(125, 1.3) * std::pow(396.1, 0.2)) * 0.935;
    EXPECT_NEAR(cuttingForce(p, 396.1, 0.169), byHand, 1e-9 * byHand);
    EXPECT_NEAR(byHand, 2156, 1.0);  // the order of magnitude the doc quotes
    const double v = M_PI * 125 * 396.1 / 1000;
    EXPECT_NEAR(cuttingSpeed(p, 396.1), v, 1e-12);
    EXPECT_NEAR(cuttingPower(p, 396.1, 0.169), byHand * v / (60000 * 0.75), 1e-9);
    EXPECT_NEAR(roughness(p, 0.169), 1000 / (18 * std::sqrt(3.0)) * 0.169 * 0.169 / 1.0, 1e-12);
}

TEST(CuttingModel, ToolLifeInvertsTheSpeedFormula) {
    const Problem p = test::seedProblem();
    for (double T : {15.0, 60.0, 180.0, 1000.0}) {
        const double n = speedForToolLife(p, T, 0.15);
        EXPECT_NEAR(toolLife(p, n, 0.15), T, 1e-9 * T);
        // v = C_v*d^q/(T^m*a_p^x*f^y*a_e^u*Z^p)*K_v
        const double v = 332 * std::pow(125, 0.2) / (std::pow(T, 0.2) * std::pow(3, 0.1) * std::pow(0.15, 0.4) *
                                                     std::pow(100, 0.2));
        EXPECT_NEAR(cuttingSpeed(p, n), v, 1e-9 * v);
    }
}

TEST(CuttingModel, PlainTaylorWhenOnlyCAndM) {
    Problem p = test::seedProblem();
    p.toolLife = {};
    p.toolLife.cV = 300, p.toolLife.m = 0.25;
    const double v = cuttingSpeed(p, 500);
    EXPECT_NEAR(v * std::pow(toolLife(p, 500, 0.1), 0.25), 300, 1e-9);
    EXPECT_NEAR(toolLife(p, 500, 0.1), toolLife(p, 500, 0.3), 1e-9);  // no feed dependence
}

TEST(CuttingModel, TimeAndCostPerPartByHand) {
    const Problem p = test::seedProblem();
    const Evaluation e = evaluate(p, 400, 0.16);
    const double tm = 640 / (0.16 * 4 * 400);
    EXPECT_NEAR(e.machiningTime, tm, 1e-12);
    EXPECT_NEAR(e.time, 1.0 + tm + 2.0 * tm / e.toolLife, 1e-12);
    EXPECT_NEAR(e.cost, 1.0 * (1.0 + tm) + (1.0 * 2.0 + 40) * tm / e.toolLife, 1e-12);
}

// The solver works on monomials and posynomials; they must be the model, everywhere.
TEST(CuttingModel, MonomialsAndPosynomialsMatchTheModel) {
    Problem p = test::seedProblem();
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> logN(std::log(10.0), std::log(5000.0)), logF(std::log(0.005), std::log(1.0));
    const auto cs = constraintsOf(p);
    const Posynomial t = timePerPart(p), c = costPerPart(p), f = combinedObjective(p, 3.0, 4.0);
    for (int i = 0; i < 200; ++i) {
        const double n = std::exp(logN(rng)), fz = std::exp(logF(rng));
        const Evaluation e = evaluate(p, n, fz);
        EXPECT_NEAR(cs[0].value(n, fz) / e.force, 1, 1e-12);
        EXPECT_NEAR(cs[1].value(n, fz) / e.power, 1, 1e-12);
        EXPECT_NEAR(cs[2].value(n, fz) / e.feedRate, 1, 1e-12);
        EXPECT_NEAR(cs[3].value(n, fz) / e.roughness, 1, 1e-12);
        EXPECT_NEAR(t(n, fz) / e.time, 1, 1e-12);
        EXPECT_NEAR(c(n, fz) / e.cost, 1, 1e-12);
        EXPECT_NEAR(f(n, fz) / (0.5 * e.time / 3.0 + 0.5 * e.cost / 4.0), 1, 1e-12);
        double dX, dY, h = 1e-6;
        const double X = std::log(n), Y = std::log(fz), v = f.atLog(X, Y, dX, dY);
        double a, b;
        EXPECT_NEAR(dX, (f.atLog(X + h, Y, a, b) - f.atLog(X - h, Y, a, b)) / (2 * h), 1e-6 * std::abs(v));
        EXPECT_NEAR(dY, (f.atLog(X, Y + h, a, b) - f.atLog(X, Y - h, a, b)) / (2 * h), 1e-6 * std::abs(v));
    }
}

TEST(Region, CornersAreFeasibleAndTheBoxIsTight) {
    const Problem p = test::seedProblem();
    const Region r = Region::of(p);
    const auto corners = r.corners();
    ASSERT_GE(corners.size(), 3u);
    for (const auto& c : corners) EXPECT_TRUE(r.contains(c.n, c.fz)) << c.n << " " << c.fz;
    // The highest feasible f_z is the roughness limit's.
    const auto top = r.minimum(0, -1);
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->fz, std::sqrt(0.92 * 1.0 / p.quality.raCoefficient), 1e-9);
    // At that f_z the power limit caps n.
    const auto range = r.speedRange(top->fz);
    ASSERT_TRUE(range);
    EXPECT_NEAR(cuttingPower(p, (*range)[1], top->fz), 7.5, 1e-8);
}
