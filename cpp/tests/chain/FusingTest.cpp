// The chain of whole parts, planned from the shipped knowledge base: generated double-sided
// panels whose pockets and holes are known by construction, the sample panel, and NIST parts.
// Every element is machined or listed with a reason, the order keeps the precedences (checked
// here independently of the sequencer), optimising never adds travel, and the rules hold.
#include "Fixtures.h"

#include <aeronc/chain/ChainJson.h>
#include <aeronc/chain/ConstructionRules.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/kb/ProcessTemplates.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/PanelGenerator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

using namespace aeronc;
using namespace aeronc::chain;

namespace {

const test::KbDir& kbDir() {
    static const test::KbDir dir("fusing");
    return dir;
}

double area(const Loop& l) {
    double a = 0;
    for (std::size_t i = 0; i < l.size(); ++i)
        a += l[i][0] * l[(i + 1) % l.size()][1] - l[(i + 1) % l.size()][0] * l[i][1];
    return 0.5 * a;
}

bool outer(const MachiningUnit& u) { return u.featureType == "open_pocket" || u.featureType == "flange"; }

// The properties every chain must have, checked without the sequencer's code. Returns the
// number of parent -> child pairs whose order rule 3 decides.
int expectSoundChain(const recognition::DomainTree& tree, const MachiningChain& c, const std::string& part) {
    SCOPED_TRACE(part);
    // Every element is machined by some unit or listed with the reason.
    std::map<int, int> units;
    for (const MachiningUnit& u : c.units) ++units[u.element];
    std::set<int> listed;
    for (const Unmachined& m : c.unmachined) {
        EXPECT_FALSE(m.reason.empty()) << "element " << m.element;
        listed.insert(m.element);
    }
    for (const auto& e : tree.elements)
        EXPECT_TRUE(units[e.id] > 0 || listed.count(e.id)) << "element " << e.id << " neither machined nor listed";

    // Island tops below the pocket's top are faced by a floor unit of an element naming them,
    // or the chain says they are not, with the faces, once per face.
    std::set<int> namedTops;
    for (const Unmachined& m : c.unmachined)
        for (int f : m.faces) EXPECT_TRUE(namedTops.insert(f).second) << "face " << f << " listed twice";
    std::map<int, const recognition::DomainElement*> elementById;
    for (const auto& e : tree.elements) elementById[e.id] = &e;
    auto faces = [&](const MachiningUnit& u, const std::vector<int>& top) {
        if (!u.faceIslandTops || u.step != StepCode::Web) return false;
        const auto* owner = elementById[u.element];
        bool named = false;
        for (const auto& a : owner->attached) named |= a.kind == "island_top" && a.faces == top;
        // It faces some island strictly between its element's floor and top.
        bool lower = false;
        for (double h : u.islandTops) lower |= !std::isnan(h) && h > owner->level && h < owner->top;
        EXPECT_TRUE(lower) << "unit " << u.id << " faces island tops but has none between floor and top";
        return named && lower;
    };
    for (const auto& e : tree.elements)
        for (const auto& a : e.attached) {
            if (a.kind != "island_top" || e.type == recognition::ElementType::Hole) continue;
            bool listedTop = false;  // by this element or another one naming the same faces
            for (const Unmachined& m : c.unmachined) listedTop |= m.faces == a.faces;
            bool faced = false;
            for (const MachiningUnit& u : c.units) faced |= faces(u, a.faces);
            EXPECT_TRUE(listedTop != faced) << "island top of element " << e.id << (faced ? " faced and listed" : " neither faced nor listed");
        }

    // Through an opening the finishing passes go the breakthrough and the corner radius below its
    // floor level, as far as the tool reaches: a rounded corner passes the wall's lower edge whole.
    for (const MachiningUnit& u : c.units) {
        const recognition::DomainElement* e = nullptr;
        for (const auto& x : tree.elements)
            if (x.id == u.element) e = &x;
        if (!e || e->type != recognition::ElementType::Opening || u.operation != Operation::Profile) continue;
        const ChainTool* t = c.tool(u.tool);
        if (!t) return ADD_FAILURE() << "unit " << u.id << ": no tool " << u.tool, 0;
        const double want = std::max(e->level - ChainOptions{}.breakthrough - u.cutter.cornerRadius,
                                     std::min(e->level - ChainOptions{}.breakthrough, u.top - t->usableLength()));
        EXPECT_NEAR(u.bottom, want, 1e-9) << "unit " << u.id;
    }

    // The order lists every unit once.
    std::vector<int> sorted = c.order;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted.size(), c.units.size());
    for (std::size_t i = 0; i < sorted.size(); ++i)
        if (sorted[i] != static_cast<int>(i)) return ADD_FAILURE() << "order is no permutation", 0;
    std::map<int, int> pos;
    for (std::size_t i = 0; i < c.order.size(); ++i) pos[c.order[i]] = static_cast<int>(i);

