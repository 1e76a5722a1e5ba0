// Tool selection against hand computations: analytic areas, worked time examples.
#include <aeronc/core/Error.h>
#include <aeronc/toolselect/Selection.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace aeronc::toolselect;

namespace {

constexpr double kPi = 3.14159265358979323846;
using Loop = std::vector<std::array<double, 2>>;

Loop rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

PocketGeometry pocket(Loop outer, double depth = 10, const std::string& name = "P1") {
    PocketGeometry p;
    p.outer = std::move(outer);
    p.depth = depth;
    p.name = name;
    return p;
}

Tool endMill(const std::string& id, double d, double cr = 0, double flute = 40, double reach = 60) {
    Tool t;
    t.id = id;
    t.type = cr == 0 ? "flat" : (std::fabs(cr - d / 2) < 1e-12 ? "ball" : "bull");
    t.material = "carbide";
    t.diameter = d, t.cornerRadius = cr, t.fluteLength = flute, t.reach = reach, t.flutes = 3;
    return t;
}

// Each 90° inside corner keeps (1 − π/4)·r² the tool cannot reach.
double cornerLoss(int corners, double r) { return corners * (1 - kPi / 4) * r * r; }

}  // namespace

TEST(ToolSelectionTest, RectangleEtaMatchesAnalyticArea) {
    const double W = 40, H = 30;
    for (double r : {0.5, 2.0, 5.0, 8.0, 12.0}) {
        SCOPED_TRACE("r = " + std::to_string(r));
        const MachinableRatio m = machinableRatio(pocket(rect(0, 0, W, H)), r);
        EXPECT_NEAR(m.area, W * H, 1e-9);
        EXPECT_NEAR(m.eta, 1 - (4 - kPi) * r * r / (W * H), 1e-3);
        // The round joins are inscribed chords: a little under the true arcs.
        EXPECT_NEAR(m.machinableArea, W * H - cornerLoss(4, r), 2e-4 * W * H);
        EXPECT_EQ(m.narrowPassages, 0);
    }
    // Clockwise input is the same pocket.
    Loop cw = rect(0, 0, W, H);
    std::reverse(cw.begin(), cw.end());
    EXPECT_NEAR(machinableRatio(pocket(cw), 8).eta, 1 - (4 - kPi) * 64 / (W * H), 1e-3);
    // A tool wider than the pocket reaches nothing.
    EXPECT_EQ(machinableRatio(pocket(rect(0, 0, W, H)), 15.5).eta, 0);
}

TEST(ToolSelectionTest, PocketWithIsland) {
    PocketGeometry p = pocket(rect(0, 0, 100, 60));
    p.islands.push_back(rect(40, 20, 60, 40));  // same orientation as the contour on purpose
    const double r = 4;
    const MachinableRatio m = machinableRatio(p, r);
    // The tool rolls round the island's convex corners, so only the contour's corners keep material.
    const double A = 100 * 60 - 20 * 20, Am = A - cornerLoss(4, r);
    EXPECT_NEAR(m.area, A, 1e-9);
    EXPECT_NEAR(m.eta, Am / A, 1e-3);
    EXPECT_NEAR(m.machinableArea, Am, 2e-4 * A);
    EXPECT_EQ(m.narrowPassages, 0);
}

TEST(ToolSelectionTest, IslandTooCloseToWallIsANarrowPassage) {
    PocketGeometry p = pocket(rect(0, 0, 100, 60));
    p.islands.push_back(rect(40, 3, 60, 40));  // 3 mm gap under it, tool 8 mm
    const MachinableRatio m = machinableRatio(p, 4);
    EXPECT_EQ(m.narrowPassages, 1);
    // The 20 x 3 gap is lost on top of the contour's corners; its ends keep a little more.
    const double A = 6000 - 20 * 37;
    EXPECT_LT(m.machinableArea, A - cornerLoss(4, 4) - 20 * 3 + 1e-6);
    EXPECT_GT(m.machinableArea, A - cornerLoss(4, 4) - 20 * 3 - 2 * 4 * 4);
}

