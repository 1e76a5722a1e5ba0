// Recognition of generated integral panels against the truth the generator knows.
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/PanelGenerator.h>

#include <gtest/gtest.h>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>
#include <set>

#include <cstdlib>

#include <cmath>
#include <map>
#include <string>

using namespace aeronc;
using namespace aeronc::recognition;
using namespace aeronc::testparts;

namespace {

bool inside(const Polyline& loop, double x, double y) {
    bool in = false;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const double xi = loop[i][0], yi = loop[i][1], xj = loop[j][0], yj = loop[j][1];
        if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) in = !in;
    }
    return in;
}

// The recognised element a truth element stands for: same setup and level, region holding its point.
int match(const DomainTree& t, const TruthElement& want) {
    const double sign = want.setup == 0 ? 1 : -1;
    int found = -1;
    for (const DomainElement& e : t.elements) {
        if (std::fabs(t.setups[static_cast<std::size_t>(e.setup)].direction[2] - sign) > 1e-9) continue;
        if (std::fabs(e.level - want.level) > 1e-3) continue;
        if (!inside(e.contour, want.point[0], want.point[1])) continue;
        bool inIsland = false;
        for (const Polyline& isl : e.islands) inIsland |= inside(isl, want.point[0], want.point[1]);
        if (inIsland) continue;
        EXPECT_EQ(found, -1) << "two elements hold truth element " << want.id << " (" << want.note << ")";
        found = e.id;
    }
    return found;
}

void expectMatchesTruth(const PanelSpec& spec, std::vector<Vec3> directions = {{0, 0, 1}, {0, 0, -1}}) {
    const Panel panel = makePanel(spec);
    RecogniseOptions o;
    o.directions = directions;
    const DomainTree t = recognise(validatedSolid(panel.shape, "panel"), o);
    ASSERT_EQ(t.setups.size(), directions.size());
    std::map<int, int> recognisedOf;  // truth id -> element id
    for (const TruthElement& want : panel.truth) {
        const int id = match(t, want);
        ASSERT_GE(id, 0) << "not found: truth element " << want.id << " " << want.type << " (" << want.note
                         << ") at level " << want.level;
        recognisedOf[want.id] = id;
    }
    for (const TruthElement& want : panel.truth) {
        const DomainElement& e = t.elements[static_cast<std::size_t>(recognisedOf[want.id])];
        SCOPED_TRACE("truth element " + std::to_string(want.id) + " (" + want.note + ")");
        EXPECT_EQ(toString(e.type), want.type);
        EXPECT_EQ(e.parent, want.parent < 0 ? -1 : recognisedOf[want.parent]);
        EXPECT_EQ(static_cast<int>(e.islandFaces.size()), want.islands);
        if (want.type == "hole") {
            ASSERT_TRUE(e.hole.has_value());
            EXPECT_NEAR(e.hole->diameter, want.diameter, 1e-6);
            EXPECT_EQ(e.hole->through, want.through);
            EXPECT_NEAR(e.hole->counterboreDiameter, want.counterboreDiameter, 1e-6);
            EXPECT_NEAR(e.hole->countersinkDiameter, want.countersinkDiameter, 1e-3);
        }
        if (want.note == "joggle") {
            bool attached = false;
            for (const AttachedFeature& a : t.elements[static_cast<std::size_t>(e.parent)].attached)
                attached |= a.kind == "joggle" && a.element == e.id;
            EXPECT_TRUE(attached) << "joggle not attached to its pocket";
        }
    }
    // Nothing found that is not in the truth.
    EXPECT_EQ(t.elements.size(), panel.truth.size());
    // Pocket walls and floors carry their roles; every face has one role.
    std::map<std::string, int> roles;
    for (FaceRole r : t.faceRoles) roles[toString(r)]++;
    EXPECT_EQ(roles["unclaimed"], 0);
    // Every face inside the blank belongs to an element.
    EXPECT_TRUE(t.unclaimedFaces.empty()) << (t.warnings.empty() ? "" : t.warnings.back());
    EXPECT_GT(roles["floor"], 0);
    EXPECT_GT(roles["wall"], 0);
    EXPECT_GT(roles["hole_wall"], 0);
}

}  // namespace

TEST(PanelRecognition, DefaultPanelMatchesTruth) { expectMatchesTruth(PanelSpec{}); }

TEST(PanelRecognition, LargerPanelWithFloorFilletsMatchesTruth) {
    PanelSpec s;
    s.pocketsX = 6;
    s.pocketsY = 4;
    s.floorFillet = 3;
    expectMatchesTruth(s);
}

TEST(PanelRecognition, FloorFilletRadiusAndCornerRadius) {
    PanelSpec s;
    s.pocketsX = 2, s.pocketsY = 1;
    s.floorFillet = 2.5;
    s.cornerRadius = 7;
    s.lowerRibs = s.islands = s.openings = s.lighteningHoles = s.boltHoles = s.joggles = s.flange = false;
    s.bottomPockets = false;
    const Panel panel = makePanel(s);
    RecogniseOptions o;
    o.directions = {{0, 0, 1}};
    const DomainTree t = recognise(validatedSolid(panel.shape, "panel"), o);
    ASSERT_EQ(t.elements.size(), 2u);
    for (const DomainElement& e : t.elements) {
        EXPECT_NEAR(e.floorFilletRadius, 2.5, 1e-6);
        EXPECT_NEAR(e.minCornerRadius, 7, 1e-6);
        EXPECT_NEAR(e.depth, s.thickness - s.webZ, 1e-6);
        EXPECT_FALSE(e.filletFaces.empty());
        // The drive contour runs on the walls, not on the fillet: its width is the pocket's.
        EXPECT_NEAR(e.minWidth, s.pitch - s.ribThickness, 0.05);
    }
}