    // Precedences: step order; rule 1 (larger tool first within a step); rule 2 (outer before
    // inner with one tool); rule 3 (a parent's unit before its child's with one tool and class).
    std::map<int, const recognition::DomainElement*> byId;
    for (const auto& e : tree.elements) byId[e.id] = &e;
    std::map<std::pair<int, StepCode>, const MachiningUnit*> byElementStep;
    for (const MachiningUnit& u : c.units) byElementStep[{u.element, u.step}] = &u;
    const ProcessTemplate& t = c.processTemplate;
    // The unit of the nearest ancestor with a unit in the same step, lying higher.
    auto parentUnit = [&](const MachiningUnit& b) -> const MachiningUnit* {
        for (int p = byId[b.element]->parent; p >= 0; p = byId[p]->parent) {
            const auto it = byElementStep.find({p, b.step});
            if (it == byElementStep.end()) continue;
            return it->second->bottom > b.bottom + 1e-9 ? it->second : nullptr;
        }
        return nullptr;
    };
    // Rule 3 holds over rule 1: a child cut with a larger tool than an ancestor waits for it.
    auto underNarrowerParent = [&](const MachiningUnit& a) {
        for (const MachiningUnit* p = parentUnit(a); p; p = parentUnit(*p))
            if (p->cutter.diameter < a.cutter.diameter - 1e-9) return true;
        return false;
    };
    int parentPairs = 0;
    for (const MachiningUnit& a : c.units)
        for (const MachiningUnit& b : c.units) {
            if (a.setup != b.setup || a.id == b.id) continue;
            if (t.rank(a.step) < t.rank(b.step)) EXPECT_LT(pos[a.id], pos[b.id]) << a.id << " before " << b.id;
            if (a.step != b.step) continue;
            if (a.cutter.diameter > b.cutter.diameter + 1e-9 && !underNarrowerParent(a))
                EXPECT_LT(pos[a.id], pos[b.id]) << "rule 1";
            if (a.tool == b.tool && outer(a) && !outer(b)) EXPECT_LT(pos[a.id], pos[b.id]) << "rule 2";
        }
    // Rule 3 whatever the tools: a child's unit starts below material its parent's unit removes.
    for (const MachiningUnit& b : c.units)
        if (const MachiningUnit* a = parentUnit(b)) {
            EXPECT_LT(pos[a->id], pos[b.id]) << "rule 3: unit " << a->id << " (element " << a->element
                                             << ") before unit " << b.id << " (element " << b.element << ")";
            ++parentPairs;
        }

    EXPECT_LE(c.travel.optimised, c.travel.rulesOnly + 1e-9);
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.rule << ": " << r.node << ": " << r.message;

    // Geometry in the setup frame: contours counter-clockwise, islands clockwise, heights in order.
    for (const MachiningUnit& u : c.units) {
        EXPECT_GT(u.top, u.bottom) << "unit " << u.id;
        if (u.operation == Operation::Drill || u.operation == Operation::Helix) {
            EXPECT_EQ(u.holes.size(), 1u);
            continue;
        }
        EXPECT_GT(area(u.contour), 0) << "unit " << u.id;
        for (const Loop& isl : u.islands) EXPECT_LT(area(isl), 0) << "unit " << u.id;
        EXPECT_GT(u.stepDown, 0) << "unit " << u.id;
        EXPECT_GT(u.stepOver, 0) << "unit " << u.id;
        EXPECT_GT(u.setting.spindleRpm, 0) << "unit " << u.id;
    }
    // The JSON carries it all.
    EXPECT_EQ(toJson(fromJson(toJson(c))), toJson(c));
    return parentPairs;
}

