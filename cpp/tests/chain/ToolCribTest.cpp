// The shipped crib (docs/tool-crib.md) on generated panels whose pockets are known by
// construction: a pocket deeper than any standard end mill's flutes with small corners is
// finished with a necked long-reach end mill, reaching the floor in layers no higher than its
// flutes; a 1 mm deep pocket with 0.5 mm corners (engraving size) with the 1 mm end mill.
#include "Fixtures.h"

#include <aeronc/brep/PartIO.h>
#include <aeronc/chain/ChainJson.h>
#include <aeronc/chain/ConstructionRules.h>
#include <aeronc/kb/LongReach.h>
#include <aeronc/kb/ProcessTemplates.h>
#include <aeronc/kb/ToolPlanning.h>
#include <aeronc/toolselect/PlanJson.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/PanelGenerator.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <gp_Ax2.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

using namespace aeronc;
using namespace aeronc::chain;

namespace {

testparts::PanelSpec pocketsOnly(double thickness, double webZ, double cornerRadius) {
    testparts::PanelSpec s;
    s.pocketsX = 2;
    s.pocketsY = 1;
    s.pitch = 40;
    s.thickness = thickness;
    s.webZ = webZ;
    s.cornerRadius = cornerRadius;
    s.floorFillet = 0;
    s.lowerRibs = s.islands = s.openings = s.lighteningHoles = s.boltHoles = false;
    s.joggles = s.flange = s.bottomPockets = false;
    return s;
}

recognition::DomainTree recogniseUp(const testparts::PanelSpec& s) {
    recognition::RecogniseOptions o;
    o.directions = {{0, 0, 1}};
    return recognition::recognise(validatedSolid(testparts::makePanel(s).shape, "panel"), o);
}

// The closed pockets' finishing-wall units: tool id -> the units.
std::vector<const MachiningUnit*> finishWalls(const MachiningChain& c, int element) {
    std::vector<const MachiningUnit*> out;
    for (const MachiningUnit& u : c.units)
        if (u.element == element && u.step == StepCode::FinishWall) out.push_back(&u);
    return out;
}

}  // namespace

// 28 mm deep, R3 corners, flat floor: the reach of every standard end mill of radius <= 3 mm
// is its flutes (13 mm for the D6); the necked D6 x 30 reaches 30 mm with 9 mm flutes.
TEST(ToolCrib, DeepPocketWithR3CornersIsFinishedByTheLongReachEndMill) {
    const auto tree = recogniseUp(pocketsOnly(34, 6, 3));
    const test::KbDir dir("crib_deep");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    int pockets = 0;
    for (const auto& e : tree.elements) {
        if (e.type != recognition::ElementType::ClosedPocket) continue;
        ++pockets;
        EXPECT_NEAR(e.top - e.level, 28, 1e-6);
        for (const Unmachined& m : c.unmachined) EXPECT_NE(m.element, e.id) << m.reason;
        const auto walls = finishWalls(c, e.id);
        ASSERT_FALSE(walls.empty()) << "element " << e.id;
        for (const MachiningUnit* u : walls) {
            EXPECT_EQ(u->tool, "EM-F6x30") << "element " << e.id;
            EXPECT_NEAR(u->bottom, e.level, 1e-6);       // down to the floor
            // The handbook's finishing a_p (1 mm) halved for a reach of 5 diameters.
            EXPECT_NEAR(u->stepDown, 0.5, 1e-9);
        }
        // The floor and the roughing reach 28 mm too.
        std::set<StepCode> steps;
        for (const MachiningUnit& u : c.units)
            if (u.element == e.id) {
                steps.insert(u.step);
                const ChainTool* t = c.tool(u.tool);
                ASSERT_TRUE(t) << u.tool;
                EXPECT_GE(t->usableLength() + 1e-9, e.top - u.bottom) << u.tool;
            }
        EXPECT_TRUE(steps.count(StepCode::Rough));
        EXPECT_TRUE(steps.count(StepCode::Web));
    }
    EXPECT_EQ(pockets, 2);
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.node << ": " << r.message;
}

