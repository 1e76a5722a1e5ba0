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
