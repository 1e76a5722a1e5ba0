// Chamfer mills for countersinks and pocket chamfers (docs/edges.md): the choice of a mill by
// included angle, cover and tip (toolselect/EdgeTools.h), the shipped crib's edge tools, and the
// edge units the chain makes on a generated panel whose countersunk bolt holes are known by
// construction (hole 6.6 mm, countersink 12 mm at 90 degrees) and on a pocket whose mouth is
// chamfered all round or on two sides.
#include "Fixtures.h"

#include <aeronc/brep/PartIO.h>
#include <aeronc/kb/ProcessTemplates.h>
#include <aeronc/recognition/DomainTreeJson.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/PanelGenerator.h>
#include <aeronc/toolselect/EdgeTools.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

using namespace aeronc;
using namespace aeronc::chain;
using toolselect::EdgeNeed;
using toolselect::EdgeTool;

namespace {

EdgeTool mill(const std::string& id, double d, double tip, double angle) {
    EdgeTool t;
    t.id = id, t.kind = "chamfer", t.material = "carbide";
    t.diameter = d, t.tipDiameter = tip, t.includedAngle = angle, t.flutes = 4, t.reach = 25;
    return t;
}

}  // namespace

TEST(EdgeTools, ChamferMillMatchesTheAngleCoversTheWidthAndPassesInsideTheHole) {
    const std::vector<EdgeTool> crib = {mill("90-D6", 6, 0.5, 90), mill("90-D10", 10, 1, 90),
                                        mill("90-D16", 16, 2, 90), mill("60-D10", 10, 1, 60)};
    // A 45 degree chamfer 2 mm wide: the D6 covers 0.25 + 0.2 + 2 = 2.45 <= 3, the smallest that does.
    EdgeNeed chamfer{90, 2, 2, 0};
    auto c = toolselect::chamferTool(crib, chamfer);
    ASSERT_TRUE(c.tool) << c.why;
    EXPECT_EQ(c.tool->id, "90-D6");
    // 2.7 mm wide (a 12 mm countersink on a 6.6 mm hole): the D6's cone is too short, the D10 fits.
    c = toolselect::chamferTool(crib, {90, 2.7, 2.7, 6.6});
    ASSERT_TRUE(c.tool) << c.why;
    EXPECT_EQ(c.tool->id, "90-D10");
    // The same countersink on a 1.2 mm hole: no tip of these passes inside it.
    c = toolselect::chamferTool({mill("90-D10", 10, 1, 90)}, {90, 2.7, 2.7, 1.2});
    EXPECT_FALSE(c.tool);
    EXPECT_NE(c.why.find("tip below 0.8 mm"), std::string::npos) << c.why;
    // A 60 degree countersink takes the 60 degree mill, a 120 degree one none.
    c = toolselect::chamferTool(crib, {60, 2, 2 * std::sqrt(3.0), 6.6});
    ASSERT_TRUE(c.tool) << c.why;
    EXPECT_EQ(c.tool->id, "60-D10");
    c = toolselect::chamferTool(crib, {120, 2, 1.15, 6.6});
    EXPECT_FALSE(c.tool);
    EXPECT_NE(c.why.find("120 degree chamfer mill of diameter >= 4.4 mm"), std::string::npos) << c.why;
    // The pass: the axis 0.2 mm beyond the tip's rim from the lower line, the tip 0.2 / tan 45 below it.
    const auto p = toolselect::chamferPass(crib[1]);
    EXPECT_NEAR(p.offset, 0.7, 1e-12);
    EXPECT_NEAR(p.tipBelow, 0.2, 1e-12);
}