// 94 mm deep, 76 mm wide, R12 corners: deeper than every end mill of the crib before schema
// version 10 reaches (60 mm, the D12 x 60), so no roughing tool was found and the pocket was left.
// The long-reach end mills D16-D32 of version 10 rough, floor and finish it, each unit within its
// tool's reach, in layers no higher than the flutes and at the long-reach a_p.
TEST(ToolCrib, PocketDeeperThanEveryStandardReachIsMachinedWithTheLongReachEndMills) {
    testparts::PanelSpec s = pocketsOnly(100, 6, 12);
    s.pitch = 80;
    const auto tree = recogniseUp(s);
    const test::KbDir dir("crib_long");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    const kb::LongReach reduction = kb::LongReach::of(kb);
    int pockets = 0;
    for (const auto& e : tree.elements) {
        if (e.type != recognition::ElementType::ClosedPocket) continue;
        ++pockets;
        EXPECT_NEAR(e.top - e.level, 94, 1e-6);
        for (const Unmachined& m : c.unmachined) EXPECT_NE(m.element, e.id) << m.reason;
        std::set<StepCode> steps;
        for (const MachiningUnit& u : c.units) {
            if (u.element != e.id) continue;
            steps.insert(u.step);
            const ChainTool* t = c.tool(u.tool);
            ASSERT_TRUE(t) << u.tool;
            EXPECT_GE(t->usableLength() + 1e-9, e.top - u.bottom) << u.tool;
            if (e.top - u.bottom <= 60) continue;
            // Below 60 mm only the long-reach end mills reach: D16 and more, 80 mm and more.
            EXPECT_GE(t->diameter, 16 - 1e-9) << u.tool;
            EXPECT_GE(t->usableLength(), 80 - 1e-9) << u.tool;
            EXPECT_LE(u.stepDown, t->fluteLength + 1e-9) << u.tool;
            if (u.step == StepCode::Rough) {
                const auto hb = kb.cuttingCondition("7050-T7451", t->material, "roughing", t->diameter);
                EXPECT_LE(u.stepDown, reduction.apFactor * hb.ap + 1e-9) << u.tool;
            }
        }
        EXPECT_TRUE(steps.count(StepCode::Rough)) << "element " << e.id;
        EXPECT_TRUE(steps.count(StepCode::Web)) << "element " << e.id;
        const auto walls = finishWalls(c, e.id);
        ASSERT_FALSE(walls.empty()) << "element " << e.id;
        for (const MachiningUnit* u : walls) EXPECT_NEAR(u->bottom, e.level, 1e-6);
    }
    EXPECT_EQ(pockets, 2);
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.node << ": " << r.message;
}

// Cutting data whose a_p is higher than the flutes (here the finishing rows raised to 30 mm, 15
// after the long-reach reduction): the layers stay at the flute length, the neck cuts nothing.
TEST(ToolCrib, LayersAreNoHigherThanTheFlutes) {
    const auto tree = recogniseUp(pocketsOnly(34, 6, 3));
    const test::KbDir dir("crib_layers");
    auto kb = dir.open();
    const kb::Table cc = kb.table("cutting_condition");
    std::vector<kb::CellEdit> edits;
    for (std::size_t i = 0; i < cc.rows.size(); ++i)
        if (cc.rows[i][1] == "7050-T7451" && cc.rows[i][3] == "finishing" && !cc.rows[i][4])
            edits.push_back({cc.rowIds[i], "ap_mm", "30"});
    ASSERT_EQ(edits.size(), 2u);  // carbide and HSS
    kb.editTable("cutting_condition", edits, {}, {});
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    int walls = 0;
    for (const MachiningUnit& u : c.units) {
        if (u.step != StepCode::FinishWall) continue;
        ++walls;
        EXPECT_EQ(u.tool, "EM-F6x30");
        EXPECT_NEAR(u.stepDown, 9.0, 1e-9);
    }
    EXPECT_EQ(walls, 2);
}

