// The JSON contract: programs in, reports out, and a clear message for every malformed input.
#include <aeronc/verify/ReportJson.h>

#include "../ErrorOf.h"
#include "Fixtures.h"

#include <gtest/gtest.h>

using namespace aeronc::verify;
using namespace aeronc::verify::test;
using aeronc::test::inputErrorOf;
using nlohmann::json;

namespace {

json validProgram() {
    return json::parse(R"({
        "cellSize": 0.5,
        "blank": [0, 0, 0, 60, 40, 20],
        "ops": [
          {"label": "rough", "axis": [0, 0, 1], "cutter": {"diameter": 6, "cornerRadius": 0},
           "radialAllowance": 0.5, "axialAllowance": 0.3,
           "moves": [[0, 14, 14, 25], [2, 14, 14, 8.3], [1, 46, 14, 8.3], [0, 46, 14, 25]]},
          {"label": "drill", "axis": [0, 0, -1], "cutter": {"diameter": 6.6},
           "moves": [[3, 5, 5, 12, -2, 1.5, 0.2]]}
        ],
        "finishedFaces": [7, 8],
        "elements": {"pocket": [7, 8, 9]}
    })");
}

std::string programError(const std::function<void(json&)>& edit) {
    json j = validProgram();
    edit(j);
    return inputErrorOf([&] { programFromJson(j); });
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(ProgramJson, ReadsEveryField) {
    const Program p = programFromJson(validProgram());
    EXPECT_DOUBLE_EQ(p.cellSize, 0.5);
    EXPECT_TRUE(p.hasBlank);
    EXPECT_DOUBLE_EQ(p.blank[5], 20);
    ASSERT_EQ(p.operations.size(), 2u);
    const Operation& rough = p.operations[0];
    EXPECT_EQ(rough.label, "rough");
    EXPECT_EQ(rough.axis, 1);
    EXPECT_DOUBLE_EQ(rough.cutter.radius, 3);
    EXPECT_DOUBLE_EQ(rough.radialAllowance, 0.5);
    EXPECT_DOUBLE_EQ(rough.axialAllowance, 0.3);
    ASSERT_EQ(rough.moves.size(), 4u);
    EXPECT_EQ(rough.moves[1].kind, MoveKind::Plunge);
    EXPECT_DOUBLE_EQ(rough.moves[1].z, 8.3);
    const Operation& drill = p.operations[1];
    EXPECT_EQ(drill.axis, -1);
    EXPECT_DOUBLE_EQ(drill.cutter.cornerRadius, 0);
    EXPECT_EQ(drill.moves[0].kind, MoveKind::DrillCycle);
    EXPECT_DOUBLE_EQ(drill.moves[0].retract, -2);
    EXPECT_DOUBLE_EQ(drill.moves[0].peck, 1.5);
    EXPECT_EQ(p.finishedFaces, (std::vector<int>{7, 8}));
    ASSERT_EQ(p.elements.size(), 1u);
    EXPECT_EQ(p.elements[0].first, "pocket");
    EXPECT_EQ(p.elements[0].second, (std::vector<int>{7, 8, 9}));
}

TEST(ProgramJson, NamesWhatIsWrong) {
    EXPECT_TRUE(has(inputErrorOf([] { programFromJson(json::array()); }), "JSON object"));
    EXPECT_TRUE(has(programError([](json& j) { j.erase("ops"); }), "\"ops\""));
    EXPECT_TRUE(has(programError([](json& j) { j["cellSize"] = 0; }), "cellSize"));
    EXPECT_TRUE(has(programError([](json& j) { j["blank"] = {0, 0, 0, 60, 40}; }), "blank"));
    EXPECT_TRUE(has(programError([](json& j) { j["blank"] = {0, 0, 30, 60, 40, 20}; }), "blank"));
    const auto axis = programError([](json& j) { j["ops"][0]["axis"] = {1, 0, 0}; });
    EXPECT_TRUE(has(axis, "'rough'") && has(axis, "+Z or -Z")) << axis;
    EXPECT_TRUE(has(programError([](json& j) { j["ops"][0].erase("cutter"); }), "needs a cutter"));
    const auto dia = programError([](json& j) { j["ops"][0]["cutter"]["diameter"] = -6; });
    EXPECT_TRUE(has(dia, "'rough'") && has(dia, "diameter")) << dia;
    EXPECT_TRUE(has(programError([](json& j) { j["ops"][0]["cutter"]["cornerRadius"] = 4; }), "corner radius"));
    EXPECT_TRUE(has(programError([](json& j) { j["ops"][0]["moves"][2] = {1, 46, 14}; }), "move 2"));
    EXPECT_TRUE(has(programError([](json& j) { j["ops"][0]["moves"][2] = {7, 46, 14, 8}; }), "kind"));
    EXPECT_TRUE(has(programError([](json& j) { j["ops"][0]["moves"][2] = {1, 46, "a", 8}; }), "move 2 y"));
    EXPECT_TRUE(has(programError([](json& j) { j["ops"][0]["moves"][2] = {1, 46, 14, 8, 9}; }), "[kind, x, y, z]"));
    EXPECT_TRUE(has(programError([](json& j) { j["ops"][1]["moves"][0] = {3, 5, 5, 12}; }), "drill cycle"));
    EXPECT_TRUE(has(programError([](json& j) { j["ops"][0].erase("moves"); }), "list of moves"));
    EXPECT_TRUE(has(programError([](json& j) { j["finishedFaces"] = {7, 0}; }), "finishedFaces[1]"));
    EXPECT_TRUE(has(programError([](json& j) { j["elements"] = {1, 2}; }), "elements"));
    EXPECT_TRUE(has(programError([](json& j) { j["ops"][0]["radialAllowance"] = -3; }), "radial allowance"));
}

TEST(ProgramJson, OptionsAreChecked) {
    const SimulationOptions o =
        simulationOptionsFromJson(json::parse(R"({"floorTolerance": 0.05, "leftoverMap": false, "maxListed": 3})"));
    EXPECT_DOUBLE_EQ(o.coverage.floorTolerance, 0.05);
    EXPECT_FALSE(o.leftoverMap);
    EXPECT_EQ(o.maxListed, 3);
    EXPECT_TRUE(has(inputErrorOf([] { simulationOptionsFromJson(json{{"gougeTolerance", -1}}); }), "gougeTolerance"));
    EXPECT_TRUE(has(inputErrorOf([] { simulationOptionsFromJson(json{{"wallSearch", 0}}); }), "wallSearch"));
    EXPECT_TRUE(has(inputErrorOf([] { simulationOptionsFromJson(json{{"leftoverMap", 1}}); }), "leftoverMap"));
    EXPECT_TRUE(has(inputErrorOf([] { simulationOptionsFromJson(json{{"maxListed", 1.5}}); }), "maxListed"));
    EXPECT_TRUE(has(inputErrorOf([] { simulationOptionsFromJson(json{{"floorTolerence", 0.1}}); }), "floorTolerence"));
    EXPECT_NO_THROW(simulationOptionsFromJson(json{{"deflection", 0.01}}));
}

TEST(ProgramJson, ReportCarriesTheChecksAndTheMap) {
    const PocketSpec pocket{10, 10, 50, 30, 4, 8};
    const Plate plate = makePlate(60, 40, 20, {pocket});
    json j = validProgram();
    j["ops"].erase(1);
    json moves = json::array();
    for (const Move& m : pocketPath(pocket, 3, 2.4, 7.9, 25)) moves.push_back({int(m.kind), m.x, m.y, m.z});
    j["ops"][0]["moves"] = moves;
    j["ops"][0]["radialAllowance"] = 0;
    j["ops"][0]["axialAllowance"] = 0;
    j["finishedFaces"] = {plate.pockets[0].floor};
    SimulationOptions o;
    o.maxListed = 5;
    const json r = toJson(simulate(plate.mesh, programFromJson(j), o));

    EXPECT_EQ(r["grid"]["nx"], 120);
    EXPECT_EQ(r["grid"]["ny"], 80);
    EXPECT_GT(r["gouges"]["count"].get<int>(), 5);
    EXPECT_EQ(r["gouges"]["list"].size(), 5u);
    const json& worst = r["gouges"]["worst"];
    EXPECT_DOUBLE_EQ(worst["depth"].get<double>(), 0.1);
    EXPECT_EQ(worst["kind"], "floor");
    EXPECT_EQ(worst["op"], "rough");
    EXPECT_EQ(worst["face"], plate.pockets[0].floor);
    EXPECT_EQ(worst["position"].size(), 3u);
    EXPECT_EQ(r["collisions"]["count"], 0);
    EXPECT_TRUE(r["collisions"]["worst"].is_null());
    ASSERT_EQ(r["coverage"]["faces"].size(), 1u);
    EXPECT_EQ(r["coverage"]["faces"][0]["face"], plate.pockets[0].floor);
    EXPECT_EQ(r["coverage"]["faces"][0]["uncoveredArea"], 0);
    EXPECT_EQ(r["ops"][0]["label"], "rough");
    EXPECT_EQ(r["leftover"]["top"].size(), 120u * 80u);
    EXPECT_EQ(r["leftover"]["bottom"].size(), 120u * 80u);
    EXPECT_DOUBLE_EQ(r["leftover"]["top"][40 * 120 + 60].get<double>(), -0.1);
}
