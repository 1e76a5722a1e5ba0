// Tool planning fed by the knowledge base (kb/ToolPlanning.h): generated panels whose pockets
// and holes are known by construction, planned with the shipped knowledge base, checked
// against hand computation.
#include <aeronc/core/Error.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/kb/KnowledgeBase.h>
#include <aeronc/kb/ToolPlanning.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/PanelGenerator.h>
#include <aeronc/toolselect/PlanJson.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace aeronc;
using namespace aeronc::toolselect;
using aeronc::recognition::DomainTree;
using aeronc::recognition::ElementType;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A plain panel: pockets only, vertical corner radius 6, floor fillet 2.
testparts::PanelSpec plainSpec() {
    testparts::PanelSpec s;
    s.pocketsX = 2;
    s.pocketsY = 1;
    s.pitch = 30;  // pocket 26 x 26: small enough that the largest tools do not qualify
    s.cornerRadius = 6;
    s.floorFillet = 2;
    s.lowerRibs = s.islands = s.openings = s.lighteningHoles = s.boltHoles = false;
    s.joggles = s.flange = s.bottomPockets = false;
    return s;
}

DomainTree recogniseUp(const testparts::PanelSpec& spec) {
    const auto panel = testparts::makePanel(spec);
    recognition::RecogniseOptions o;
    o.directions = {{0, 0, 1}};
    return recognition::recognise(validatedSolid(panel.shape, "panel"), o);
}

class ToolPlanningTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("aeronc_plan_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    kb::KnowledgeBase openDefault() {
        return kb::KnowledgeBase::openWithSqlFolder((dir_ / "kb.sqlite").string(),
                                                    [] { return (fs::path(AERONC_RESOURCES) / "kb").string(); });
    }
    fs::path dir_;
};

}  // namespace