TEST(EdgeTools, ShippedCribHoldsTheChamferMills) {
    const test::KbDir dir("edge_crib");
    const auto kb = dir.open();
    const auto tools = kb.edgeTools();
    std::vector<std::string> chamfers;
    for (const auto& t : tools)
        if (t.kind == "chamfer") chamfers.push_back(t.id);
    EXPECT_EQ(chamfers, (std::vector<std::string>{"CM-45-D6", "CM-90-D6", "CM-45-D10", "CM-90-D10", "CM-90-D16",
                                                  "CM-90-D25", "CM-90-D32"}));
    for (const auto& t : tools)
        if (t.kind == "chamfer") EXPECT_GE(t.reach, t.diameter) << t.id;
    const auto d10 = std::find_if(tools.begin(), tools.end(), [](const EdgeTool& t) { return t.id == "CM-90-D10"; });
    ASSERT_NE(d10, tools.end());
    EXPECT_DOUBLE_EQ(d10->includedAngle, 90);
    EXPECT_DOUBLE_EQ(d10->tipDiameter, 1);
}

// The panel's countersunk bolt holes are drilled, then countersunk with the 90 degree D10 mill:
// its tip 0.2 mm below the countersink's lower line (2.7 mm below the top), its axis 0.7 mm inside
// the 6.6 mm hole's edge, after the drill.
TEST(EdgeTools, CountersunkBoltHolesGetAChamferMillPassAfterTheirDrill) {
    testparts::PanelSpec s;
    s.pocketsX = 2, s.pocketsY = 1, s.pitch = 40;
    s.lowerRibs = s.islands = s.openings = s.lighteningHoles = false;
    s.joggles = s.flange = s.bottomPockets = false;
    const testparts::Panel panel = testparts::makePanel(s);
    int countersunk = 0;
    for (const auto& t : panel.truth) countersunk += t.countersinkDiameter > 0;
    ASSERT_GT(countersunk, 0);
    recognition::RecogniseOptions o;
    o.directions = {{0, 0, 1}};
    const auto tree = recognition::recognise(validatedSolid(panel.shape, "panel"), o);
    const test::KbDir dir("edge_panel");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");

    int cut = 0;
    for (const auto& e : tree.elements) {
        if (!e.hole || !(e.hole->countersinkDiameter > 0)) continue;
        EXPECT_NEAR(e.hole->countersinkDiameter, 12, 1e-3);
        EXPECT_NEAR(e.hole->countersinkAngle, 90, 1e-3);
        for (const Unmachined& m : c.unmachined)
            EXPECT_EQ(m.reason.find("countersink"), std::string::npos) << "element " << e.id << ": " << m.reason;
        const MachiningUnit* edge = nullptr;
        const MachiningUnit* drill = nullptr;
        for (const MachiningUnit& u : c.units) {
            if (u.element != e.id) continue;
            if (u.step == StepCode::Edge) edge = &u;
            if (u.step == StepCode::Drill || u.step == StepCode::HoleMill) drill = &u;
        }
        ASSERT_TRUE(edge) << "element " << e.id;
        ASSERT_TRUE(drill) << "element " << e.id;
        ++cut;
        EXPECT_EQ(edge->operation, Operation::Chamfer);
        EXPECT_EQ(edge->tool, "CM-90-D10");
        EXPECT_EQ(edge->cutter.type, "chamfer");
        EXPECT_DOUBLE_EQ(edge->cutter.includedAngle, 90);
        // The countersink rises 2.7 mm from the hole's top (its location) to the panel's top.
        const double lower = e.hole->location[2];
        EXPECT_NEAR(lower + 2.7, s.thickness, 1e-6);
        EXPECT_NEAR(edge->top, s.thickness, 1e-6);
        EXPECT_NEAR(edge->bottom, lower - 0.2, 1e-6);
        EXPECT_NEAR(edge->edgeOffset, 0.7, 1e-12);
        // The drive loop is the hole's edge.
        for (const Point2& p : edge->contour)
            EXPECT_NEAR(std::hypot(p[0] - edge->at[0], p[1] - edge->at[1]), 3.3, 1e-9);
        EXPECT_GT(edge->setting.spindleRpm, 0);
        EXPECT_GT(edge->setting.feedMmMin, 0);
        EXPECT_LT(edge->order, 0 + static_cast<int>(c.order.size()));
        EXPECT_GT(edge->order, drill->order) << "the countersink comes after its hole";
    }
    EXPECT_EQ(cut, countersunk);
    const ChainTool* t = c.tool("CM-90-D10");
    ASSERT_TRUE(t);
    EXPECT_EQ(t->type, "chamfer");
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.rule << " " << r.node << ": " << r.message;
}

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <BRep_Tool.hxx>
#include <gp_Pnt.hxx>

