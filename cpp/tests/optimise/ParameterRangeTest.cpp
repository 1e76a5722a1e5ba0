// Parameter files that are valid JSON but outside any physical range: deep nesting once
// overflowed the stack while a message was written; a huge exponent once gave a NaN fitness
// marked feasible, or a force and power of 0 and an objective map of NaNs.
#include "ErrorOf.h"

#include "Fixtures.h"

#include <aeronc/optimise/Genetic.h>
#include <aeronc/optimise/ObjectiveMap.h>
#include <aeronc/optimise/Report.h>
#include <aeronc/optimise/Solver.h>

#include <cmath>

using namespace aeronc::optimise;
using aeronc::test::inputErrorOf;

namespace {

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string deepArray(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

}  // namespace

TEST(ParameterRange, DeepNestingIsAnErrorNotAStackOverflow) {
    // Through the text reader the CLI and the binding use.
    std::string text = test::seedJson().dump();
    text.insert(text.rfind('}'), ",\"notes\":" + deepArray(100000));
    EXPECT_TRUE(has(inputErrorOf([&] { parameterJson(text); }), "nested")) << "text";
    // A value nested 100,000 deep where a number belongs, given as JSON already.
    nlohmann::json j = test::seedJson();
    j["cutter"]["diameter_mm"] = nlohmann::json::parse(deepArray(100000));
    const std::string m = inputErrorOf([&] { parseParameters(j); });
    EXPECT_TRUE(has(m, "cutter.diameter_mm must be a number")) << m;
    EXPECT_LT(m.size(), 300u) << m;
}

TEST(ParameterRange, NotJsonAtAllIsNamed) {
    EXPECT_TRUE(has(inputErrorOf([] { parameterJson("{\"cutter\": "); }), "not valid JSON"));
    EXPECT_TRUE(has(inputErrorOf([] { parameterJson("{\"a\": 1e400}"); }), "not valid JSON"));
    // Nesting within the limit is read.
    EXPECT_NO_THROW(parameterJson("{\"notes\": " + deepArray(50) + "}"));
}

TEST(ParameterRange, ExponentsThatOverflowTheModelAreRefused) {
    struct Case {
        const char* section;
        const char* key;
        double value;
    };
    const Case cases[] = {
        {"tool_life", "q_v", -9.2e18}, {"tool_life", "q_v", 9.2e18}, {"tool_life", "x_v", 1e300},
        {"tool_life", "m", 1e-300},    {"force", "q_F", 9223372036854775808.0}, {"force", "w_F", -1e10},
        {"force", "x_F", 1e5},         {"force", "C_F", 1e308},                {"tool_life", "C_v", 1e-308},
    };
    for (const Case& c : cases) {
        nlohmann::json j = test::seedJson();
        j[c.section][c.key] = c.value;
        const std::string m = inputErrorOf([&] { parseParameters(j); });
        EXPECT_TRUE(has(m, "search box")) << c.section << "." << c.key << " = " << c.value << ": " << m;
    }
}

TEST(ParameterRange, TheGeneticAlgorithmNeverCallsANaNFeasible) {
    // Bypassing the parameter file: the problem as a caller could build it.
    Problem p = test::seedProblem();
    p.toolLife.qV = -9.2e18;
    EXPECT_TRUE(has(inputErrorOf([&] { solveGenetic(p, GeneticOptions{}); }), "search box"));
    p = test::seedProblem();
    p.force.qF = 9223372036854775808.0;
    EXPECT_TRUE(has(inputErrorOf([&] { solveGenetic(p, GeneticOptions{}); }), "search box"));
    EXPECT_TRUE(has(inputErrorOf([&] { objectiveMap(p, Solution{}, MapBox{}); }), "search box"));
}

TEST(ParameterRange, TheShippedParameterFilesStillSolve) {
    const Parameters ps = test::seedParameters();
    const Solution s = solveGenetic(ps.problem, GeneticOptions{});
    EXPECT_TRUE(s.combined.feasible);
    EXPECT_TRUE(std::isfinite(s.combined.objective));
    EXPECT_GT(s.combined.at.force, 0);
    EXPECT_GT(s.combined.at.power, 0);
}