TEST_F(ToolPlanningTest, PanelToolsMatchHandComputation) {
    const testparts::PanelSpec spec = plainSpec();
    const DomainTree tree = recogniseUp(spec);
    auto kb = openDefault();
    const std::string material = "7050-T7451";
    const ToolPlan plan = kb::planTools(tree, kb, material);
    const std::vector<Tool> tools = kb.tools();

    // Hand geometry: the pocket is the pitch-minus-rib square with rounded vertical corners.
    const double side = spec.pitch - spec.ribThickness;  // 26
    const double rc = spec.cornerRadius;                 // 6
    const double depth = spec.thickness - spec.webZ;     // 12
    const double A = side * side - (4 - kPi) * rc * rc;
    // A disc of radius r >= rc sweeps the square minus (4 - pi) r^2 at its corners, while
    // the disc fits (2r <= side); a larger disc does not enter at all.
    auto etaByHand = [&](double r) {
        if (2 * r > side) return 0.0;
        const double rr = std::max(r, rc);
        return (side * side - (4 - kPi) * rr * rr) / A;
    };
    const double etaMin = kb.threshold("eta_min");

    // Finishing by hand: the largest end mill with radius <= 6, corner radius equal to the
    // floor fillet 2 and reach >= 12 mm: EM-B12R2 in default_data.sql.
    const Tool* finisher = nullptr;
    for (const Tool& t : tools)
        if (t.isEndMill() && t.radius() <= rc + 1e-9 && std::fabs(t.cornerRadius - spec.floorFillet) < 1e-9 &&
            t.usableLength() >= depth && (!finisher || t.diameter > finisher->diameter))
            finisher = &t;
    ASSERT_TRUE(finisher);
    EXPECT_EQ(finisher->id, "EM-B12R2");

    // Roughing by hand: from the largest end mill reaching the depth down, the first whose
    // eta meets the threshold: D25 gives 0.840, D20 gives 0.915, so EM-B20R3 (ties by id).
    const Tool* rougher = nullptr;
    for (const Tool& t : tools)  // largest diameter first, ties by id
        if (t.isEndMill() && t.usableLength() >= depth && etaByHand(t.radius()) >= etaMin) {
            rougher = &t;
            break;
        }
    ASSERT_TRUE(rougher);
    EXPECT_EQ(rougher->id, "EM-B20R3");
    EXPECT_LT(etaByHand(12.5), etaMin);

    int pockets = 0;
    for (const ElementChoice& c : plan.elements) {
        ASSERT_EQ(c.type, ElementType::ClosedPocket) << "element " << c.element;
        ++pockets;
        EXPECT_EQ(c.error, "") << "element " << c.element;
        ASSERT_GE(c.finishingTool, 0);
        ASSERT_GE(c.roughingTool, 0);
        EXPECT_EQ(plan.tools[c.finishingTool].id, finisher->id) << "element " << c.element;
        EXPECT_EQ(plan.tools[c.roughingTool].id, rougher->id) << "element " << c.element;
        EXPECT_NEAR(c.ratio.area, A, 1e-3 * A) << "element " << c.element;
        EXPECT_NEAR(c.ratio.eta, etaByHand(rougher->radius()), 1e-3) << "element " << c.element;
        EXPECT_EQ(c.ratio.narrowPassages, 0);

        // Every end mill that fits in the pocket: eta against the hand value.
        const auto& e = tree.elements[static_cast<std::size_t>(c.element)];
        const PocketGeometry g = pocketGeometry(e, tree.setups[0].direction);
        EXPECT_NEAR(g.minCornerRadius, rc, 1e-3);
        EXPECT_NEAR(g.floorFilletRadius, spec.floorFillet, 1e-3);
        EXPECT_NEAR(g.depth, depth, 1e-6);
        for (double r : {1.0, 3.0, 6.0, 8.0, 10.0, 12.5})
            EXPECT_NEAR(machinableRatio(g, r).eta, etaByHand(r), 1e-3) << "r " << r;
    }
    EXPECT_EQ(pockets, spec.pocketsX * spec.pocketsY);
    EXPECT_TRUE(plan.holes.empty());

    // One roughing group, no merging; its time by hand: t = A / (a_e * f * n), N layers.
    ASSERT_EQ(plan.groupsBefore.size(), 1u);
    ASSERT_EQ(plan.groupsAfter.size(), 1u);
    EXPECT_EQ(plan.groupsAfter[0].elements.size(), 2u);
    EXPECT_EQ(plan.merge.toolChangesBefore, 0);
    EXPECT_EQ(plan.merge.toolChangesAfter, 0);
    const auto cc = kb.cuttingCondition(material, rougher->material, "roughing", rougher->diameter);
    const double n = 1000 * cc.vc / (kPi * rougher->diameter);
    const double feed = cc.fz * rougher->flutes * n;
    const double ae = cc.aeRatio * rougher->diameter;
    const double nn = std::floor(depth / cc.ap + 1e-9);
    const double layers = depth - nn * cc.ap < kb.threshold("layer_delta_mm") ? nn : nn + 1;
    EXPECT_NEAR(plan.merge.timeBefore, 2 * A / (ae * feed) * layers, 2e-3 * plan.merge.timeBefore);
    EXPECT_DOUBLE_EQ(plan.merge.timeAfter, plan.merge.timeBefore);

    // What the ToolControllers get: the rougher's speed and feeds by hand.
    int roughSettings = 0;
    for (const ToolSetting& ts : plan.settings) {
        if (plan.tools[ts.tool].id != rougher->id || ts.operation != "roughing") continue;
        ++roughSettings;
        EXPECT_NEAR(ts.spindleRpm, std::min(n, kb.machine(kb.machineNames().front()).maxSpindleRpm), 1e-9);
        EXPECT_NEAR(ts.feedMmMin, feed, 1e-9);
        EXPECT_NEAR(ts.plungeFeedMmMin, feed * kb.threshold("plunge_feed_ratio"), 1e-9);
        EXPECT_NEAR(ts.ae, ae, 1e-12);
    }
    EXPECT_EQ(roughSettings, 1);

    const std::string json = toJson(plan, material);
    EXPECT_NE(json.find("\"roughingTool\": \"EM-B20R3\""), std::string::npos) << json;
}

TEST_F(ToolPlanningTest, HoleGetsTheDrillOfItsDiameter) {
    testparts::PanelSpec spec = plainSpec();
    spec.boltHoles = true;  // through holes of 6.6 mm, some under an 11 mm counterbore
    const DomainTree tree = recogniseUp(spec);
    auto kb = openDefault();

    // The shipped series has the 6.6 mm clearance drill.
    ToolPlan plan = kb::planTools(tree, kb, "7050-T7451");
    int bolts = 0;
    for (const HoleChoice& h : plan.holes) {
        if (std::fabs(h.diameter - 6.6) > 1e-3) continue;
        ++bolts;
        ASSERT_GE(h.drill, 0) << h.error;
        EXPECT_EQ(plan.tools[h.drill].id, "DR-6.6");
        EXPECT_EQ(h.error, "");
    }
    EXPECT_GT(bolts, 0);

    // Without it, the 6.8 mm tap drill is not close enough: the holes are reported.
    const auto table = kb.table("tool");
    for (std::size_t i = 0; i < table.rows.size(); ++i)
        if (table.rows[i][0] == std::string("DR-6.6")) kb.editTable("tool", {}, {}, {table.rowIds[i]});
    plan = kb::planTools(tree, kb, "7050-T7451");
    int reported = 0;
    for (const HoleChoice& h : plan.holes) {
        if (std::fabs(h.diameter - 6.6) > 1e-3) continue;
        ++reported;
        EXPECT_EQ(h.drill, -1);
        EXPECT_NE(h.error.find("no drill of diameter 6.6"), std::string::npos) << h.error;
        EXPECT_NE(h.error.find("hole element " + std::to_string(h.element)), std::string::npos) << h.error;
    }
    EXPECT_EQ(reported, bolts);
    // The pockets are planned as before.
    for (const ElementChoice& c : plan.elements) EXPECT_EQ(c.error, "") << c.element;
}