namespace {

// `part` with a chamfer `width` wide on every edge whose two ends pass `on` (and `keep`).
template <class On, class Keep>
TopoDS_Shape chamferEdges(const TopoDS_Shape& part, double width, On on, Keep keep) {
    BRepFilletAPI_MakeChamfer ch(part);
    for (TopExp_Explorer x(part, TopAbs_EDGE); x.More(); x.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(x.Current());
        TopoDS_Vertex a, b;
        TopExp::Vertices(edge, a, b);
        const gp_Pnt p = BRep_Tool::Pnt(a), q = BRep_Tool::Pnt(b);
        if (on(p) && on(q) && keep(p, q)) ch.Add(width, edge);
    }
    ch.Build();
    return ch.Shape();
}

template <class On>
TopoDS_Shape chamferEdges(const TopoDS_Shape& part, double width, On on) {
    return chamferEdges(part, width, on, [](const gp_Pnt&, const gp_Pnt&) { return true; });
}

// A 100 x 60 x 20 block with a 60 x 30 x 10 pocket whose mouth carries a 45 degree x 2 mm
// chamfer all round (four planes: the pocket's corners are sharp), or along its long sides only.
TopoDS_Shape chamferedPocket(bool allRound = true) {
    TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(100, 60, 20)).Shape();
    TopoDS_Shape pocket = BRepPrimAPI_MakeBox(gp_Pnt(20, 15, 10), gp_Pnt(80, 45, 30)).Shape();
    auto onMouth = [](const gp_Pnt& r) {
        return std::abs(r.Z() - 20) < 1e-6 && r.X() > 19 && r.X() < 81 && r.Y() > 14 && r.Y() < 46;
    };
    return chamferEdges(BRepAlgoAPI_Cut(block, pocket).Shape(), 2, onMouth, [allRound](const gp_Pnt& p, const gp_Pnt& q) {
        return allRound || std::abs(p.Y() - q.Y()) < 1e-6;  // the long sides run along x
    });
}

// The same pocket with a 20 x 10 island standing to the top in its middle, the island's top
// edges chamfered 45 degrees x 2 mm all round, the pocket's mouth not at all.
TopoDS_Shape pocketWithChamferedIsland() {
    TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(100, 60, 20)).Shape();
    TopoDS_Shape pocket = BRepPrimAPI_MakeBox(gp_Pnt(20, 15, 10), gp_Pnt(80, 45, 30)).Shape();
    TopoDS_Shape island = BRepPrimAPI_MakeBox(gp_Pnt(40, 25, 10), gp_Pnt(60, 35, 20)).Shape();
    return chamferEdges(BRepAlgoAPI_Fuse(BRepAlgoAPI_Cut(block, pocket).Shape(), island).Shape(), 2, [](const gp_Pnt& r) {
        return std::abs(r.Z() - 20) < 1e-6 && r.X() > 39 && r.X() < 61 && r.Y() > 24 && r.Y() < 36;
    });
}

