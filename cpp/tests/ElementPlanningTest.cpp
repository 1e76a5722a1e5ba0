// Tool planning for a recognised part from a given tool list (no knowledge base): element
// geometry, per-element failures, cutting data, checked against hand computation.
#include <aeronc/core/Error.h>
#include <aeronc/toolselect/ElementPlanning.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace aeronc;
using namespace aeronc::toolselect;
using aeronc::recognition::DomainTree;

TEST(ElementPlanning, PocketGeometryProjectsOntoTheSetupPlane) {
    // A 40 x 10 rectangle at z = 5 seen from -Z: the projection keeps its size and area.
    recognition::DomainElement e;
    e.id = 7;
    e.setup = 0;
    e.depth = 4;
    e.minCornerRadius = -1;
    e.floorFilletRadius = 1.5;
    e.contour = {{0, 0, 5}, {40, 0, 5}, {40, 10, 5}, {0, 10, 5}};
    e.islands = {{{10, 2, 5}, {12, 2, 5}, {12, 4, 5}, {10, 4, 5}}};
    const PocketGeometry g = pocketGeometry(e, {0, 0, -2});
    EXPECT_EQ(g.name, "element 7");
    EXPECT_DOUBLE_EQ(g.depth, 4);
    EXPECT_DOUBLE_EQ(g.minCornerRadius, -1);
    EXPECT_DOUBLE_EQ(g.floorFilletRadius, 1.5);
    ASSERT_EQ(g.outer.size(), 4u);
    ASSERT_EQ(g.islands.size(), 1u);
    double area2 = 0;
    for (std::size_t i = 0, j = 3; i < 4; j = i++)
        area2 += g.outer[j][0] * g.outer[i][1] - g.outer[i][0] * g.outer[j][1];
    EXPECT_NEAR(std::fabs(area2) / 2, 400, 1e-9);
    EXPECT_NEAR(std::hypot(g.outer[1][0] - g.outer[0][0], g.outer[1][1] - g.outer[0][1]), 40, 1e-9);

    // A tilted direction: the loop lies in the plane square to it, so its area is kept too.
    const double c = std::cos(0.3), s = std::sin(0.3);
    recognition::DomainElement t = e;
    t.contour.clear();
    for (const auto& p : e.contour) t.contour.push_back({p[0], c * p[1] - s * p[2], s * p[1] + c * p[2]});
    const PocketGeometry gt = pocketGeometry(t, {0, -s, c});
    area2 = 0;
    for (std::size_t i = 0, j = 3; i < 4; j = i++)
        area2 += gt.outer[j][0] * gt.outer[i][1] - gt.outer[i][0] * gt.outer[j][1];
    EXPECT_NEAR(std::fabs(area2) / 2, 400, 1e-9);
    EXPECT_THROW(pocketGeometry(e, {0, 0, 0}), Error);
}

TEST(ElementPlanning, AnElementWithoutAToolIsReportedAndTheOthersStillPlanned) {
    DomainTree tree;
    tree.setups.push_back({0, {0, 0, 1}, "+Z", {0, 1}});
    auto square = [](int id, double side, double corner) {
        recognition::DomainElement e;
        e.id = id;
        e.setup = 0;
        e.depth = 10;
        e.minCornerRadius = corner;
        e.contour = {{0, 0, 0}, {side, 0, 0}, {side, side, 0}, {0, side, 0}};
        return e;
    };
    tree.elements = {square(0, 50, 5), square(1, 50, 0)};  // element 1: sharp corners
    Tool t;
    t.id = "F10";
    t.type = "flat";
    t.material = "carbide";
    t.diameter = 10;
    t.flutes = 3;
    t.fluteLength = 30;
    t.reach = 40;
    PlanSettings s;
    s.etaMin = 0.5;
    s.roughingData = [&](std::size_t i) { return roughingCuttingData(t, 600, 0.1, 4, 0.5, 0.2); };
    const ToolPlan plan = planTools(tree, {t}, s);
    ASSERT_EQ(plan.elements.size(), 2u);
    EXPECT_EQ(plan.elements[0].finishingTool, 0);
    EXPECT_EQ(plan.elements[0].error, "");
    EXPECT_EQ(plan.elements[1].finishingTool, -1);
    EXPECT_EQ(plan.elements[1].roughingTool, 0);  // roughing does not need the corner radius
    EXPECT_NE(plan.elements[1].error.find("element 1"), std::string::npos) << plan.elements[1].error;
    EXPECT_NE(plan.elements[1].error.find("radius <= 0"), std::string::npos) << plan.elements[1].error;
    ASSERT_EQ(plan.groupsBefore.size(), 1u);
    EXPECT_EQ(plan.groupsBefore[0].elements, (std::vector<int>{0, 1}));
    EXPECT_EQ(plan.merge.toolChangesBefore, 0);
}

// The machine's spindle limit caps n, so small tools cut slower than the formula alone says.
TEST(ElementPlanning, SpindleSpeedCappedByMachine) {
    Tool t;
    t.id = "D6";
    t.type = "flat";
    t.material = "carbide";
    t.diameter = 6, t.flutes = 3, t.fluteLength = 18, t.reach = 30;
    // v_c 900 m/min on D6: n = 1000·900/(π·6) ≈ 47,746 r/min.
    const CuttingData free = roughingCuttingData(t, 900, 0.1, 2, 0.5, 0.2);
    EXPECT_NEAR(free.feedPerMinute, 0.1 * 3 * 1000 * 900 / (M_PI * 6), 1e-6);
    const CuttingData capped = roughingCuttingData(t, 900, 0.1, 2, 0.5, 0.2, 18000);
    EXPECT_NEAR(capped.feedPerMinute, 0.1 * 3 * 18000, 1e-9);
    EXPECT_NEAR(capped.ae, 3, 1e-12);
    // A cap above n changes nothing.
    EXPECT_NEAR(roughingCuttingData(t, 900, 0.1, 2, 0.5, 0.2, 60000).feedPerMinute, free.feedPerMinute, 1e-9);
}