recognition::DomainTree recogniseBothSides(const testparts::Panel& panel) {
    recognition::RecogniseOptions o;
    o.directions = {{0, 0, 1}, {0, 0, -1}};
    return recognition::recognise(validatedSolid(panel.shape, "panel"), o);
}

}  // namespace

// A wall leaning away from the axis is finished square to the floor, leaving depth x tan(lean)
// at its top: a 0.3-degree draft on a 15 mm pocket keeps within 0.1 mm (0.079), a 60-degree
// bevel does not and is listed with its faces (only those leave the coverage check). A chamfer
// without a tool is listed with its faces, not as the whole element, and a face once.
TEST(Fusing, BevelsAFlatEndMillCannotFinishAreListedWithTheirFaces) {
    recognition::DomainTree t = test::smallTree();
    recognition::DomainElement& e = t.elements[0];  // 15 mm deep
    recognition::AttachedFeature draft, bevel;
    draft.kind = bevel.kind = "open_corner";
    draft.faces = {201}, draft.size = 0.3;
    bevel.faces = {202, 203}, bevel.size = 60;
    e.attached = {draft, bevel};
    e.chamferFaces = {204};
    t.elements[1].chamferFaces = {204, 205};  // shared with the pocket inside
    const MachiningChain c = buildChain(t, test::smallPlan(), parseTemplate(test::panelRows()), test::smallOptions());
    std::vector<std::vector<int>> listed;
    for (const Unmachined& u : c.unmachined)
        if (u.element <= 1) {
            EXPECT_FALSE(u.faces.empty()) << u.reason;
            listed.push_back(u.faces);
            if (u.faces == std::vector<int>{202, 203}) {
                EXPECT_NE(u.reason.find("60 degrees"), std::string::npos) << u.reason;
                EXPECT_NE(u.reason.find(" 25.981 mm"), std::string::npos) << u.reason;  // 15 tan 60
            }
        }
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(listed, (std::vector<std::vector<int>>{{202, 203}, {204}, {205}}));
}

// A blind counterbore with a fillet between wall and floor (milled_002's four): its helix unit
// carries the fillet, so the cutter keeps out of it near the floor (HelicalHole); a through
// hole has none.
TEST(Fusing, BlindHoleCarriesItsFloorFilletToTheHelix) {
    recognition::DomainTree t = test::smallTree();
    recognition::DomainElement& e = t.elements[2];
    e.hole->through = false;
    e.hole->diameter = 12;
    e.minWidth = 12;
    e.minCornerRadius = 6;
    e.floorFaces = {301};
    e.floorFilletRadius = 1.5;
    toolselect::ToolPlan plan = test::smallPlan();
    plan.holes[0].diameter = 12;
    plan.holes[0].drill = -1;
    MachiningChain c = buildChain(t, plan, parseTemplate(test::panelRows()), test::smallOptions());
    const MachiningUnit* helix = nullptr;
    for (const MachiningUnit& u : c.units)
        if (u.element == 2 && u.operation == Operation::Helix) helix = &u;
    ASSERT_NE(helix, nullptr);
    ASSERT_EQ(helix->holes.size(), 1u);
    EXPECT_DOUBLE_EQ(helix->holes[0].floorFilletRadius, 1.5);
    EXPECT_EQ(toJson(fromJson(toJson(c))), toJson(c));
    e.hole->through = true;
    e.floorFaces.clear();
    c = buildChain(t, plan, parseTemplate(test::panelRows()), test::smallOptions());
    for (const MachiningUnit& u : c.units)
        for (const HoleTarget& h : u.holes) EXPECT_EQ(h.floorFilletRadius, 0) << "unit " << u.id;
}