// A 160 x 120 x 40 block with an 80 x 60 x 30 pocket whose mouth carries a 45 degree x 12.7 mm
// chamfer all round (the width of NIST CTC-03's large chamfers): wider than the cone of the
// crib's 90 degree D16 (16 / 2 - 1 - 0.2 = 6.8 mm) and the D25 (10.8 mm).
TopoDS_Shape wideChamferedPocket() {
    TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(160, 120, 40)).Shape();
    TopoDS_Shape pocket = BRepPrimAPI_MakeBox(gp_Pnt(40, 30, 10), gp_Pnt(120, 90, 50)).Shape();
    return chamferEdges(BRepAlgoAPI_Cut(block, pocket).Shape(), 12.7, [](const gp_Pnt& r) {
        return std::abs(r.Z() - 40) < 1e-6 && r.X() > 39 && r.X() < 121 && r.Y() > 29 && r.Y() < 91;
    });
}

recognition::DomainTree recogniseUp(const TopoDS_Shape& shape, const std::string& name) {
    recognition::RecogniseOptions o;
    o.directions = {{0, 0, 1}};
    return recognition::recognise(validatedSolid(shape, name), o);
}

// The element whose attached features hold a chamfer, and that chamfer (the last found); nulls
// when none does.
std::pair<const recognition::DomainElement*, const recognition::AttachedFeature*> chamferOf(
    const recognition::DomainTree& tree) {
    std::pair<const recognition::DomainElement*, const recognition::AttachedFeature*> found{nullptr, nullptr};
    for (const auto& e : tree.elements)
        for (const auto& a : e.attached)
            if (a.kind == "chamfer") found = {&e, &a};
    return found;
}

// An element's edge unit and its wall-finishing unit (the last of each); nulls when it has none.
std::pair<const MachiningUnit*, const MachiningUnit*> edgeAndWall(const MachiningChain& c, int element) {
    std::pair<const MachiningUnit*, const MachiningUnit*> found{nullptr, nullptr};
    for (const MachiningUnit& u : c.units) {
        if (u.element != element) continue;
        if (u.step == StepCode::Edge) found.first = &u;
        if (u.step == StepCode::FinishWall) found.second = &u;
    }
    return found;
}

}  // namespace

// Recognition measures the chamfer (90 degree mill, 2 mm wide, rising from the walls' top at
// z = 18); the chain cuts it after the walls are finished with the crib's mill that fits
// (CM-90-D6: tip 0.5 mm) along the pocket's outline: the axis 0.25 + 0.2 mm inside the walls,
// the tip 0.2 mm under the chamfer's lower line, and lists nothing of it.
TEST(EdgeTools, PocketMouthChamferIsCutAlongTheOutlineByTheMillThatFits) {
    const auto tree = recogniseUp(chamferedPocket(), "chamfered pocket");
    const auto [pocket, chamfer] = chamferOf(tree);
    ASSERT_TRUE(chamfer);
    EXPECT_EQ(chamfer->faces.size(), 4u);
    EXPECT_NEAR(chamfer->angle, 90, 1e-6);
    EXPECT_NEAR(chamfer->size, 2, 1e-6);
    EXPECT_TRUE(chamfer->alongContour);
    EXPECT_NEAR(chamfer->lower, 18, 1e-6);
    // What the edge step needs survives the tree's JSON.
    const auto back = recognition::fromJson(recognition::toJson(tree));
    bool kept = false;
    for (const auto& e : back.elements)
        for (const auto& a : e.attached)
            if (a.kind == "chamfer")
                kept = std::abs(a.angle - 90) < 1e-9 && std::abs(a.size - 2) < 1e-9 && a.alongContour &&
                       std::abs(a.lower - 18) < 1e-9;
    EXPECT_TRUE(kept);

    const test::KbDir dir("edge_pocket");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    for (const Unmachined& m : c.unmachined)
        EXPECT_EQ(m.reason.find("chamfer"), std::string::npos) << "element " << m.element << ": " << m.reason;
    const auto [edge, wall] = edgeAndWall(c, pocket->id);
    ASSERT_TRUE(edge);
    ASSERT_TRUE(wall);
    EXPECT_EQ(edge->operation, Operation::Chamfer);
    EXPECT_EQ(edge->tool, "CM-90-D6");
    EXPECT_EQ(edge->cutter.type, "chamfer");
    EXPECT_DOUBLE_EQ(edge->cutter.includedAngle, 90);
    EXPECT_NEAR(edge->top, 20, 1e-6);
    EXPECT_NEAR(edge->bottom, 17.8, 1e-6);
    EXPECT_NEAR(edge->edgeOffset, 0.45, 1e-12);
    EXPECT_TRUE(edge->islands.empty());
    EXPECT_TRUE(edge->openEdges.empty());
    // The drive loop is the pocket's outline under the chamfer: the walls at x = 20, 80 and
    // y = 15, 45, counter-clockwise.
    ASSERT_GE(edge->contour.size(), 4u);
    double area = 0;
    for (std::size_t i = 0; i < edge->contour.size(); ++i) {
        const Point2& p = edge->contour[i];
        const Point2& q = edge->contour[(i + 1) % edge->contour.size()];
        area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
        const double off = std::min({std::abs(p[0] - 20), std::abs(p[0] - 80), std::abs(p[1] - 15), std::abs(p[1] - 45)});
        EXPECT_LT(off, 1e-6) << p[0] << " " << p[1];
    }
    EXPECT_NEAR(area, 60 * 30, 1e-6);
    EXPECT_GT(edge->setting.spindleRpm, 0);
    EXPECT_GT(edge->order, wall->order) << "the chamfer comes after the walls under it";
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.rule << " " << r.node << ": " << r.message;
}

