// The domain tree read back from its JSON: every field toJson writes comes back equal, on
// generated panels, on the NIST parts and on a tree made by hand; bad text is refused with an
// input error that names the field at fault.
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/DomainTreeJson.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/PanelGenerator.h>

#include "ErrorOf.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

using namespace aeronc;
using namespace aeronc::recognition;
using aeronc::test::inputErrorOf;
using nlohmann::json;

namespace {

// Doubles compare exactly: the JSON carries the shortest text that reads back as the same double.
void expectSameVec(const Vec3& a, const Vec3& b, const std::string& where) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a[k], b[k]) << where << "[" << k << "]";
}

void expectSamePolyline(const Polyline& a, const Polyline& b, const std::string& where) {
    ASSERT_EQ(a.size(), b.size()) << where;
    for (std::size_t i = 0; i < a.size(); ++i) expectSameVec(a[i], b[i], where + "[" + std::to_string(i) + "]");
}

void expectSameTree(const DomainTree& a, const DomainTree& b) {
    EXPECT_EQ(a.faceCount, b.faceCount);
    ASSERT_EQ(a.setups.size(), b.setups.size());
    for (std::size_t s = 0; s < a.setups.size(); ++s) {
        const SetupDirection &x = a.setups[s], &y = b.setups[s];
        EXPECT_EQ(x.id, y.id);
        expectSameVec(x.direction, y.direction, "setup direction");
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.elements, y.elements);
        EXPECT_TRUE(x.blankTop == y.blankTop || (std::isnan(x.blankTop) && std::isnan(y.blankTop))) << "setup " << s;
    }
    ASSERT_EQ(a.elements.size(), b.elements.size());
    for (std::size_t i = 0; i < a.elements.size(); ++i) {
        const DomainElement &x = a.elements[i], &y = b.elements[i];
        const std::string w = "element " + std::to_string(i);
        EXPECT_EQ(x.id, y.id) << w;
        EXPECT_EQ(x.setup, y.setup) << w;
        EXPECT_EQ(x.parent, y.parent) << w;
        EXPECT_EQ(x.children, y.children) << w;
        EXPECT_EQ(x.type, y.type) << w;
        EXPECT_EQ(x.level, y.level) << w;
        EXPECT_EQ(x.top, y.top) << w;
        EXPECT_EQ(x.depth, y.depth) << w;
        EXPECT_EQ(x.floorArea, y.floorArea) << w;
        EXPECT_EQ(x.area, y.area) << w;
        EXPECT_EQ(x.minWidth, y.minWidth) << w;
        EXPECT_EQ(x.minCornerRadius, y.minCornerRadius) << w;
        EXPECT_EQ(x.floorFilletRadius, y.floorFilletRadius) << w;
        EXPECT_EQ(x.contourFaces, y.contourFaces) << w;
        EXPECT_EQ(x.islandFaces, y.islandFaces) << w;
        EXPECT_EQ(x.floorFaces, y.floorFaces) << w;
        EXPECT_EQ(x.topFaces, y.topFaces) << w;
        EXPECT_EQ(x.filletFaces, y.filletFaces) << w;
        EXPECT_EQ(x.chamferFaces, y.chamferFaces) << w;
        ASSERT_EQ(x.openEdges.size(), y.openEdges.size()) << w;
        for (std::size_t k = 0; k < x.openEdges.size(); ++k) {
            expectSameVec(x.openEdges[k].first, y.openEdges[k].first, w + " open edge start");
            expectSameVec(x.openEdges[k].second, y.openEdges[k].second, w + " open edge end");
        }
        expectSamePolyline(x.contour, y.contour, w + " contour");
        ASSERT_EQ(x.islands.size(), y.islands.size()) << w;
        for (std::size_t k = 0; k < x.islands.size(); ++k) expectSamePolyline(x.islands[k], y.islands[k], w + " island");
        EXPECT_EQ(x.islandTops, y.islandTops) << w;
        ASSERT_EQ(x.attached.size(), y.attached.size()) << w;
        for (std::size_t k = 0; k < x.attached.size(); ++k) {
            const AttachedFeature &p = x.attached[k], &q = y.attached[k];
            EXPECT_EQ(p.kind, q.kind) << w;
            EXPECT_EQ(p.faces, q.faces) << w;
            EXPECT_EQ(p.radius, q.radius) << w;
            EXPECT_EQ(p.size, q.size) << w;
            EXPECT_EQ(p.element, q.element) << w;
        }
        ASSERT_EQ(x.hole.has_value(), y.hole.has_value()) << w;
        if (x.hole) {
            const HoleInfo &p = *x.hole, &q = *y.hole;
            EXPECT_EQ(p.diameter, q.diameter) << w;
            EXPECT_EQ(p.depth, q.depth) << w;
            EXPECT_EQ(p.through, q.through) << w;
            expectSameVec(p.axis, q.axis, w + " hole axis");
            expectSameVec(p.location, q.location, w + " hole location");
            EXPECT_EQ(p.counterboreDiameter, q.counterboreDiameter) << w;
            EXPECT_EQ(p.counterboreDepth, q.counterboreDepth) << w;
            EXPECT_EQ(p.countersinkDiameter, q.countersinkDiameter) << w;
            EXPECT_EQ(p.countersinkAngle, q.countersinkAngle) << w;
            EXPECT_EQ(p.overhung, q.overhung) << w;
        }
    }
    EXPECT_EQ(a.faceRoles, b.faceRoles);
    EXPECT_EQ(a.faceElement, b.faceElement);
    EXPECT_EQ(a.unclaimedFaces, b.unclaimedFaces);
    EXPECT_EQ(a.warnings, b.warnings);
}