// A 60 mm blind hole: no end mill of the plan lies from half the hole to 0.8 of it (30 to 48 mm),
// so the largest below, R20, mills it in rings (toolpath::helicalHole); the rules hold. Before,
// the hole was listed unmachined ("it needs one of 30 to 48 mm").
TEST(Fusing, HoleWiderThanTwiceEveryEndMillIsMilledWithTheLargest) {
    recognition::DomainTree t = test::smallTree();
    recognition::DomainElement& e = t.elements[2];
    e.hole->through = false;
    e.hole->diameter = 60;
    e.minWidth = 60;
    e.minCornerRadius = 30;
    e.floorFaces = {301};
    toolselect::ToolPlan plan = test::smallPlan();
    plan.holes[0].diameter = 60;
    plan.holes[0].drill = -1;
    MachiningChain c = buildChain(t, plan, parseTemplate(test::panelRows()), test::smallOptions());
    const MachiningUnit* helix = nullptr;
    for (const MachiningUnit& u : c.units)
        if (u.element == 2 && u.operation == Operation::Helix) helix = &u;
    ASSERT_NE(helix, nullptr);
    EXPECT_EQ(helix->tool, "R20");
    for (const Unmachined& m : c.unmachined) EXPECT_NE(m.element, 2) << m.reason;
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.rule << ": " << r.node << ": " << r.message;
}

// A hole a wall stands over (recognition's overhung) gets no drill and no helix: the chain
// lists it with the reason.
TEST(Fusing, OverhungHoleIsListedNotDrilled) {
    recognition::DomainTree t = test::smallTree();
    t.elements[2].hole->overhung = true;
    const MachiningChain c = buildChain(t, test::smallPlan(), parseTemplate(test::panelRows()), test::smallOptions());
    for (const MachiningUnit& u : c.units) EXPECT_NE(u.element, 2) << "unit " << u.id;
    bool listed = false;
    for (const Unmachined& u : c.unmachined)
        listed |= u.element == 2 && u.reason.find("material stands within its mouth") != std::string::npos;
    EXPECT_TRUE(listed);
}

