// Bad input: an infeasible problem names its conflicting limits and the nearest relaxation
// (which must then work); missing coefficients and non-physical values are named.
#include "ErrorOf.h"

#include "Fixtures.h"

#include <aeronc/core/Error.h>
#include <aeronc/optimise/Report.h>

using namespace aeronc::optimise;
using aeronc::Error;

using aeronc::test::inputErrorOf;

namespace {

std::string parseError(const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = test::seedJson();
    edit(j);
    return inputErrorOf([&] { parseParameters(j); });
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

// Too little power for even the lightest admissible cut: power must be named, and raising
// P_max to the suggested value must make the problem solvable with power just active.
TEST(BadInput, TooLittlePowerNamesPowerAndTheRelaxationWorks) {
    Problem p = test::seedProblem();
    p.machine.power = 0.05;
    p.feedPerTooth.min = 0.05;
    const std::string m = inputErrorOf([&] { solve(p); });
    EXPECT_TRUE(has(m, "infeasible")) << m;
    EXPECT_TRUE(has(m, "raise P_max from 0.05 to")) << m;
    const Region r = Region::of(p);
    const auto rel = singleRelaxations(r);
    ASSERT_FALSE(rel.empty());
    // The nearest single relaxation here: power, or the f_z search minimum.
    bool sawPower = false;
    for (const auto& x : rel) {
        Problem q = p;
        const double limit = x.neededLimit * (x.constraint.upper ? 1 + 1e-7 : 1 - 1e-7);
        switch (x.constraint.kind) {
            case ConstraintKind::Power: q.machine.power = limit, sawPower = true; break;
            case ConstraintKind::FeedPerToothMin: q.feedPerTooth.min = limit; break;
            case ConstraintKind::SpindleMin: q.machine.minSpindle = limit; break;
            default: FAIL() << "unexpected relaxation of " << x.constraint.symbol;
        }
        const Solution s = solve(q);  // must not throw
        EXPECT_TRUE(s.combined.feasible);
    }
    EXPECT_TRUE(sawPower);
    // Just below the suggested power it is still infeasible: the relaxation is the nearest.
    Problem q = p;
    for (const auto& x : rel)
        if (x.constraint.kind == ConstraintKind::Power) q.machine.power = x.neededLimit * (1 - 1e-6);
    EXPECT_THROW(solve(q), Error);
}

TEST(BadInput, RoughnessAgainstTheFeedRangeNamesBoth) {
    Problem p = test::seedProblem();
    p.quality.raMax = 0.0001;
    const std::string m = inputErrorOf([&] { solve(p); });
    EXPECT_TRUE(has(m, "R_a,max")) << m;
    EXPECT_TRUE(has(m, "f_z,min")) << m;
    EXPECT_TRUE(has(m, "lower f_z,min from 0.005 to")) << m;
}

TEST(BadInput, NoStepInsideTheSpindleRange) {
    Problem p = test::seedProblem();
    p.machine.spindleSteps = {2000, 2500};
    const std::string m = inputErrorOf([&] { solve(p); });
    EXPECT_TRUE(has(m, "spindle steps")) << m;
    EXPECT_TRUE(has(m, "raise n_max from 1800 to")) << m;
}

TEST(BadInput, FeedLimitBelowTheLeastFeed) {
    Problem p = test::seedProblem();
    p.machine.maxFeed = 0.1;  // less than Z * n_min * f_z,min = 4*30*0.005 = 0.6 mm/min
    const std::string m = inputErrorOf([&] { solve(p); });
    EXPECT_TRUE(has(m, "raise v_f,max from 0.1 to 0.6 mm/min")) << m;
}

TEST(BadInput, MissingCoefficientsAreNamed) {
    EXPECT_TRUE(has(parseError([](auto& j) { j["force"].erase("C_F"); }), "force.C_F")) << "C_F";
    EXPECT_TRUE(has(parseError([](auto& j) { j["force"].erase("y_F"); }), "force.y_F"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["tool_life"].erase("m"); }), "tool_life.m"));
    EXPECT_TRUE(has(parseError([](auto& j) { j.erase("force"); }), "missing section \"force\""));
    EXPECT_TRUE(has(parseError([](auto& j) { j["machine"].erase("power_kw"); }), "machine.power_kw"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["economics"].erase("t_c_min"); }), "economics.t_c_min"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["quality"].erase("ra_max_um"); }), "quality.ra_max_um"));
}

TEST(BadInput, WrongTypesAndUnknownKeys) {
    EXPECT_TRUE(has(parseError([](auto& j) { j["force"]["C_F"] = "825"; }), "force.C_F must be a number"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["force"]["CF"] = 825; }), "unknown key force.CF"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["frobnicate"] = 1; }), "unknown key \"frobnicate\""));
    EXPECT_TRUE(has(parseError([](auto& j) { j["cutter"]["teeth"] = 4.5; }), "whole number"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["baseline"]["n_rpm"] = 400; }), "exactly one of"));
}

TEST(BadInput, NonPhysicalValuesAreNamed) {
    EXPECT_TRUE(has(parseError([](auto& j) { j["cutter"]["diameter_mm"] = 0; }), "cutter diameter d_0 must be positive"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["cutter"]["diameter_mm"] = -125; }), "got -125"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["cutter"]["teeth"] = 0; }), "teeth Z must be at least 1"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["cut"]["a_p_mm"] = 0; }), "depth of cut a_p must be positive"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["cut"]["a_e_mm"] = -1; }), "width of cut a_e must be positive"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["cut"]["a_e_mm"] = 200; }), "exceeds the cutter diameter"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["machine"]["efficiency"] = 1.5; }), "efficiency eta must be at most 1"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["machine"]["min_spindle_rpm"] = 2000; }), "exceeds n_max"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["tool_life"]["m"] = 0; }), "tool-life exponent m must be positive"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["cutter"]["corner_radius_mm"] = 0; }), "corner radius r"));
    EXPECT_TRUE(has(parseError([](auto& j) { j["machine"]["spindle_steps_rpm"] = {300, 200}; }), "ascending"));
    EXPECT_TRUE(has(parseError([](auto& j) {
                        j["economics"]["w_time"] = 0;
                        j["economics"]["w_cost"] = 0;
                    }),
                    "both zero"));
}

TEST(BadInput, UnknownMethod) {
    EXPECT_TRUE(has(inputErrorOf([] { parseMethod("simplex"); }), "nlopt, ga or both"));
}