TEST(ToolSelectionTest, DumbbellCorridorNarrowerThanTool) {
    // Two 40 x 40 squares joined by a 30 long, 8 wide corridor; tool diameter 10.
    const Loop outer = {{0, 0},   {40, 0},  {40, 16}, {70, 16}, {70, 0},  {110, 0},
                        {110, 40}, {70, 40}, {70, 24}, {40, 24}, {40, 40}, {0, 40}};
    const double A = 2 * 1600 + 30 * 8;
    const MachinableRatio m = machinableRatio(pocket(outer), 5);
    EXPECT_NEAR(m.area, A, 1e-9);
    EXPECT_EQ(m.narrowPassages, 1);
    // The squares keep their 8 corners, the corridor is lost except where the tool, standing
    // in a square, dips at most 2 mm into its mouth (the mouth corners are 3 mm from its centre).
    const double squares = 3200 - cornerLoss(8, 5);
    EXPECT_GE(m.machinableArea, squares - 0.1);
    EXPECT_LE(m.machinableArea, squares + 2 * 2 * 8);
    EXPECT_LT(m.eta, 0.95);
    EXPECT_THROW(roughingTool(pocket(outer), {endMill("T10", 10)}, 0.95), aeronc::Error);

    // A 6 mm tool passes: no narrow passage; the mouth corners are convex, so only the
    // squares' 8 corners keep material.
    const MachinableRatio small = machinableRatio(pocket(outer), 3);
    EXPECT_EQ(small.narrowPassages, 0);
    EXPECT_NEAR(small.machinableArea, A - cornerLoss(8, 3), 2e-4 * A);
}

// A region deeper than every end mill reaches (the side of a part 300 mm high): listed with the
// tool it would need and the longest reach the crib has.
TEST(ToolSelectionTest, RegionDeeperThanEveryReachNamesTheReachItNeeds) {
    Tool necked = endMill("F20x100", 20, 0, 30, 100);
    necked.neckDiameter = 19;
    const std::vector<Tool> tools = {endMill("F10", 10, 0, 22, 30), necked};
    try {
        roughingTool(pocket(rect(0, 0, 200, 60), 320, "element 7"), tools, 0.85);
        FAIL() << "a 320 mm deep region took a tool";
    } catch (const aeronc::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("pocket 'element 7'"), std::string::npos) << m;
        EXPECT_NE(m.find("the longest reaches 100 mm"), std::string::npos) << m;
        EXPECT_NE(m.find("it needs an end mill reaching 320 mm"), std::string::npos) << m;
    }
    // 90 mm: the necked D20 reaches it, its flutes (30 mm) being no limit.
    EXPECT_EQ(roughingTool(pocket(rect(0, 0, 200, 60), 90), tools, 0.85)->id, "F20x100");
}

TEST(ToolSelectionTest, DeadEndSlotNarrowerThanTool) {
    // A 40 x 40 pocket with a 6 wide, 20 deep slot out of its right wall; tool diameter 10.
    const Loop outer = {{0, 0}, {40, 0}, {40, 17}, {60, 17}, {60, 23}, {40, 23}, {40, 40}, {0, 40}};
    const MachinableRatio m = machinableRatio(pocket(outer), 5);
    EXPECT_EQ(m.narrowPassages, 1);
    EXPECT_NEAR(m.area, 1600 + 120, 1e-9);
    EXPECT_LT(m.machinableArea, 1600 - cornerLoss(4, 5) + 2 * 6 + 1e-6);
    // With a 4 mm tool the slot is reachable.
    EXPECT_EQ(machinableRatio(pocket(outer), 2).narrowPassages, 0);
}

TEST(ToolSelectionTest, FinishingPicksLargestRadiusWithinCorner) {
    std::vector<Tool> tools;
    for (int i = 0; i < 30; ++i) {
        const int d = 2 + (i * 7) % 30;  // 2..31, shuffled
        tools.push_back(endMill("T" + std::to_string(d), d));
    }
    PocketGeometry p = pocket(rect(0, 0, 100, 80), 20);
    p.minCornerRadius = 12.5;
    const Tool* t = finishingTool(p, tools);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->diameter, 25);
    p.minCornerRadius = 12.49;
    EXPECT_EQ(finishingTool(p, tools)->diameter, 24);
    p.minCornerRadius = -1;  // no corner limit
    EXPECT_EQ(finishingTool(p, tools)->diameter, 31);
    // Reach: make the 25 too short for the depth.
    p.minCornerRadius = 12.5;
    for (Tool& x : tools)
        if (x.diameter == 25) x.fluteLength = 15, x.reach = 18;
    EXPECT_EQ(finishingTool(p, tools)->diameter, 24);
}

