// How high the material may stand over each unit, on a chain written by hand: a pocket A with
// a sub-pocket B in its floor, a counterbore C with its hole H below it.
#include <aeronc/chain/StockTops.h>

#include <gtest/gtest.h>

using namespace aeronc::chain;

namespace {

ChainElement element(int id, int parent, double level, double top) {
    ChainElement e;
    e.id = id, e.parent = parent, e.level = level, e.top = top;
    return e;
}

MachiningUnit unit(int id, int element, StepCode step, double top, double bottom, double axial, int order) {
    MachiningUnit u;
    u.id = id, u.element = element, u.step = step, u.top = top, u.bottom = bottom, u.axialAllowance = axial;
    u.order = order;
    return u;
}

MachiningChain handChain(int drillOrder, int counterboreOrder) {
    MachiningChain c;
    c.elements = {element(0, -1, 5, 20), element(1, 0, 0, 5), element(2, 3, -1, 14), element(3, -1, 14, 20)};
    c.units = {unit(0, 0, StepCode::Rough, 20, 5, 0.5, 0),  unit(1, 1, StepCode::Rough, 5.5, 0, 0.5, 1),
               unit(2, 0, StepCode::Web, 5.5, 5, 0, 2),     unit(3, 2, StepCode::Drill, 14, -1, 0, drillOrder),
               unit(4, 3, StepCode::HoleMill, 20, 14, 0, counterboreOrder)};
    return c;
}

}  // namespace

TEST(StockTops, WhatEarlierUnitsLeaveStandsOverTheUnit) {
    MachiningChain c = handChain(3, 4);
    setStockTops(c);
    EXPECT_FALSE(c.units[0].stockTop.has_value());  // A's roughing starts at A's top
    // B's roughing: A's roughing left its axial allowance over B; B's top is A's floor.
    EXPECT_FALSE(c.units[1].stockTop.has_value());
    // A's web: A's walls rise to 20 and keep what the roughing left along them.
    ASSERT_TRUE(c.units[2].stockTop.has_value());
    EXPECT_DOUBLE_EQ(*c.units[2].stockTop, 20);
    // H drilled before its counterbore is milled: the counterbore's material stands over it.
    ASSERT_TRUE(c.units[3].stockTop.has_value());
    EXPECT_DOUBLE_EQ(*c.units[3].stockTop, 20);
    EXPECT_FALSE(c.units[4].stockTop.has_value());
}

TEST(StockTops, FollowTheOrder) {
    MachiningChain c = handChain(4, 3);  // the counterbore first: nothing stands over the hole
    setStockTops(c);
    EXPECT_FALSE(c.units[3].stockTop.has_value());
    // B roughed before A: A's whole height stands over it.
    c.units[0].order = 1, c.units[1].order = 0;
    setStockTops(c);
    ASSERT_TRUE(c.units[1].stockTop.has_value());
    EXPECT_DOUBLE_EQ(*c.units[1].stockTop, 20);
    // A disabled roughing clears nothing.
    c = handChain(3, 4);
    c.units[0].enabled = false;
    setStockTops(c);
    ASSERT_TRUE(c.units[1].stockTop.has_value());
    EXPECT_DOUBLE_EQ(*c.units[1].stockTop, 20);
    // Nor is a roughing short of its element's floor counted on (the gate may leave it out
    // alone): B's roughing comes down from A's top.
    c = handChain(3, 4);
    c.units[0].shortOfFloor = true;
    setStockTops(c);
    ASSERT_TRUE(c.units[1].stockTop.has_value());
    EXPECT_DOUBLE_EQ(*c.units[1].stockTop, 20);
}

// A root element below the blank's top of its setup (a pocket in a face that another setup, or
// nothing here, lowers): the blank may still stand over it, so its units come down at feed from
// the blank's top. A root at the blank's top is unchanged; without a blank top nothing changes.
TEST(StockTops, RootBelowTheBlanksTopStartsThere) {
    MachiningChain c = handChain(4, 3);
    ChainSetup s;
    s.id = 0;
    s.blankTop = 32;
    c.setups = {s};
    for (ChainElement& e : c.elements) e.setup = 0;
    for (MachiningUnit& u : c.units) u.setup = 0;
    setStockTops(c);
    for (const MachiningUnit& u : c.units) {
        ASSERT_TRUE(u.stockTop.has_value()) << "unit " << u.id;
        EXPECT_DOUBLE_EQ(*u.stockTop, 32) << "unit " << u.id;
    }
    c.setups[0].blankTop = 20;
    setStockTops(c);
    EXPECT_FALSE(c.units[0].stockTop.has_value());
    c.setups[0].blankTop.reset();
    setStockTops(c);
    EXPECT_FALSE(c.units[0].stockTop.has_value());
}

// A's roughing leaves 1 mm on A's walls (a 40 x 40 square) until A's walls are finished. A
// sub-pocket B along A's wall meets that allowance on its way down: the material stands there to
// A's top. B in the middle of A's floor does not; nor does B once A's walls are finished.
TEST(StockTops, WallAllowanceOfTheAncestorStandsOverAUnitAlongItsWall) {
    auto square = [](double x0, double y0, double x1, double y1) { return Loop{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; };
    auto chain = [&](Loop sub, int wallOrder) {
        MachiningChain c = handChain(3, 4);
        c.units[0].contour = square(0, 0, 40, 40), c.units[0].radialAllowance = 1;
        c.units[1].contour = std::move(sub), c.units[1].cutter.diameter = 4;
        MachiningUnit wall = unit(5, 0, StepCode::FinishWall, 20, 5, 0, wallOrder);
        wall.radialAllowance = 0;
        c.units.push_back(wall);
        setStockTops(c);
        return c.units[1].stockTop;
    };
    const auto along = chain(square(0, 10, 8, 20), 5);  // B's wall on A's wall at x = 0
    ASSERT_TRUE(along.has_value());
    EXPECT_DOUBLE_EQ(*along, 20);
    EXPECT_FALSE(chain(square(15, 15, 25, 25), 5).has_value());  // B in the middle of A's floor
    EXPECT_TRUE(chain(square(0.5, 10, 8, 20), 5).has_value());  // 0.5 mm off the wall: in the allowance
    EXPECT_FALSE(chain(square(1.5, 10, 8, 20), 5).has_value());  // beyond it
    EXPECT_FALSE(chain(square(0, 10, 8, 20), 0).has_value());    // A's walls finished before B
    // A hole whose mouth reaches into the allowance.
    MachiningChain c = handChain(3, 4);
    c.units[0].contour = square(0, 0, 40, 40), c.units[0].radialAllowance = 1;
    c.units[1].holes = {HoleTarget{3.5, 20, 6, 5, 0, false, 0}};
    setStockTops(c);
    ASSERT_TRUE(c.units[1].stockTop.has_value());
    EXPECT_DOUBLE_EQ(*c.units[1].stockTop, 20);
}