// 1 mm deep, R0.5 corners: engraving size, below every standard end mill (the smallest is 2 mm).
TEST(ToolCrib, OneMillimetreDeepPocketIsFinishedWithTheOneMillimetreEndMill) {
    const auto tree = recogniseUp(pocketsOnly(9, 8, 0.5));
    const test::KbDir dir("crib_engrave");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    int pockets = 0;
    for (const auto& e : tree.elements) {
        if (e.type != recognition::ElementType::ClosedPocket) continue;
        ++pockets;
        for (const Unmachined& m : c.unmachined) EXPECT_NE(m.element, e.id) << m.reason;
        const auto walls = finishWalls(c, e.id);
        ASSERT_FALSE(walls.empty()) << "element " << e.id;
        for (const MachiningUnit* u : walls) {
            const ChainTool* t = c.tool(u->tool);
            ASSERT_TRUE(t);
            EXPECT_DOUBLE_EQ(t->diameter, 1.0) << u->tool;
            EXPECT_NEAR(u->bottom, e.level, 1e-6);
            // The small tools' own cutting data: a thin layer and a slow feed.
            EXPECT_LE(u->stepDown, 0.4 + 1e-9);
            EXPECT_LT(u->setting.feedMmMin, 1000.0);
        }
    }
    EXPECT_EQ(pockets, 2);
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.node << ": " << r.message;
}

namespace {

// Two closed pockets as grooves `width` wide and `depth` deep in a 9 mm plate, planned with the
// shipped crib: each is machined (roughed, unless `roughed` is false, and wall-finished) by units
// that fit the groove with their allowance; unitCheck adds what the test asks of every unit.
void expectGroovesCut(double width, double depth, double cornerRadius, const char* kbName,
                      const std::function<void(const MachiningUnit&)>& unitCheck, bool roughed = true) {
    testparts::PanelSpec s = pocketsOnly(9, 9 - depth, cornerRadius);
    s.ribThickness = 1.5;
    s.pitch = s.ribThickness + width;
    const auto tree = recogniseUp(s);
    const test::KbDir dir(kbName);
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    int pockets = 0;
    for (const auto& e : tree.elements) {
        if (e.type != recognition::ElementType::ClosedPocket) continue;
        ++pockets;
        EXPECT_NEAR(e.minWidth, width, 2e-2);  // measured on the faceted outline
        for (const Unmachined& m : c.unmachined) EXPECT_NE(m.element, e.id) << m.reason;
        std::set<StepCode> steps;
        for (const MachiningUnit& u : c.units) {
            if (u.element != e.id) continue;
            steps.insert(u.step);
            unitCheck(u);
            EXPECT_LE(u.cutter.diameter + 2 * u.radialAllowance, e.minWidth + 1e-6) << toString(u.step) << " " << u.tool;
        }
        EXPECT_EQ(steps.count(StepCode::Rough), roughed ? 1u : 0u);
        EXPECT_TRUE(steps.count(StepCode::FinishWall));
    }
    EXPECT_EQ(pockets, 2);
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.node << ": " << r.message;
}

}  // namespace

// Grooves 2 mm wide and 1 mm deep (engraving): the roughing step's 1 mm allowance leaves no room
// for any cutter (0.5 + 2 x 1 > 2); capped at a quarter of the tool's diameter, the 1 mm end
// mill roughs them with 0.25 mm and every step fits the groove.
TEST(ToolCrib, NarrowGroovesAreRoughedWithAnAllowanceTheToolCanLeave) {
    expectGroovesCut(2.0, 1.0, 0.5, "crib_grooves", [](const MachiningUnit& u) {
        EXPECT_LE(u.radialAllowance, 0.25 * u.cutter.diameter + 1e-9) << toString(u.step);
    });
}

// Lettering: grooves 0.36 mm wide and 0.6 mm deep (milled_003's are 0.517 mm; at 0.5 mm the
// roughing's floor allowance would leave it nothing to cut, PocketsShallowerThan... below). The
// D0.5 end mill fits in none; the D0.2 micro end mill of schema version 9 roughs and finishes
// them with an allowance it can leave.
TEST(ToolCrib, LetteringNarrowerThanHalfAMillimetreIsCutWithTheMicroEndMill) {
    expectGroovesCut(0.36, 0.6, 0.12, "crib_lettering", [](const MachiningUnit& u) {
        EXPECT_LE(u.cutter.diameter, 0.3 + 1e-9) << toString(u.step) << " " << u.tool;
    });
}

