// Rest machining: the smaller cutter sweeps what it reaches and the larger one did not, and
// works only near the corners.
#include "ErrorOf.h"
#include "Checks.h"

#include <aeronc/toolpath/PocketClearing.h>
#include <aeronc/toolpath/RestCorners.h>

#include <gtest/gtest.h>

using namespace aeronc::toolpath;
using namespace aeronc::toolpath::test;
using aeronc::test::inputErrorOf;

TEST(RestCorners, SweepsWhatTheLargerCutterLeftOnlyNearTheCorners) {
    const Loop contour = roundedRectangle(0, 0, 70, 50, 2);
    const std::vector<Loop> islands{roundedRectangle(25, 15, 45, 35, 1)};
    PocketUnit u{contour, islands, {}, 0, -6};
    PocketParameters p;
    p.stepOver = 2;
    p.stepDown = 3;
    p.radialAllowance = 0.2;
    const Cutter previous{16, 0}, small{5, 0};
    const Toolpath t = restCorners(u, previous, small, p);
    ASSERT_FALSE(t.moves.empty());
    const Raster r(-1, -1, 71, 51, 0.2);
    const auto reach = opening(r, contour, islands, 2.5, 0.2);
    const auto before = opening(r, contour, islands, 8, 0.2 - r.px);  // generous to the larger cutter
    const auto got = swept(r, cutsAt(t, -6), 2.5 + 0.02);
    std::size_t missed = 0, rest = 0;
    for (std::size_t k = 0; k < reach.size(); ++k) {
        if (!reach[k] || before[k]) continue;
        ++rest;
        missed += !got[k];
    }
    EXPECT_GT(rest, 500u);  // there is something to machine
    EXPECT_EQ(missed, 0u);
    // Only near the corners of the contour and of the island.
    std::vector<Point> corners{{0, 0}, {70, 0}, {70, 50}, {0, 50}, {25, 15}, {45, 15}, {45, 35}, {25, 35}};
    for (const auto& [a, b] : cutsAt(t, -6))
        for (const Point& q : {a, b}) {
            double d = 1e9;
            for (const Point& c : corners) d = std::min(d, dist(q, c));
            EXPECT_LT(d, 2 * 8 + 2.5) << q[0] << ", " << q[1];
        }
    // Never into the walls or the island.
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Point a{t.moves[i - 1].u, t.moves[i - 1].v}, b{t.moves[i].u, t.moves[i].v};
        if (std::max(t.moves[i - 1].h, t.moves[i].h) >= 0) continue;
        EXPECT_GE(loopSegmentDistance(contour, a, b), 2.7 - 0.011);
        EXPECT_GE(loopSegmentDistance(islands[0], a, b), 2.7 - 0.011);
    }
    // Far less than clearing the pocket again with the small cutter.
    EXPECT_LT(t.cutLength, pocketClearing(u, small, p).cutLength / 3);
}

TEST(RestCorners, NothingLeftGivesAnEmptyToolpath) {
    PocketUnit u{roundedRectangle(0, 0, 60, 40, 10), {}, {}, 0, -5};  // corners wider than both cutters
    const Toolpath t = restCorners(u, {16, 0}, {8, 0}, {});
    EXPECT_TRUE(t.moves.empty());
    EXPECT_EQ(t.cutLength, 0);
}

TEST(RestCorners, BadInputIsAClearError) {
    PocketUnit u{rectangle(0, 0, 60, 40), {}, {}, 0, -5};
    EXPECT_NE(inputErrorOf([&] { restCorners(u, {8, 0}, {8, 0}, {}); }).find("smaller"), std::string::npos);
    EXPECT_NE(inputErrorOf([&] { restCorners(u, {NAN, 0}, {8, 0}, {}); }).find("previous cutter"), std::string::npos);
}