TEST(ToolSelectionTest, FinishingMatchesFloorFillet) {
    const std::vector<Tool> tools = {endMill("F20", 20), endMill("B16r2", 16, 2), endMill("B12r3", 12, 3),
                                     endMill("B20r1", 20, 1), endMill("Ball6", 6, 3)};
    PocketGeometry p = pocket(rect(0, 0, 100, 80), 10);
    p.minCornerRadius = 10;
    p.floorFilletRadius = 2;
    EXPECT_EQ(finishingTool(p, tools)->id, "B16r2");  // equal corner radius beats a larger tool
    p.floorFilletRadius = 1;
    EXPECT_EQ(finishingTool(p, tools)->id, "B20r1");
    p.floorFilletRadius = 0.5;  // nothing equal: largest with corner radius <= 0.5
    EXPECT_EQ(finishingTool(p, tools)->id, "F20");
    p.floorFilletRadius = 0;
    EXPECT_EQ(finishingTool(p, tools)->id, "F20");
    p.floorFilletRadius = 3;
    p.minCornerRadius = 5;
    EXPECT_EQ(finishingTool(p, tools)->id, "Ball6");  // B12r3 is too wide for the corners
}

TEST(ToolSelectionTest, NoFinishingToolNamesWhatIsNeeded) {
    const std::vector<Tool> tools = {endMill("T2", 2), endMill("T6", 6), endMill("T10", 10)};
    PocketGeometry p = pocket(rect(0, 0, 50, 50), 10, "Rib pocket 7");
    p.minCornerRadius = 0.4;
    try {
        finishingTool(p, tools);
        FAIL() << "expected an error";
    } catch (const aeronc::Error& e) {
        EXPECT_EQ(e.kind(), aeronc::Error::Kind::Input);
        const std::string msg = e.what();
        EXPECT_NE(msg.find("Rib pocket 7"), std::string::npos) << msg;
        EXPECT_NE(msg.find("radius <= 0.4 mm"), std::string::npos) << msg;
    }
    p.minCornerRadius = 3;
    p.depth = 75;
    try {
        finishingTool(p, tools);
        FAIL() << "expected an error";
    } catch (const aeronc::Error& e) {
        EXPECT_NE(std::string(e.what()).find(">= 75 mm"), std::string::npos) << e.what();
    }
}

TEST(ToolSelectionTest, ImpossibleToolIsRejected) {
    std::vector<Tool> bad = {endMill("X", 10)};
    bad[0].cornerRadius = 6;
    bad[0].type = "bull";
    EXPECT_THROW(bad[0].validate(), aeronc::Error);
    Tool t = endMill("Y", 10);
    t.reach = 20, t.fluteLength = 30;
    EXPECT_THROW(t.validate(), aeronc::Error);
    t = endMill("Z", -1);
    try {
        t.validate();
        FAIL();
    } catch (const aeronc::Error& e) {
        EXPECT_NE(std::string(e.what()).find("'Z'"), std::string::npos);
    }
    PocketGeometry p = pocket(rect(0, 0, 50, 50));
    EXPECT_THROW(finishingTool(p, bad), aeronc::Error);
    EXPECT_NO_THROW(endMill("B", 10, 5).validate());
}

TEST(ToolSelectionTest, RoughingPicksFirstToolMeetingThreshold) {
    // 40 x 30: eta = 1 − (4 − π) r² / 1200 → r 15: 0, r 12: 0.897, r 10: 0.928, r 8: 0.954,
    // r 6: 0.974.
    std::vector<Tool> tools;
    for (double d : {6.0, 30.0, 12.0, 20.0, 8.0, 16.0, 24.0}) tools.push_back(endMill("D" + std::to_string(int(d)), d));
    const PocketGeometry p = pocket(rect(0, 0, 40, 30), 10);
    MachinableRatio m;
    const Tool* t = roughingTool(p, tools, 0.95, &m);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->diameter, 16);
    EXPECT_NEAR(m.eta, 1 - (4 - kPi) * 64 / 1200, 1e-3);
    EXPECT_EQ(roughingTool(p, tools, 0.96)->diameter, 12);
    EXPECT_EQ(roughingTool(p, tools, 0.90)->diameter, 20);  // r 12 gives 0.897
    EXPECT_EQ(roughingTool(p, tools, 0.89)->diameter, 24);
    for (Tool& x : tools)
        if (x.diameter == 16) x.fluteLength = 8, x.reach = 9;  // cannot reach 10 mm
    EXPECT_EQ(roughingTool(p, tools, 0.95)->diameter, 12);
    EXPECT_THROW(roughingTool(p, tools, 0.999), aeronc::Error);
}

TEST(ToolSelectionTest, UnitTimeWorkedExample) {
    const CuttingData d{6, 800, 2, 0.3};
    // t = 1200 / (6 · 800) = 0.25 min; H 10.5: nn 5, 0.5 left >= 0.3 → 6 layers.
    EXPECT_NEAR(unitTime(1200, 10.5, d), 1.5, 1e-12);
    // H 10.2: 0.2 left < 0.3 → 5 layers.
    EXPECT_NEAR(unitTime(1200, 10.2, d), 1.25, 1e-12);
    // 0.6 / 0.2 is 2.999… in floating point; still 3 layers.
    EXPECT_NEAR(unitTime(100, 0.6, {1, 100, 0.2, 0.05}), 3.0, 1e-12);
    EXPECT_THROW(unitTime(100, 1, {0, 100, 1, 0}), aeronc::Error);
}