// Lettering strokes 0.28 mm wide (milled_003's are 0.21 to 0.40 mm): the D0.2 micro end mill
// with its roughing allowance (0.2 + 2 x 0.05 = 0.3 mm) fits in none and no smaller end mill
// exists, so no roughing unit is planned (the toolpath would refuse it and take the finishing
// units down with it); the finishing tool, which fits, cuts each stroke alone.
TEST(ToolCrib, LetteringNarrowerThanTheRoughingAllowanceIsCutByTheFinishingToolAlone) {
    expectGroovesCut(0.28, 0.5, 0.1, "crib_strokes", [](const MachiningUnit& u) {
        EXPECT_LE(u.cutter.diameter, 0.2 + 1e-9) << toString(u.step) << " " << u.tool;
    }, false);
}

// Strokes 0.22 mm wide (milled_003's narrowest are 0.213 to 0.23 mm): the D0.2 micro end mill
// fits, but not with the floor step's allowance (0.2 + 2 x 0.025 = 0.25 mm). The finishing steps
// leave, scaled alike, a quarter of the room the width leaves, so every step fits the stroke and
// the walls are still finished last with none.
TEST(ToolCrib, StrokesBarelyWiderThanTheSmallestEndMillAreFinishedWithTheRoomTheyLeave) {
    expectGroovesCut(0.22, 0.5, 0.08, "crib_tight_strokes", [](const MachiningUnit& u) {
        EXPECT_LE(u.cutter.diameter, 0.2 + 1e-9) << toString(u.step) << " " << u.tool;
        if (u.step == StepCode::FinishWall) EXPECT_EQ(u.radialAllowance, 0.0);
    }, false);
}

// Pockets 0.4 mm deep (a shallow recess, a logo): the roughing step's 0.5 mm floor allowance
// leaves nothing for a roughing unit to cut (its toolpath would refuse it, and the gate would
// take the finishing units with it). No roughing unit is planned; the floor unit cuts each from
// its top, and every unit has depth to cut below its floor allowance.
TEST(ToolCrib, PocketsShallowerThanTheRoughingFloorAllowanceAreCutByTheFloorUnit) {
    expectGroovesCut(3.0, 0.4, 1.0, "crib_shallow", [](const MachiningUnit& u) {
        EXPECT_LT(u.bottom + u.axialAllowance, u.top) << toString(u.step) << " " << u.tool;
    }, false);
}

namespace {

// The crib's end mills as the selector sees them (id, type, diameter, corner radius, reach).
struct CribMill {
    std::string id, type;
    double diameter, cornerRadius, usable;
};
std::vector<CribMill> cribMills(const kb::KnowledgeBase& kb) {
    const kb::Table t = kb.table("tool");
    auto col = [&](const char* name) {
        for (std::size_t i = 0; i < t.columns.size(); ++i)
            if (t.columns[i].name == name) return i;
        ADD_FAILURE() << "no column " << name;
        return std::size_t{0};
    };
    const std::size_t id = col("id"), type = col("type"), d = col("diameter"), cr = col("corner_radius"),
                      fl = col("flute_length"), reach = col("reach"), neck = col("neck_diameter");
    std::vector<CribMill> out;
    for (const auto& r : t.rows) {
        if (*r[type] != "flat" && *r[type] != "bull") continue;
        const double f = std::stod(*r[fl]), re = std::stod(*r[reach]);
        out.push_back({*r[id], *r[type], std::stod(*r[d]), std::stod(*r[cr]), r[neck] || f >= re ? re : f});
    }
    return out;
}

const Remainder* remainderOf(const MachiningChain& c, int element, const std::string& kind) {
    for (const Remainder& r : c.remainders)
        if (r.element == element && r.kind == kind) return &r;
    return nullptr;
}

}  // namespace

