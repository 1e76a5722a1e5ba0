// The JSON boundary: the same toolpaths as the C++ calls, the documented move format, and a
// clear message for each mistake.
#include "ErrorOf.h"
#include "Checks.h"

#include <aeronc/toolpath/Drilling.h>
#include <aeronc/toolpath/PocketClearing.h>
#include <aeronc/toolpath/ToolpathJson.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace aeronc::toolpath;
using aeronc::test::inputErrorOf;
using json = nlohmann::json;

namespace {
json pocketUnit() {
    return {{"operation", "pocket"},
            {"contour", {{0, 0}, {60, 0}, {60, 40}, {0, 40}}},
            {"islands", {{{20, 15}, {30, 15}, {30, 25}, {20, 25}}}},
            {"top", 0},
            {"bottom", -9},
            {"radialAllowance", 0.3},
            {"axialAllowance", 0.1},
            {"stepDown", 3},
            {"stepOver", 4},
            {"rampAngle", 4},
            {"clearance", 3},
            {"safeHeight", 20},
            {"cutter", {{"diameter", 8}, {"cornerRadius", 0.5}}}};
}
}  // namespace

TEST(ToolpathJson, PocketMatchesTheDirectCall) {
    const json out = json::parse(toolpathJson(pocketUnit().dump()));
    PocketParameters p;
    p.radialAllowance = 0.3, p.axialAllowance = 0.1, p.stepDown = 3, p.stepOver = 4, p.rampAngleDeg = 4;
    p.clearance = 3, p.safeHeight = 20;
    const Toolpath t = pocketClearing({{{0, 0}, {60, 0}, {60, 40}, {0, 40}}, {{{20, 15}, {30, 15}, {30, 25}, {20, 25}}}, {}, 0, -9},
                                      {8, 0.5}, p);
    ASSERT_EQ(out["moves"].size(), t.moves.size());
    for (std::size_t i = 0; i < t.moves.size(); ++i) {
        const auto& m = out["moves"][i];
        ASSERT_EQ(m.size(), 4u);
        EXPECT_EQ(m[0].get<int>(), int(t.moves[i].kind));
        EXPECT_NEAR(m[1].get<double>(), t.moves[i].u, 5e-7);
        EXPECT_NEAR(m[2].get<double>(), t.moves[i].v, 5e-7);
        EXPECT_NEAR(m[3].get<double>(), t.moves[i].h, 5e-7);
    }
    EXPECT_NEAR(out["cutLength"].get<double>(), t.cutLength, 5e-7);
    EXPECT_NEAR(out["rapidLength"].get<double>(), t.rapidLength, 5e-7);
    EXPECT_EQ(out["moves"][0][3].get<double>(), 20);  // starts at the safe height
}

TEST(ToolpathJson, DrillMovesCarryTheCycle) {
    const json unit{{"operation", "drill"},
                    {"holes", {{{"u", 5}, {"v", -2.5}, {"diameter", 6}, {"top", 0}, {"bottom", -10}, {"through", true}}}},
                    {"peck", 2},
                    {"dwell", 0.5},
                    {"cutter", {{"diameter", 6}}}};
    const json out = json::parse(toolpathJson(unit.dump()));
    std::size_t cycles = 0;
    for (const auto& m : out["moves"]) {
        if (m[0] != 3) continue;
        ++cycles;
        ASSERT_EQ(m.size(), 7u);
        EXPECT_EQ(m[1].get<double>(), 5);
        EXPECT_EQ(m[2].get<double>(), -2.5);
        EXPECT_NEAR(m[3].get<double>(), -10 - drillTipLength(6, 118) - 0.5, 1e-6);
        EXPECT_EQ(m[4].get<double>(), 2);  // R plane: top + default clearance
        EXPECT_EQ(m[5].get<double>(), 2);
        EXPECT_EQ(m[6].get<double>(), 0.5);
    }
    EXPECT_EQ(cycles, 1u);
}

