// Cutting levels: equal steps of at most stepDown, the last exactly at the floor.
#include "ErrorOf.h"

#include <aeronc/toolpath/Levels.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace aeronc::toolpath;
using aeronc::test::inputErrorOf;

TEST(Levels, ExactMultipleGivesFullSteps) {
    const auto l = cuttingLevels(0, -20, 4);
    ASSERT_EQ(l.size(), 5u);
    for (std::size_t i = 0; i < l.size(); ++i) EXPECT_NEAR(l[i], -4.0 * double(i + 1), 1e-12);
    EXPECT_EQ(l.back(), -20.0);
}

TEST(Levels, RemainderIsSharedAndLastIsExact) {
    const double top = 12.3, floor = -8.7 + 0.2;
    const auto l = cuttingLevels(top, floor, 4);
    ASSERT_EQ(l.size(), std::size_t(std::ceil((top - floor) / 4)));
    double above = top;
    for (double h : l) {
        EXPECT_LE(above - h, 4 + 1e-12);
        EXPECT_GT(above - h, 0);
        above = h;
    }
    EXPECT_EQ(l.back(), floor);
}

TEST(Levels, ShallowerThanOneStepIsOneLevel) {
    const auto l = cuttingLevels(5, 4.5, 4);
    ASSERT_EQ(l.size(), 1u);
    EXPECT_EQ(l[0], 4.5);
}

TEST(Levels, BadInputIsRefused) {
    EXPECT_NE(inputErrorOf([] { cuttingLevels(0, 1, 4); }).find("below"), std::string::npos);
    EXPECT_NE(inputErrorOf([] { cuttingLevels(0, -1, 0); }).find("stepDown"), std::string::npos);
    EXPECT_NE(inputErrorOf([] { cuttingLevels(0, -1, -2); }).find("stepDown"), std::string::npos);
    EXPECT_NE(inputErrorOf([] { cuttingLevels(NAN, -1, 1); }).find("finite"), std::string::npos);
    EXPECT_NE(inputErrorOf([] { cuttingLevels(0, -1e6, 1e-3); }).find("10,000"), std::string::npos);
}