// Sharp (R0) vertical corners, 12 mm deep: no end mill fits them. The pocket is roughed with a
// larger tool and finished with the smallest radius the crib has that reaches 12 mm; the corners
// it leaves are listed with their area (four 90-degree corners: 4 (1 - pi/4) r^2), not the whole
// pocket.
TEST(ToolCrib, SharpCorneredPocketIsFinishedWithTheSmallestReachingToolAndTheCornersListed) {
    const auto tree = recogniseUp(pocketsOnly(20, 8, 0));
    const test::KbDir dir("crib_sharp");
    const auto kb = dir.open();
    double smallest = 1e9;  // the smallest radius of an end mill reaching 12 mm
    for (const CribMill& m : cribMills(kb))
        if (m.usable >= 12 - 1e-9) smallest = std::min(smallest, 0.5 * m.diameter);
    ASSERT_LT(smallest, 3.0);
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    int pockets = 0;
    for (const auto& e : tree.elements) {
        if (e.type != recognition::ElementType::ClosedPocket) continue;
        ++pockets;
        EXPECT_NEAR(e.minCornerRadius, 0, 1e-6);
        for (const Unmachined& m : c.unmachined) EXPECT_NE(m.element, e.id) << m.reason;
        const auto walls = finishWalls(c, e.id);
        ASSERT_FALSE(walls.empty()) << "element " << e.id;
        for (const MachiningUnit* u : walls) {
            EXPECT_NEAR(0.5 * u->cutter.diameter, smallest, 1e-9) << u->tool;
            EXPECT_NEAR(u->bottom, e.level, 1e-6);
        }
        // Roughed with a larger tool; the walls' passes, not a rest unit, take what it left in the
        // corners (a rest unit's links would cross the roughing's wider allowance: Fusing.cpp).
        bool rest = false, wider = false;
        for (const MachiningUnit& u : c.units)
            if (u.element == e.id) {
                rest |= u.operation == Operation::Rest;
                wider |= u.step == StepCode::Rough && 0.5 * u.cutter.diameter > smallest + 1e-9;
            }
        EXPECT_TRUE(wider) << "element " << e.id;
        EXPECT_FALSE(rest) << "element " << e.id;
        const Remainder* r = remainderOf(c, e.id, "corners");
        ASSERT_TRUE(r) << "element " << e.id;
        EXPECT_EQ(r->tool, walls.back()->tool);
        EXPECT_NEAR(r->toolRadius, smallest, 1e-9);
        EXPECT_NEAR(r->depth, 12, 1e-6);
        const double corners = 4 * (1 - M_PI / 4) * smallest * smallest;
        EXPECT_NEAR(r->area, corners, 0.1 * corners);
        EXPECT_NE(r->needs.find("sharp"), std::string::npos) << r->needs;
    }
    EXPECT_EQ(pockets, 2);
    for (const RuleCheck& rc : c.checks) EXPECT_TRUE(rc.ok) << rc.node << ": " << rc.message;
    // The chain checked again, unedited, is unchanged; the JSON keeps the remainders.
    EXPECT_EQ(toJson(checkChain(c)), toJson(c));
    EXPECT_EQ(fromJson(toJson(c)).remainders.size(), c.remainders.size());
}