TEST(ToolpathJson, EveryOperationAnswers) {
    const json cutter{{"diameter", 10}};
    const json square = {{0, 0}, {50, 0}, {50, 50}, {0, 50}};
    for (const json& unit :
         {json{{"operation", "profile"}, {"contour", square}, {"top", 0}, {"bottom", -4}, {"side", "inside"}, {"lead", "line"},
               {"cutter", cutter}},
          json{{"operation", "profile"}, {"contour", {{0, 0}, {50, 0}}}, {"closed", false}, {"side", "right"},
               {"startLimit", {5, 0}}, {"endLimit", {45, 0}}, {"top", 0}, {"bottom", -4}, {"cutter", cutter}},
          json{{"operation", "helix"},
               {"holes", {{{"u", 0}, {"v", 0}, {"diameter", 20}, {"top", 0}, {"bottom", -5}}}},
               {"cutter", cutter}},
          json{{"operation", "rest"}, {"contour", square}, {"top", 0}, {"bottom", -4}, {"cutter", {{"diameter", 4}}},
               {"previousCutter", cutter}, {"stepOver", 2}}}) {
        const json out = json::parse(toolpathJson(unit.dump()));
        EXPECT_GT(out["moves"].size(), 10u) << unit["operation"];
        EXPECT_GT(out["cutLength"].get<double>(), 0) << unit["operation"];
    }
}

// A rest unit after a roughing that left more than it leaves: "previousAllowance" makes the band
// between the two part of its rest, so it cuts more than when the roughing left the same.
TEST(ToolpathJson, RestTakesThePreviousUnitsAllowance) {
    const json square = {{0, 0}, {50, 0}, {50, 50}, {0, 50}};
    json unit = {{"operation", "rest"}, {"contour", square}, {"top", 0}, {"bottom", -4},
                 {"cutter", {{"diameter", 4}}}, {"previousCutter", {{"diameter", 10}}}, {"stepOver", 2},
                 {"radialAllowance", 0.2}};
    const double same = json::parse(toolpathJson(unit.dump()))["cutLength"].get<double>();
    unit["previousAllowance"] = 1.0;
    const double more = json::parse(toolpathJson(unit.dump()))["cutLength"].get<double>();
    EXPECT_GT(more, 2 * same);
    unit["previousAllowance"] = "much";
    EXPECT_NE(inputErrorOf([&] { toolpathJson(unit.dump()); }).find("previousAllowance"), std::string::npos);
    unit["previousAllowance"] = -1;
    EXPECT_NE(inputErrorOf([&] { toolpathJson(unit.dump()); }).find("previous unit's radial allowance"),
              std::string::npos);
}

TEST(ToolpathJson, MistakesAreNamed) {
    auto err = [](const std::string& text) { return inputErrorOf([&] { toolpathJson(text); }); };
    EXPECT_NE(err("{not json").find("not valid JSON"), std::string::npos);
    EXPECT_NE(err("[1, 2]").find("JSON object"), std::string::npos);
    EXPECT_NE(err(R"({"operation": "mill"})").find("unknown operation 'mill'"), std::string::npos);
    json u = pocketUnit();
    u["stepover"] = 3;
    EXPECT_NE(err(u.dump()).find("unknown key \"stepover\""), std::string::npos);
    u = pocketUnit();
    u.erase("cutter");
    EXPECT_NE(err(u.dump()).find("missing \"cutter\""), std::string::npos);
    u = pocketUnit();
    u.erase("top");
    EXPECT_NE(err(u.dump()).find("missing \"top\""), std::string::npos);
    u = pocketUnit();
    u["stepDown"] = "four";
    EXPECT_NE(err(u.dump()).find("wrong type"), std::string::npos);
    u = pocketUnit();
    u["contour"] = {{0, 0}, {1, 1, 1}};
    EXPECT_NE(err(u.dump()).find("[u, v]"), std::string::npos);
    u = pocketUnit();
    u["name"] = "P7";
    u["cutter"]["diameter"] = 80;
    const std::string m = err(u.dump());
    EXPECT_EQ(m.rfind("unit 'P7': ", 0), 0u) << m;
    EXPECT_NE(m.find("does not fit"), std::string::npos);
    u = pocketUnit();
    u["operation"] = "rest";
    EXPECT_NE(err(u.dump()).find("previousCutter"), std::string::npos);
    EXPECT_NE(err(R"({"operation": "drill", "cutter": {"diameter": 5}})").find("holes"), std::string::npos);
    EXPECT_NE(err(R"({"operation": "profile", "contour": [[0,0],[9,0]], "top": 0, "bottom": -1,
                      "side": "up", "cutter": {"diameter": 5}})")
                  .find("unknown side"),
              std::string::npos);
}