TEST(Fusing, GeneratedDoubleSidedPanel) {
    testparts::PanelSpec spec;  // every feature kind, pockets on both faces
    spec.pocketsX = 4;
    spec.pocketsY = 3;
    spec.floorFillet = 2;
    const auto panel = testparts::makePanel(spec);
    const auto tree = recogniseBothSides(panel);
    const auto kb = kbDir().open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    EXPECT_GT(expectSoundChain(tree, c, "generated panel"), 0);  // its ribs and joggles have children

    // Both setups have units, each in its own frame.
    ASSERT_EQ(c.setups.size(), 2u);
    for (const ChainSetup& s : c.setups) EXPECT_FALSE(s.processes.empty()) << s.name;
    EXPECT_DOUBLE_EQ(c.setups[1].w[2], -1);

    std::map<int, const recognition::DomainElement*> byId;
    for (const auto& e : tree.elements) byId[e.id] = &e;
    int drilled = 0, milledHoles = 0, rests = 0;
    for (const MachiningUnit& u : c.units) {
        const auto& e = *byId[u.element];
        if (u.operation == Operation::Drill) {
            // The drill of the hole's own diameter (the generator's are clearance sizes).
            EXPECT_NEAR(u.cutter.diameter, e.hole->diameter, 0.01) << "unit " << u.id;
            EXPECT_EQ(u.cutter.type, "drill");
            ++drilled;
        }
        if (u.operation == Operation::Helix) {
            // Flat-bottomed counterbores: an end mill between half and 0.8 of the hole.
            EXPECT_FALSE(e.hole->through);
            EXPECT_GE(u.cutter.diameter, 0.5 * e.hole->diameter - 1e-9);
            EXPECT_LE(u.cutter.diameter, 0.8 * e.hole->diameter + 1e-9);
            EXPECT_DOUBLE_EQ(u.cutter.cornerRadius, 0);
            ++milledHoles;
        }
        if (u.operation == Operation::Rest) {
            // Only where the roughing tool could not follow the corners.
            ASSERT_TRUE(u.previousCutter.has_value());
            EXPECT_LT(u.cutter.diameter, u.previousCutter->diameter);
            ASSERT_TRUE(u.previousAllowance.has_value());
            EXPECT_GE(*u.previousAllowance, u.radialAllowance);
            EXPECT_TRUE(e.minCornerRadius < 0 || 0.5 * u.previousCutter->diameter + u.radialAllowance > e.minCornerRadius)
                << "unit " << u.id;
            ++rests;
        }
        // A child's unit starts from its parent's floor.
        if (u.step == StepCode::Rough && e.parent >= 0 && byId[e.parent]->type != recognition::ElementType::Hole)
            EXPECT_NEAR(u.top, std::min(e.top, byId[e.parent]->level + 0.5), 1e-9) << "unit " << u.id;
    }
    int throughHoles = 0, blindHoles = 0;
    for (const auto& e : tree.elements)
        if (e.hole) (e.hole->through ? throughHoles : blindHoles)++;
    EXPECT_EQ(drilled, throughHoles);  // every through hole size of the generator is in the series
    EXPECT_EQ(milledHoles, blindHoles);
    EXPECT_GT(drilled, 0);
    EXPECT_GT(rests, 0);
    // Every pocket whose roughing tool is wider than its corners got a rest unit.
    for (const MachiningUnit& r : c.units) {
        if (r.step != StepCode::Rough || r.operation != Operation::Pocket) continue;
        const auto& e = *byId[r.element];
        if (e.minCornerRadius < 0 || 0.5 * r.cutter.diameter + 0.5 <= e.minCornerRadius + 1e-3) continue;
        const bool finisherSmaller = std::any_of(c.units.begin(), c.units.end(), [&](const MachiningUnit& f) {
            return f.element == e.id && f.step == StepCode::FinishWall && f.cutter.diameter < r.cutter.diameter;
        });
        if (!finisherSmaller) continue;
        // Corners no tool fits are left to the walls' passes and listed (Fusing.cpp).
        if (std::any_of(c.remainders.begin(), c.remainders.end(),
                        [&](const Remainder& m) { return m.element == e.id && m.kind == "corners"; }))
            continue;
        EXPECT_TRUE(std::any_of(c.units.begin(), c.units.end(),
                                [&](const MachiningUnit& u) { return u.element == e.id && u.step == StepCode::Corner; }))
            << "element " << e.id;
    }
}