// Chamfered along two of its four walls only, a pass along the outline would cut the other two:
// recognition says the chamfer does not run along the whole loop, and the chain lists its faces
// with the crib's mill that would fit them.
TEST(EdgeTools, ChamferAlongPartOfTheOutlineIsListedWithTheMillThatFits) {
    const auto tree = recogniseUp(chamferedPocket(false), "chamfered pocket");
    const auto [pocket, chamfer] = chamferOf(tree);
    ASSERT_TRUE(chamfer);
    EXPECT_EQ(chamfer->faces.size(), 2u);
    EXPECT_NEAR(chamfer->angle, 90, 1e-6);
    EXPECT_FALSE(chamfer->alongContour);

    const test::KbDir dir("edge_pocket_part");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    for (const MachiningUnit& u : c.units) EXPECT_NE(u.step, StepCode::Edge) << "unit " << u.id;
    const Unmachined* listed = nullptr;
    for (const Unmachined& m : c.unmachined)
        if (m.element == pocket->id && m.reason.find("chamfer face") != std::string::npos) listed = &m;
    ASSERT_TRUE(listed);
    EXPECT_EQ(listed->faces.size(), 2u);
    EXPECT_NE(listed->reason.find("45 degrees to the top, up to 2 mm wide"), std::string::npos) << listed->reason;
    EXPECT_NE(listed->reason.find("CM-90-D6"), std::string::npos) << listed->reason;
}