// The generator's bosses stop 2 mm under the panel top: every element that has them as islands
// (their pocket, and the lowered rib's region beside it) knows that height, with and without a
// fillet round their foot; islands standing to the top keep the element's top.
TEST(PanelRecognition, IslandTopsAreTheBossHeights) {
    for (double fillet : {0.0, 2.0}) {
        PanelSpec s;
        s.floorFillet = fillet;
        const Panel panel = makePanel(s);
        const DomainTree t = recognise(validatedSolid(panel.shape, "panel"), RecogniseOptions{});
        int lower = 0;
        for (const DomainElement& e : t.elements) {
            SCOPED_TRACE("element " + std::to_string(e.id) + ", fillet " + std::to_string(fillet));
            ASSERT_EQ(e.islandTops.size(), e.islands.size());
            for (double h : e.islandTops) {
                EXPECT_LE(h, e.top + 1e-9);
                if (h < e.top - 1e-6) {
                    EXPECT_NEAR(h, s.thickness - 2, 1e-6);
                    ++lower;
                }
            }
        }
        int truthIslands = 0;
        for (const TruthElement& te : panel.truth) truthIslands += te.islands;
        EXPECT_EQ(lower, truthIslands);
        EXPECT_GT(lower, 0);
    }
}

// The fast section of faces along the axis must agree with OCCT's general section,
// also on a part moved away from the origin (faces with locations).
TEST(PanelRecognition, FastSectionAgreesWithGeneralSection) {
    PanelSpec s;
    s.floorFillet = 2;
    const Panel panel = makePanel(s);
    gp_Trsf move;
    move.SetTranslation(gp_Vec(125, -40, 7.5));
    const TopoDS_Shape part = validatedSolid(panel.shape.Moved(TopLoc_Location(move)), "panel");
    RecogniseOptions o;
    o.directions = {{0, 0, 1}, {0, 0, -1}};
    const DomainTree fast = recognise(part, o);
    setenv("AERONC_GENERAL_SECTION", "1", 1);
    const DomainTree general = recognise(part, o);
    unsetenv("AERONC_GENERAL_SECTION");
    ASSERT_EQ(fast.elements.size(), panel.truth.size());
    ASSERT_EQ(fast.elements.size(), general.elements.size());
    for (std::size_t k = 0; k < fast.elements.size(); ++k) {
        EXPECT_EQ(fast.elements[k].type, general.elements[k].type);
        EXPECT_NEAR(fast.elements[k].level, general.elements[k].level, 1e-9);
        EXPECT_NEAR(fast.elements[k].area, general.elements[k].area, 0.05);
        EXPECT_EQ(fast.elements[k].contourFaces.size(), general.elements[k].contourFaces.size());
    }
    EXPECT_EQ(fast.faceRoles, general.faceRoles);
}

// Any direction the user gives: the panel turned in space, recognised along its own turned
// axes, gives the same elements as the upright panel along ±Z.
TEST(PanelRecognition, GivenTiltedDirections) {
    const Panel panel = makePanel(PanelSpec{});
    gp_Trsf turn;
    turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, -2, 0.5)), 0.6);
    const gp_Dir up = gp_Dir(0, 0, 1).Transformed(turn);
    RecogniseOptions upright, tilted;
    upright.directions = {{0, 0, 1}, {0, 0, -1}};
    tilted.directions = {{up.X(), up.Y(), up.Z()}, {-up.X(), -up.Y(), -up.Z()}};
    const DomainTree a = recognise(validatedSolid(panel.shape, "panel"), upright);
    const DomainTree b = recognise(validatedSolid(panel.shape.Moved(TopLoc_Location(turn)), "turned"), tilted);
    ASSERT_EQ(a.elements.size(), panel.truth.size());
    ASSERT_EQ(b.elements.size(), a.elements.size());
    std::multiset<std::string> ta, tb;
    for (const DomainElement& e : a.elements) ta.insert(std::string(toString(e.type)) + "@" + std::to_string(std::lround(e.depth * 1000)));
    for (const DomainElement& e : b.elements) tb.insert(std::string(toString(e.type)) + "@" + std::to_string(std::lround(e.depth * 1000)));
    EXPECT_EQ(ta, tb);
    EXPECT_EQ(a.faceRoles, b.faceRoles);
}

// Lightening holes in pocket floors over the range of real panels: floors 1 to 5 mm thick,
// corner radii up to half the pocket width, hole diameters up to the pocket width minus the
// corner radius. Each pocket and its hole are found, with the hole under the pocket.
TEST(PanelRecognition, FloorHolesOverThicknessRadiusAndDiameter) {
    PanelSpec s;
    s.pocketsX = 1, s.pocketsY = 2;  // cell (0, 0) a plain pocket, cell (0, 1) a lightening hole
    s.lowerRibs = s.islands = s.openings = s.boltHoles = s.joggles = s.flange = s.bottomPockets = false;
    s.thickness = 30;
    const double pw = s.pitch - s.ribThickness;
    for (double floor : {1.0, 2.0, 3.0, 5.0})
        for (double radius : {3.0, 0.25 * pw, 0.5 * pw - 0.25})
            for (double diameter : {10.0, 0.5 * (pw - radius), pw - radius}) {
                s.webZ = floor;
                s.cornerRadius = radius;
                s.lighteningDiameter = diameter;
                SCOPED_TRACE("floor " + std::to_string(floor) + " mm, corner radius " + std::to_string(radius) +
                             ", hole diameter " + std::to_string(diameter));
                expectMatchesTruth(s, {{0, 0, 1}});
            }
}