// A crib whose end mills reaching 24 mm are all bull-nosed (the flat ones taken out), a floor
// fillet of 0.3 mm: the floor is finished with the smallest corner radius that reaches (0.5 mm),
// and the band it leaves along the walls (0.2 mm high) is listed with its area.
TEST(ToolCrib, FloorFilletSmallerThanEveryReachingCornerIsFinishedAndTheFootListed) {
    testparts::PanelSpec s = pocketsOnly(30, 6, 6);
    s.floorFillet = 0.3;
    const auto tree = recogniseUp(s);
    const test::KbDir dir("crib_fillet");
    auto kb = dir.open();
    {
        const kb::Table t = kb.table("tool");
        std::vector<long long> drop;
        const auto mills = cribMills(kb);
        for (std::size_t i = 0, k = 0; i < t.rows.size(); ++i) {
            if (*t.rows[i][1] != "flat" && *t.rows[i][1] != "bull") continue;
            const CribMill& m = mills[k++];
            if (m.type == "flat" && m.usable >= 24 - 1e-9) drop.push_back(t.rowIds[i]);
        }
        ASSERT_FALSE(drop.empty());
        kb.editTable("tool", {}, {}, drop);
    }
    double smallestCorner = 1e9;
    for (const CribMill& m : cribMills(kb))
        if (m.usable >= 24 - 1e-9) smallestCorner = std::min(smallestCorner, m.cornerRadius);
    ASSERT_NEAR(smallestCorner, 0.5, 1e-9);
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    int pockets = 0;
    for (const auto& e : tree.elements) {
        if (e.type != recognition::ElementType::ClosedPocket) continue;
        ++pockets;
        EXPECT_NEAR(e.floorFilletRadius, 0.3, 1e-6);
        for (const Unmachined& m : c.unmachined) EXPECT_NE(m.element, e.id) << m.reason;
        const MachiningUnit* floor = nullptr;
        for (const MachiningUnit& u : c.units)
            if (u.element == e.id && u.step == StepCode::Web) floor = &u;
        ASSERT_TRUE(floor) << "element " << e.id;
        EXPECT_NEAR(floor->cutter.cornerRadius, smallestCorner, 1e-9) << floor->tool;
        EXPECT_NEAR(floor->bottom, e.level, 1e-6);
        EXPECT_FALSE(finishWalls(c, e.id).empty());
        const Remainder* r = remainderOf(c, e.id, "floor_fillet");
        ASSERT_TRUE(r) << "element " << e.id;
        EXPECT_NEAR(r->depth, 0.2, 1e-9);
        // The band along the pocket's walls: 4 x (36 - 12) straight + 2 pi x 6 round, 0.2 mm wide.
        const double walls = 4 * (36 - 12) + 2 * M_PI * 6;
        EXPECT_NEAR(r->area, 0.2 * walls, 0.02 * 0.2 * walls);
        EXPECT_NE(r->needs.find("0.3 mm"), std::string::npos) << r->needs;
    }
    EXPECT_EQ(pockets, 2);
    for (const RuleCheck& rc : c.checks) EXPECT_TRUE(rc.ok) << rc.node << ": " << rc.message;
    EXPECT_EQ(toJson(checkChain(c)), toJson(c));
}