// Chamfered round its island and nowhere else: recognition says so (and the tree's JSON keeps
// it), and the chain cuts it after the walls with one pass round the island, the axis 0.45 mm
// outside it, the outer loop taken open all round so that no pass runs along it.
TEST(EdgeTools, IslandChamferedAllRoundIsCutRoundTheIsland) {
    const auto tree = recogniseUp(pocketWithChamferedIsland(), "chamfered island");
    const auto [pocket, chamfer] = chamferOf(tree);
    ASSERT_TRUE(chamfer);
    EXPECT_EQ(chamfer->faces.size(), 4u);
    EXPECT_NEAR(chamfer->angle, 90, 1e-6);
    EXPECT_FALSE(chamfer->alongContour);
    EXPECT_EQ(chamfer->alongIslands, std::vector<int>{0});
    EXPECT_NEAR(chamfer->lower, 18, 1e-6);
    const auto back = recognition::fromJson(recognition::toJson(tree));
    bool kept = false;
    for (const auto& e : back.elements)
        for (const auto& a : e.attached)
            if (a.kind == "chamfer") kept = a.alongIslands == std::vector<int>{0} && std::abs(a.lower - 18) < 1e-9;
    EXPECT_TRUE(kept);

    const test::KbDir dir("edge_island");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    for (const Unmachined& m : c.unmachined)
        EXPECT_EQ(m.reason.find("chamfer"), std::string::npos) << "element " << m.element << ": " << m.reason;
    const auto [edge, wall] = edgeAndWall(c, pocket->id);
    ASSERT_TRUE(edge);
    ASSERT_TRUE(wall);
    EXPECT_EQ(edge->tool, "CM-90-D6");
    EXPECT_NEAR(edge->top, 20, 1e-6);
    EXPECT_NEAR(edge->bottom, 17.8, 1e-6);
    EXPECT_NEAR(edge->edgeOffset, 0.45, 1e-12);
    ASSERT_EQ(edge->islands.size(), 1u);
    for (const Point2& p : edge->islands[0]) {
        const double off = std::min({std::abs(p[0] - 40), std::abs(p[0] - 60), std::abs(p[1] - 25), std::abs(p[1] - 35)});
        EXPECT_LT(off, 1e-6) << p[0] << " " << p[1];
    }
    ASSERT_GE(edge->contour.size(), 4u);
    EXPECT_EQ(edge->openEdges.size(), edge->contour.size()) << "the outer loop is open all round";
    EXPECT_GT(edge->order, wall->order) << "the chamfer comes after the walls under it";
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.rule << " " << r.node << ": " << r.message;
}

// A 12.7 mm wide 45 degree chamfer round a pocket's mouth: only the 90 degree D32 of schema
// version 11 covers it (2 + 0.2 + 12.7 <= 16); it is cut along the outline after the walls, the
// axis 2.2 mm inside them, the tip 0.2 mm under the chamfer's lower line (z = 27.3), and nothing
// of it is listed. Before, the chain listed it: "needs a 90 degree chamfer mill of diameter >= 25.8 mm".
TEST(EdgeTools, ChamferWiderThanTheD25IsCutByTheD32) {
    const auto tree = recogniseUp(wideChamferedPocket(), "wide chamfered pocket");
    const auto [pocket, chamfer] = chamferOf(tree);
    ASSERT_TRUE(chamfer);
    EXPECT_NEAR(chamfer->angle, 90, 1e-6);
    EXPECT_NEAR(chamfer->size, 12.7, 1e-6);
    EXPECT_TRUE(chamfer->alongContour);
    EXPECT_NEAR(chamfer->lower, 27.3, 1e-6);

    const test::KbDir dir("edge_wide");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    for (const Unmachined& m : c.unmachined)
        EXPECT_EQ(m.reason.find("chamfer"), std::string::npos) << "element " << m.element << ": " << m.reason;
    const auto [edge, wall] = edgeAndWall(c, pocket->id);
    ASSERT_TRUE(edge);
    ASSERT_TRUE(wall);
    EXPECT_EQ(edge->operation, Operation::Chamfer);
    EXPECT_EQ(edge->tool, "CM-90-D32");
    EXPECT_DOUBLE_EQ(edge->cutter.includedAngle, 90);
    EXPECT_NEAR(edge->top, 40, 1e-6);
    EXPECT_NEAR(edge->bottom, 27.1, 1e-6);
    EXPECT_NEAR(edge->edgeOffset, 2.2, 1e-12);
    EXPECT_GT(edge->setting.spindleRpm, 0);
    EXPECT_GT(edge->setting.feedMmMin, 0);
    EXPECT_GT(edge->order, wall->order) << "the chamfer comes after the walls under it";
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.rule << " " << r.node << ": " << r.message;
}