// Read back, written again: the same text, and the same tree field by field.
void expectRoundTrip(const DomainTree& t) {
    const std::string text = toJson(t);
    const DomainTree back = fromJson(text);
    EXPECT_EQ(toJson(back), text);
    EXPECT_EQ(toJson(back, -1), toJson(t, -1));
    expectSameTree(t, back);
}

// What a tree holds, so that a round trip is known to have carried each kind of field.
struct Seen {
    int holes = 0, counterbores = 0, countersinks = 0, attached = 0, openEdges = 0, islands = 0, sharpOrNone = 0,
        noCorner = 0, children = 0, setups = 0, warnings = 0;
    void add(const DomainTree& t) {
        setups += static_cast<int>(t.setups.size());
        warnings += static_cast<int>(t.warnings.size());
        for (const DomainElement& e : t.elements) {
            holes += e.hole.has_value();
            counterbores += e.hole && e.hole->counterboreDiameter > 0;
            countersinks += e.hole && e.hole->countersinkDiameter > 0;
            attached += static_cast<int>(e.attached.size());
            openEdges += static_cast<int>(e.openEdges.size());
            islands += static_cast<int>(e.islands.size());
            noCorner += e.minCornerRadius < 0;
            children += static_cast<int>(e.children.size());
        }
    }
};

}  // namespace

TEST(DomainTreeJson, GeneratedPanelsRoundTrip) {
    testparts::PanelSpec full;  // every feature the generator makes, both sides
    testparts::PanelSpec filleted = full;
    filleted.floorFillet = 2;
    Seen seen;
    for (const testparts::PanelSpec& spec : {full, filleted}) {
        const DomainTree t = recognise(validatedSolid(testparts::makePanel(spec).shape, "panel"));
        seen.add(t);
        expectRoundTrip(t);
    }
    // The panels exercise the optional and nested parts of the schema.
    EXPECT_GT(seen.holes, 0);
    EXPECT_GT(seen.counterbores, 0);
    EXPECT_GT(seen.countersinks, 0);
    EXPECT_GT(seen.attached, 0);
    EXPECT_GT(seen.openEdges, 0);
    EXPECT_GT(seen.islands, 0);
    EXPECT_GT(seen.children, 0);
    EXPECT_GE(seen.setups, 4);
}

namespace {
std::vector<std::string> nistParts() {
    std::vector<std::string> out;
    const std::filesystem::path dir = std::filesystem::path(AERONC_SHARED_DATA) / "nist";
    if (!std::filesystem::exists(dir)) return out;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".stp") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}
}  // namespace

class NistTreeJson : public ::testing::TestWithParam<std::string> {};

TEST_P(NistTreeJson, RoundTrips) {
    const DomainTree t = recognise(loadPart(GetParam()));
    ASSERT_GT(t.elements.size(), 0u);
    for (const SetupDirection& s : t.setups) EXPECT_TRUE(std::isfinite(s.blankTop)) << s.name;
    expectRoundTrip(t);
}