TEST_F(ToolPlanningTest, UnknownMaterialIsAnInputError) {
    auto kb = openDefault();
    DomainTree tree;
    try {
        kb::planTools(tree, kb, "unobtainium");
        ADD_FAILURE() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), Error::Kind::Input);
        EXPECT_NE(std::string(e.what()).find("material 'unobtainium'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("7050-T7451"), std::string::npos) << e.what();
    }
}

// A real part nobody here made: every milled element's finishing tool is the one a
// programmer picks by hand from the tool list (the four conditions, a tool matching the floor
// fillet first, then the largest), and its roughing tool is the first from the largest down
// whose eta meets the threshold.
TEST_F(ToolPlanningTest, NistPartToolsFollowTheRulesByHand) {
    const fs::path part = fs::path(AERONC_SHARED_DATA) / "nist" / "nist_ftc_07_asme1_rd.stp";
    if (!fs::exists(part)) GTEST_SKIP() << "no " << part;
    const auto kb = openDefault();
    const std::string material = "7050-T7451";
    const DomainTree tree = recognition::recognise(loadPart(part.string()), {});
    const ToolPlan plan = kb::planTools(tree, kb, material);
    const double etaMin = kb.threshold("eta_min");
    auto hasData = [&](const Tool& t, const char* op) {
        try {
            kb.cuttingCondition(material, t.material, op, t.diameter);
            return true;
        } catch (const Error&) {
            return false;
        }
    };

    int checkedFinish = 0, checkedRough = 0;
    for (const ElementChoice& c : plan.elements) {
        const auto& e = tree.elements[static_cast<std::size_t>(c.element)];
        Vec3 dir{0, 0, 1};
        for (const auto& s : tree.setups)
            if (s.id == e.setup) dir = s.direction;
        const PocketGeometry g = pocketGeometry(e, dir);
        const double fillet = std::max(0.0, g.floorFilletRadius);

        // Finishing by hand.
        std::string expected;
        bool expectedMatches = false;
        double expectedD = 0;
        for (const Tool& t : plan.tools) {
            if (!(t.type == "flat" || t.type == "bull" || t.type == "ball") || !hasData(t, "finishing")) continue;
            if (g.minCornerRadius >= 0 && t.diameter / 2 > g.minCornerRadius + 1e-6) continue;
            if (t.cornerRadius > fillet + 1e-6) continue;
            if (t.usableLength() < g.depth - 1e-6) continue;
            const bool matches = fillet > 0 && std::fabs(t.cornerRadius - fillet) <= 1e-6;
            if (expected.empty() || (matches && !expectedMatches) ||
                (matches == expectedMatches && t.diameter > expectedD + 1e-6))
                expected = t.id, expectedMatches = matches, expectedD = t.diameter;
        }
        if (expected.empty()) {
            EXPECT_EQ(c.finishingTool, -1) << "element " << c.element;
        } else {
            ASSERT_GE(c.finishingTool, 0) << "element " << c.element << ": " << c.error;
            EXPECT_EQ(plan.tools[c.finishingTool].id, expected) << "element " << c.element;
            ++checkedFinish;
        }

        // Roughing: the chosen tool meets eta_min, every larger candidate does not.
        if (c.roughingTool < 0) continue;
        const Tool& chosen = plan.tools[c.roughingTool];
        EXPECT_GE(c.ratio.eta, etaMin - 1e-12) << "element " << c.element;
        EXPECT_NEAR(machinableRatio(g, chosen.radius()).eta, c.ratio.eta, 1e-9);
        for (const Tool& t : plan.tools) {
            if (!(t.type == "flat" || t.type == "bull" || t.type == "ball") || !hasData(t, "roughing")) continue;
            if (t.diameter <= chosen.diameter + 1e-9 || t.usableLength() < g.depth - 1e-6) continue;
            EXPECT_LT(machinableRatio(g, t.radius()).eta, etaMin) << "element " << c.element << ": " << t.id
                                                                  << " is larger and would do";
        }
        ++checkedRough;
    }
    EXPECT_GT(checkedFinish, 0);
    EXPECT_GT(checkedRough, 0);
}