TEST(Fusing, SamplePanel) {
    const std::string part = AERONC_RESOURCES "/samples/sample_panel.step";
    const auto tree = recognition::recognise(loadPart(part), {});
    const auto kb = kbDir().open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    expectSoundChain(tree, c, part);
    // Its 6.6 and 20 mm through holes are drilled, the 11 mm counterbores milled.
    std::map<double, std::set<std::string>> toolsByHole;
    for (const MachiningUnit& u : c.units)
        for (const HoleTarget& h : u.holes) toolsByHole[std::round(h.diameter * 10) / 10].insert(u.tool);
    EXPECT_EQ(toolsByHole[6.6], (std::set<std::string>{"DR-6.6"}));
    EXPECT_EQ(toolsByHole[20.0], (std::set<std::string>{"DR-20"}));
    EXPECT_EQ(toolsByHole[11.0].size(), 1u);
    EXPECT_EQ(toolsByHole[11.0].begin()->rfind("EM-F", 0), 0u);
    // What is left is said: sharp inner corners no end mill finishes, as what the finished
    // pockets keep (not as pockets not machined). The countersinks are cut with a chamfer mill,
    // one edge unit each, and not listed.
    int sharp = 0, countersinks = 0;
    for (const Remainder& r : c.remainders)
        if (r.kind == "corners" && r.step == StepCode::FinishWall && r.needs.find("sharp") != std::string::npos) ++sharp;
    for (const Unmachined& m : c.unmachined) {
        EXPECT_EQ(m.reason.find("radius <= 0 mm"), std::string::npos) << m.reason;
        EXPECT_EQ(m.reason.find("countersink"), std::string::npos) << m.reason;
    }
    for (const MachiningUnit& u : c.units) countersinks += u.operation == Operation::Chamfer;
    int sharpPockets = 0, countersunk = 0;
    for (const auto& e : tree.elements) {
        if (e.type == recognition::ElementType::ClosedPocket && e.minCornerRadius == 0) ++sharpPockets;
        if (e.hole && e.hole->countersinkDiameter > 0) ++countersunk;
    }
    EXPECT_EQ(sharp, sharpPockets);
    EXPECT_EQ(countersinks, countersunk);
    EXPECT_GT(c.travel.savedPercent, 0);
    // Its three bosses stop 2 mm under the pocket tops: each is faced, none listed.
    std::set<double> facedHeights;
    for (const MachiningUnit& u : c.units)
        if (u.faceIslandTops)
            for (double h : u.islandTops)
                if (!std::isnan(h)) facedHeights.insert(h);
    EXPECT_EQ(facedHeights, (std::set<double>{18.0}));
    for (const Unmachined& m : c.unmachined) EXPECT_TRUE(m.faces.empty()) << m.reason;

    // Floors are finished with flat or bull end mills whose corner fits the floor fillet (the
    // ball end mills stay in the corners and on the walls), at a step-over whose scallops stay
    // under 0.01 mm: checked against the scallop of two corner arcs side by side.
    std::map<int, const recognition::DomainElement*> byId;
    for (const auto& e : tree.elements) byId[e.id] = &e;
    auto scallopOf = [](const MachiningUnit& u) {
        const double R = u.cutter.diameter / 2, r = u.cutter.cornerRadius;
        const double gap = u.stepOver - 2 * (R - r);  // where the corners of two passes overlap
        return gap <= 0 ? 0.0 : r - std::sqrt(std::max(0.0, r * r - gap * gap / 4));
    };
    // Rest units that go down to the floor's final height finish the floor in the corners: the
    // same scallop, also once the chain has been checked again (as after an edit).
    const MachiningChain rechecked = checkChain(c);
    int floorRests = 0;
    for (const MachiningChain* chain : {&c, &rechecked})
        for (const MachiningUnit& u : chain->units) {
            if (u.operation != Operation::Rest || u.axialAllowance > 1e-9) continue;
            ++floorRests;
            EXPECT_LE(scallopOf(u), 0.01 + 1e-9) << "rest unit " << u.id;
        }
    EXPECT_GT(floorRests, 0);
    int webs = 0;
    for (const MachiningUnit& u : c.units) {
        if (u.step != StepCode::Web) continue;
        ++webs;
        const auto& e = *byId.at(u.element);
        EXPECT_NE(u.cutter.type, "ball") << "web unit " << u.id << " (element " << u.element << ")";
        EXPECT_LE(u.cutter.cornerRadius, std::max(0.0, e.floorFilletRadius) + 1e-3) << "web unit " << u.id;
        EXPECT_DOUBLE_EQ(u.floorFilletRadius, std::max(0.0, e.floorFilletRadius));
        const double R = u.cutter.diameter / 2, r = u.cutter.cornerRadius;
        const double gap = u.stepOver - 2 * (R - r);  // where the corners of two passes overlap
        const double scallop = gap <= 0 ? 0.0 : r - std::sqrt(std::max(0.0, r * r - gap * gap / 4));
        EXPECT_LE(scallop, 0.01 + 1e-9) << "web unit " << u.id;
    }
    EXPECT_GT(webs, 10);
}

class NistChain : public ::testing::TestWithParam<std::string> {};

TEST_P(NistChain, EveryElementMachinedOrListed) {
    const std::string part = std::string(AERONC_SHARED_DATA) + "/nist/" + GetParam();
    if (!std::filesystem::exists(part)) GTEST_SKIP() << "no " << part;
    const auto tree = recognition::recognise(loadPart(part), {});
    const auto kb = kbDir().open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    expectSoundChain(tree, c, part);
    EXPECT_GT(c.units.size(), 10u);
}

INSTANTIATE_TEST_SUITE_P(Nist, NistChain,
                         ::testing::Values("nist_ftc_07_asme1_rd.stp", "nist_ftc_08_asme1_rc.stp",
                                           "nist_ftc_09_asme1_rd.stp", "nist_ctc_01_asme1_ap203.stp"),
                         [](const auto& info) { return info.param.substr(5, 6); });