// 200 mm deep pockets, deeper than any end mill of the crib reaches (the longest, 160 mm): each
// is roughed from its top down 160 mm with a tool reaching that far, nothing goes lower, and the
// pocket stays listed with the rest in the remainders (40 mm of it, under the roughing).
TEST(ToolCrib, PocketDeeperThanEveryReachIsRoughedAsFarAsTheLongestReachesAndListed) {
    const auto tree = recogniseUp(pocketsOnly(210, 10, 6));
    const test::KbDir dir("crib_too_deep");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    int pockets = 0;
    for (const auto& e : tree.elements) {
        if (e.type != recognition::ElementType::ClosedPocket) continue;
        ++pockets;
        ASSERT_NEAR(e.top - e.level, 200, 1e-6);
        std::vector<const MachiningUnit*> units;
        for (const MachiningUnit& u : c.units)
            if (u.element == e.id) units.push_back(&u);
        ASSERT_EQ(units.size(), 1u) << "element " << e.id;
        const MachiningUnit& rough = *units[0];
        EXPECT_EQ(rough.step, StepCode::Rough);
        EXPECT_EQ(rough.operation, Operation::Pocket);
        EXPECT_TRUE(rough.shortOfFloor);
        EXPECT_NEAR(rough.bottom, e.top - 160, 1e-6);
        const ChainTool* t = c.tool(rough.tool);
        ASSERT_TRUE(t) << rough.tool;
        EXPECT_GE(t->usableLength() + 1e-9, 160) << rough.tool;
        EXPECT_NE(rough.note.find("roughed down 160 mm of its 200 mm"), std::string::npos) << rough.note;
        // Listed first for the element: what was roughed and what it still needs.
        const Unmachined* listed = nullptr;
        for (const Unmachined& m : c.unmachined)
            if (m.element == e.id) {
                listed = &m;
                break;
            }
        ASSERT_TRUE(listed) << "element " << e.id;
        EXPECT_EQ(listed->step, StepCode::Rough);
        EXPECT_NE(listed->reason.find("roughed down 160 mm of its 200 mm with " + rough.tool), std::string::npos)
            << listed->reason;
        EXPECT_NE(listed->reason.find("it needs an end mill reaching 200"), std::string::npos) << listed->reason;
        const Remainder* rest = nullptr;
        for (const Remainder& r : c.remainders)
            if (r.element == e.id && r.kind == "depth") rest = &r;
        ASSERT_TRUE(rest) << "element " << e.id;
        EXPECT_NEAR(rest->depth, 40, 1e-6);
        EXPECT_NEAR(rest->area, e.area, 1e-6);
    }
    EXPECT_EQ(pockets, 2);
    // The chain's JSON keeps the remainders; the tool plan's JSON (as Select tools stores it)
    // keeps the roughing for the reached depth, and the chain from it is the same.
    EXPECT_EQ(toJson(fromJson(toJson(c))), toJson(c));
    const std::string text = toolselect::toJson(kb::planTools(tree, kb, "7050-T7451", "AC-5AX"), "7050-T7451");
    EXPECT_NE(text.find("partialRoughingTool"), std::string::npos);
    const toolselect::ToolPlan stored = kb::storedToolPlan(kb, text, "7050-T7451");
    EXPECT_EQ(toolselect::toJson(stored, "7050-T7451"), text);
    EXPECT_EQ(toJson(kb::planChain(tree, kb, stored, "7050-T7451", "AC-5AX")),
              toJson(kb::planChain(tree, kb, "7050-T7451", "AC-5AX")));
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.node << ": " << r.message;
}

// A 5.5 mm flat-bottomed hole 35 mm deep in a 40 x 40 x 50 block (NIST FTC-10's element 44):
// no drill leaves its flat bottom, and helical interpolation needs a flat end mill below 4.4 mm
// (0.8 x the hole) reaching 35 mm. Before schema version 11 the longest D4 reached 32 mm and the
// hole was listed; the D4 x 40 mills it down to its bottom, and nothing of it is listed.
TEST(ToolCrib, DeepSmallFlatBottomedHoleIsMilledByTheD4x40) {
    const TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(40, 40, 50)).Shape();
    const TopoDS_Shape hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 20, 15), gp_Dir(0, 0, 1)), 2.75, 40).Shape();
    recognition::RecogniseOptions o;
    o.directions = {{0, 0, 1}};
    const auto tree =
        recognition::recognise(validatedSolid(BRepAlgoAPI_Cut(block, hole).Shape(), "deep hole"), o);
    const recognition::DomainElement* h = nullptr;
    for (const auto& e : tree.elements)
        if (e.hole) h = &e;
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->hole->diameter, 5.5, 1e-6);
    EXPECT_NEAR(h->hole->depth, 35, 1e-6);
    EXPECT_FALSE(h->hole->through);

    const test::KbDir dir("crib_deep_hole");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    for (const Unmachined& m : c.unmachined) EXPECT_NE(m.element, h->id) << m.reason;
    const MachiningUnit* milled = nullptr;
    for (const MachiningUnit& u : c.units)
        if (u.element == h->id && u.step == StepCode::HoleMill) milled = &u;
    ASSERT_TRUE(milled);
    EXPECT_EQ(milled->tool, "EM-F4x40");
    EXPECT_NEAR(milled->bottom, 15, 1e-6);
    const ChainTool* t = c.tool(milled->tool);
    ASSERT_TRUE(t);
    EXPECT_GE(t->usableLength() + 1e-9, 35);
    EXPECT_GT(milled->setting.spindleRpm, 0);
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.node << ": " << r.message;
}