TEST(ToolSelectionTest, MergeFollowsMuRule) {
    const std::vector<Tool> tools = {endMill("D20", 20), endMill("D16", 16)};
    const std::vector<ToolGroup> groups = {{0, {{2000, 10}}}, {1, {{1000, 8}}}};
    const CuttingData big{12, 1000, 5, 0.5};
    // Unit a with D20: 2000/12000 · 2 = 1/3.

    {   // D16 slow: b = 1000/9000 · 2 = 2/9, a with D16 = 2000/9000 · 3 = 6/9 → mu = (5/9)/(8/9) = 0.625.
        const CuttingData slow{10, 900, 4, 0.5};
        auto of = [&](std::size_t i) { return i == 0 ? big : slow; };
        MergeReport r;
        const auto out = mergeGroups(groups, tools, 0.7, of, &r);
        EXPECT_EQ(out.size(), 2u);
        EXPECT_TRUE(r.merges.empty());
        EXPECT_EQ(r.toolChangesBefore, 1);
        EXPECT_EQ(r.toolChangesAfter, 1);
        EXPECT_NEAR(r.timeBefore, 1.0 / 3 + 2.0 / 9, 1e-12);
        EXPECT_NEAR(r.timeAfter, r.timeBefore, 1e-12);
        // Below 0.625 the same pair merges.
        const auto merged = mergeGroups(groups, tools, 0.6, of, &r);
        ASSERT_EQ(merged.size(), 1u);
        ASSERT_EQ(r.merges.size(), 1u);
        EXPECT_NEAR(r.merges[0].mu, 0.625, 1e-12);
        EXPECT_NEAR(r.timeAfter, 8.0 / 9, 1e-12);
    }
    {   // D16 fast: b = 1000/11000 · 2 = 2/11, a with D16 = 4/11 → mu = (1/3 + 2/11)/(6/11) = 17/18.
        const CuttingData fast{11, 1000, 5, 0.5};
        auto of = [&](std::size_t i) { return i == 0 ? big : fast; };
        MergeReport r;
        const auto out = mergeGroups(groups, tools, 0.7, of, &r);
        ASSERT_EQ(out.size(), 1u);
        EXPECT_EQ(out[0].tool, 1u);  // onto the smaller tool
        EXPECT_EQ(out[0].units.size(), 2u);
        ASSERT_EQ(r.merges.size(), 1u);
        EXPECT_NEAR(r.merges[0].mu, 17.0 / 18, 1e-12);
        EXPECT_EQ(r.toolChangesBefore, 1);
        EXPECT_EQ(r.toolChangesAfter, 0);
        EXPECT_NEAR(r.timeBefore, 1.0 / 3 + 2.0 / 11, 1e-12);
        EXPECT_NEAR(r.timeAfter, 6.0 / 11, 1e-12);
        // The smaller tool must reach the larger group's units.
        std::vector<Tool> shortTools = tools;
        shortTools[1].fluteLength = shortTools[1].reach = 9;
        EXPECT_EQ(mergeGroups(groups, shortTools, 0.7, of).size(), 2u);
    }
}

// A necked tool's relieved neck clears the wall it finished: it cuts as deep as its reach. A tool
// without a neck is as wide as the cutter behind its flutes: its flutes limit the depth.
TEST(ToolSelectionTest, ANeckedToolReachesPastItsFlutes) {
    Tool standard = endMill("F6", 6, 0, 13, 20);
    Tool necked = endMill("F6x30", 6, 0, 9, 30);
    necked.neckDiameter = 5.7;
    EXPECT_NO_THROW(necked.validate());
    EXPECT_DOUBLE_EQ(standard.usableLength(), 13);
    EXPECT_DOUBLE_EQ(necked.usableLength(), 30);
    EXPECT_DOUBLE_EQ(necked.passHeight(), 9);
    PocketGeometry p = pocket(rect(0, 0, 50, 50), 28, "deep");
    p.minCornerRadius = 3;
    EXPECT_EQ(finishingTool(p, {standard, necked})->id, "F6x30");
    EXPECT_THROW(finishingTool(p, {standard}), aeronc::Error);
    necked.neckDiameter = 6;  // not below the cutter: no neck
    EXPECT_THROW(necked.validate(), aeronc::Error);
}