INSTANTIATE_TEST_SUITE_P(Nist, NistTreeJson, ::testing::ValuesIn(nistParts()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string n = std::filesystem::path(info.param).stem().string();
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(NistTreeJson);

namespace {

// A small tree by hand: a +Z setup holding a pocket (no concave corner) with a counterbored hole
// under it, a -Z setup holding an open pocket; values that are not short decimals.
DomainTree handTree() {
    DomainTree t;
    t.faceCount = 6;
    t.setups = {{0, {0, 0, 1}, "+Z", {0}}, {1, {0, 0, -1}, "-Z", {2}}};
    DomainElement pocket;
    pocket.id = 0, pocket.setup = 0, pocket.children = {1};
    pocket.level = 0.1 + 0.2, pocket.top = 20, pocket.depth = 20 - (0.1 + 0.2);
    pocket.floorArea = 1.0 / 3, pocket.area = 1e-300, pocket.minWidth = 12.5;
    pocket.minCornerRadius = -1, pocket.floorFilletRadius = 2;
    pocket.contourFaces = {1, 2}, pocket.islandFaces = {{3}, {}}, pocket.floorFaces = {4};
    pocket.topFaces = {5}, pocket.filletFaces = {6}, pocket.chamferFaces = {};
    pocket.contour = {{0, 0, 0.3}, {10, 0, 0.3}, {10, 10, 0.3}};
    pocket.islands = {{{4, 4, 0.3}, {6, 4, 0.3}, {5, 6, 0.3}}, {}};
    pocket.islandTops = {0.25, 0.3};
    pocket.attached = {{"floor_fillet", {6}, 2, 0, -1}, {"joggle", {}, 0, -0.5, 1}};
    DomainElement hole;
    hole.id = 1, hole.setup = 0, hole.parent = 0, hole.type = ElementType::Hole, hole.minCornerRadius = 0;
    hole.hole = HoleInfo{6.6, 7, true, {0, 0, 1}, {1, 2, 3}, 11, 4.25, 0, 0, true};
    DomainElement open;
    open.id = 2, open.setup = 1, open.type = ElementType::OpenPocket, open.minCornerRadius = 3;
    open.openEdges = {{{0, 0, 0}, {1, 0, 0}}, {{1, 0, 0}, {1, 1, -0.0}}};
    t.elements = {pocket, hole, open};
    t.faceRoles = {FaceRole::Wall, FaceRole::Wall, FaceRole::IslandWall, FaceRole::Floor, FaceRole::Top,
                   FaceRole::FloorFillet};
    t.faceElement = {0, 0, 0, 0, -1, 0};
    t.unclaimedFaces = {5};
    t.warnings = {"a warning", "another, with \"quotes\""};
    return t;
}

// The hand tree's JSON, changed by `edit`, read back: the input error's message.
std::string errorAfter(const std::function<void(json&)>& edit) {
    json j = json::parse(toJson(handTree()));
    edit(j);
    const std::string text = j.dump();
    return inputErrorOf([&] { fromJson(text); });
}

}  // namespace

TEST(DomainTreeJson, HandTreeRoundTripsEveryField) {
    const DomainTree t = handTree();
    expectRoundTrip(t);
    const DomainTree back = fromJson(toJson(t));
    // The pocket without a concave corner is written as null and read back as -1.
    EXPECT_TRUE(json::parse(toJson(t))["elements"][0]["minCornerRadius"].is_null());
    EXPECT_EQ(back.elements[0].minCornerRadius, -1);
    EXPECT_EQ(back.elements[0].level, 0.1 + 0.2);
    EXPECT_EQ(back.elements[0].area, 1e-300);
    EXPECT_EQ(back.elements[1].hole->counterboreDepth, 4.25);
    EXPECT_TRUE(back.elements[1].hole->overhung);
    EXPECT_FALSE(back.elements[0].hole.has_value());
    EXPECT_EQ(back.warnings[1], "another, with \"quotes\"");
}

TEST(DomainTreeJson, ExtraKeysAreIgnored) {
    json j = json::parse(toJson(handTree()));
    j["faceNames"] = {"a", "b", "c", "d", "e", "f"};  // what `aeronc recognise --face-names` adds
    expectSameTree(handTree(), fromJson(j.dump()));
}

TEST(DomainTreeJson, NotJsonOrNotAnObject) {
    EXPECT_NE(inputErrorOf([] { fromJson(""); }).find("not valid JSON"), std::string::npos);
    EXPECT_NE(inputErrorOf([] { fromJson("{\"faceCount\": 3,"); }).find("not valid JSON"), std::string::npos);
    EXPECT_NE(inputErrorOf([] { fromJson("[1, 2]"); }).find("top level: expected an object, got array"),
              std::string::npos);
}

TEST(DomainTreeJson, MissingOrMistypedFieldsAreNamed) {
    const auto has = [](const std::string& message, const std::string& part) {
        EXPECT_NE(message.find(part), std::string::npos) << "'" << message << "' lacks '" << part << "'";
    };
    has(errorAfter([](json& j) { j.erase("faceCount"); }), "domain tree: top level: missing field 'faceCount'");
    has(errorAfter([](json& j) { j["faceCount"] = -2; }), "faceCount: a face count cannot be negative");
    has(errorAfter([](json& j) { j["faceCount"] = 6.5; }), "faceCount: expected a whole number, got number");
    has(errorAfter([](json& j) { j["faceCount"] = 1e12; }), "faceCount: expected a whole number");
    has(errorAfter([](json& j) { j["faceCount"] = 5000000000LL; }), "faceCount: whole number 5000000000 out of range");
    has(errorAfter([](json& j) { j["setups"] = json::object(); }), "setups: expected an array, got object");
    has(errorAfter([](json& j) { j["setups"][1]["direction"] = {0, 1}; }),
        "setups[1].direction: expected [x, y, z], got [0,1]");
    has(errorAfter([](json& j) { j["setups"][0]["name"] = 3; }), "setups[0].name: expected a string, got number");
    has(errorAfter([](json& j) { j["elements"][0].erase("depth"); }), "elements[0]: missing field 'depth'");
    has(errorAfter([](json& j) { j["elements"][2]["level"] = "deep"; }),
        "elements[2].level: expected a number, got string");
    has(errorAfter([](json& j) { j["elements"][2]["level"] = nullptr; }),
        "elements[2].level: expected a number, got null");
    has(errorAfter([](json& j) { j["elements"][0]["type"] = "slot"; }), "elements[0].type: unknown element type 'slot'");
    has(errorAfter([](json& j) { j["elements"][0]["contour"][1] = {1, 2}; }),
        "elements[0].contour[1]: expected [x, y, z], got [1,2]");
    has(errorAfter([](json& j) { j["elements"][0]["islands"][0][2][1] = true; }),
        "elements[0].islands[0][2][1]: expected a number, got boolean");
    has(errorAfter([](json& j) { j["elements"][0]["islandTops"] = {0.25}; }),
        "elements[0].islandTops: expected one height per island (2), got 1");
    has(errorAfter([](json& j) { j["elements"][2]["openEdges"][0] = {{0, 0, 0}}; }),
        "elements[2].openEdges[0]: expected [start, end], got 1 points");
    has(errorAfter([](json& j) { j["elements"][0]["islandFaces"][0][0] = "3"; }),
        "elements[0].islandFaces[0][0]: expected a whole number, got string");
    has(errorAfter([](json& j) { j["elements"][0]["attached"][1].erase("kind"); }),
        "elements[0].attached[1]: missing field 'kind'");
    has(errorAfter([](json& j) { j["elements"][1]["hole"].erase("diameter"); }),
        "elements[1].hole: missing field 'diameter'");
    has(errorAfter([](json& j) { j["elements"][1]["hole"]["through"] = 1; }),
        "elements[1].hole.through: expected true or false, got number");
    has(errorAfter([](json& j) { j["elements"][1]["hole"] = "none"; }), "elements[1].hole: expected an object");
    has(errorAfter([](json& j) { j["faceRoles"][3] = "ceiling"; }), "faceRoles[3]: unknown face role 'ceiling'");
    has(errorAfter([](json& j) { j["warnings"][0] = json::object(); }), "warnings[0]: expected a string, got object");
}

TEST(DomainTreeJson, LinksAndNumbersOutOfRangeAreNamed) {
    const auto has = [](const std::string& message, const std::string& part) {
        EXPECT_NE(message.find(part), std::string::npos) << "'" << message << "' lacks '" << part << "'";
    };
    has(errorAfter([](json& j) { j["setups"][1]["id"] = 7; }), "setups[1].id: 7, but a setup's id is its position 1");
    has(errorAfter([](json& j) { j["elements"][2]["id"] = 0; }),
        "elements[2].id: 0, but an element's id is its position 2");
    has(errorAfter([](json& j) { j["elements"][2]["setup"] = 2; }),
        "elements[2].setup: setup 2 does not exist (0..1)");
    has(errorAfter([](json& j) { j["setups"][1]["elements"] = {5}; }),
        "setups[1].elements[0]: element 5 does not exist (0..2)");
    has(errorAfter([](json& j) { j["setups"][0]["elements"] = {0, 1}; }),
        "setups[0].elements[1]: element 1 is not a root element of setup 0 (its parent is 0");
    has(errorAfter([](json& j) { j["setups"][1]["elements"] = json::array(); }),
        "elements[2].parent: -1 (a root), but setups[1].elements does not list 2");
    has(errorAfter([](json& j) { j["setups"][1]["elements"] = {2, 2}; }),
        "setups[1].elements[1]: element 2 is listed twice");
    has(errorAfter([](json& j) { j["elements"][1]["parent"] = 9; }),
        "elements[1].parent: element 9 cannot be the parent");
    has(errorAfter([](json& j) { j["elements"][1]["parent"] = 1; }),
        "elements[1].parent: element 1 cannot be the parent");
    has(errorAfter([](json& j) { j["elements"][0]["children"] = json::array(); }),
        "elements[1].parent: 0, but elements[0].children does not list 1");
    has(errorAfter([](json& j) { j["elements"][0]["children"] = {1, 2}; }),
        "elements[0].children[1]: element 2 has parent -1, not 0");
    has(errorAfter([](json& j) { j["elements"][0]["children"] = {1, 1}; }),
        "elements[0].children[1]: element 1 is listed twice");
    has(errorAfter([](json& j) { j["elements"][1]["setup"] = 1; }),
        "elements[0].children[0]: element 1 is in setup 1, its parent in setup 0");
    has(errorAfter([](json& j) {  // elements 0 and 1 each the other's parent
            j["setups"][0]["elements"] = json::array();
            j["elements"][0]["parent"] = 1;
            j["elements"][1]["children"] = {0};
        }),
        "elements[0].parent: the chain of parents from element 0 goes round in a circle");
    has(errorAfter([](json& j) { j["elements"][0]["contourFaces"][1] = 7; }),
        "elements[0].contourFaces[1]: face 7 is not a face of the part (1..6)");
    has(errorAfter([](json& j) { j["elements"][0]["islandFaces"][0][0] = 0; }),
        "elements[0].islandFaces[0][0]: face 0 is not a face of the part");
    has(errorAfter([](json& j) { j["elements"][0]["attached"][0]["faces"] = {-3}; }),
        "elements[0].attached[0].faces[0]: face -3 is not a face of the part");
    has(errorAfter([](json& j) { j["elements"][0]["attached"][1]["element"] = 3; }),
        "elements[0].attached[1].element: element 3 does not exist (-1 or 0..2)");
    has(errorAfter([](json& j) { j["faceRoles"].erase(5); }), "faceRoles: 5 roles for 6 faces");
    has(errorAfter([](json& j) { j["faceElement"].push_back(0); }), "faceElement: 7 entries for 6 faces");
    has(errorAfter([](json& j) { j["faceElement"][4] = 3; }),
        "faceElement[4]: element 3 does not exist (-1 or 0..2)");
    has(errorAfter([](json& j) { j["unclaimedFaces"] = {9}; }),
        "unclaimedFaces[0]: face 9 is not a face of the part (1..6)");
}

// A tree written before unclaimedFaces existed reads back with none.
TEST(DomainTreeJson, OlderTreeWithoutUnclaimedFacesReads) {
    json j = json::parse(toJson(handTree()));
    j.erase("unclaimedFaces");
    const DomainTree back = fromJson(j.dump());
    EXPECT_TRUE(back.unclaimedFaces.empty());
    EXPECT_EQ(back.faceElement, handTree().faceElement);
}

TEST(DomainTreeJson, OlderTreeWithoutIslandTopsReads) {
    json j = json::parse(toJson(handTree()));
    ASSERT_TRUE(j["elements"][0].contains("islandTops"));
    j["elements"][0].erase("islandTops");
    const DomainTree back = fromJson(j.dump());
    EXPECT_TRUE(back.elements[0].islandTops.empty());
    EXPECT_EQ(back.elements[0].islands.size(), 2u);
}
