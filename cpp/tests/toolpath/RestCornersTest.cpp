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

// After a roughing that left 1 mm on the walls, a rest unit leaving 0.2 mm: the 0.8 mm band along
// every wall is material (the roughing's D16 never came nearer than 9 mm to the walls), so no
// rapid of the rest unit may come down through it, and the unit sweeps it with the corners.
// Before, the rest took the band as cleared: its entries came down through it.
TEST(RestCorners, RapidsStayOutOfWhatThePreviousUnitLeft) {
    const Loop contour = roundedRectangle(0, 0, 70, 50, 2);
    const std::vector<Loop> islands{roundedRectangle(25, 15, 45, 35, 1)};
    const double top = 0, bottom = -6;
    PocketUnit u{contour, islands, {}, top, bottom};
    PocketParameters p;
    p.stepOver = 2;
    p.stepDown = 3;
    p.radialAllowance = 0.2;
    const double a0 = 1.0, R0 = 8, R = 2.5;
    const Toolpath t = restCorners(u, {2 * R0, 0}, {2 * R, 0}, p, a0);
    ASSERT_FALSE(t.moves.empty());

    const Raster r(-1, -1, 71, 51, 0.1);
    // Generous to the roughing (more taken as cleared, less as material) by two pixels.
    const auto roughed = opening(r, contour, islands, R0, a0 - 2 * r.px);
    // The height of the material over each pixel of the pocket, as the moves go.
    std::vector<double> height(r.size(), -HUGE_VAL);
    for (int j = 0; j < r.nv; ++j)
        for (int i = 0; i < r.nu; ++i) {
            const Point c = r.centre(i, j);
            bool pocket = inside(contour, c);
            for (const Loop& isl : islands) pocket = pocket && !inside(isl, c);
            if (pocket && !roughed[r.at(i, j)]) height[r.at(i, j)] = top;
        }
    auto disc = [&](const Point& c, double radius, auto&& f) {
        const int i0 = std::max(0, int(std::floor((c[0] - radius - r.u0) / r.px)));
        const int i1 = std::min(r.nu - 1, int(std::ceil((c[0] + radius - r.u0) / r.px)));
        const int j0 = std::max(0, int(std::floor((c[1] - radius - r.v0) / r.px)));
        const int j1 = std::min(r.nv - 1, int(std::ceil((c[1] + radius - r.v0) / r.px)));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i)
                if (dist(r.centre(i, j), c) <= radius) f(r.at(i, j));
    };
    std::size_t through = 0;
    double worst = 0;
    for (std::size_t m = 1; m < t.moves.size(); ++m) {
        const Move& a = t.moves[m - 1];
        const Move& b = t.moves[m];
        const double l = std::hypot(b.u - a.u, b.v - a.v);
        const int n = std::max(1, int(std::ceil(l / 0.05)));
        for (int k = 0; k <= n; ++k) {
            const double s = double(k) / n;
            const Point c{a.u + s * (b.u - a.u), a.v + s * (b.v - a.v)};
            const double h = a.h + s * (b.h - a.h);
            if (b.kind == Move::Kind::Rapid) {
                // Within the cutter less 0.02 mm, nothing may stand above the rapid.
                disc(c, R - 0.02, [&](std::size_t q) {
                    if (height[q] > h + 1e-9) ++through, worst = std::max(worst, height[q] - h);
                });
            } else {
                // A cutting move lowers the material it sweeps to the higher of its ends.
                const double cut = std::max(a.h, b.h);
                disc(c, R, [&](std::size_t q) { height[q] = std::min(height[q], cut); });
            }
        }
    }
    EXPECT_EQ(through, 0u) << "rapids down to " << worst << " mm into the material left";
    // The band and the corners are swept at the floor: nothing within the rest cutter's reach
    // at 0.2 mm stands above it (stingy to the roughing by two pixels).
    const auto reach = opening(r, contour, islands, R, 0.2);
    const auto before = opening(r, contour, islands, R0, a0 + 2 * r.px);
    const auto got = swept(r, cutsAt(t, bottom), R + 0.02);
    std::size_t missed = 0, band = 0;
    for (std::size_t k = 0; k < reach.size(); ++k) {
        if (!reach[k] || before[k]) continue;
        ++band;
        missed += !got[k];
    }
    EXPECT_GT(band, 2000u);
    EXPECT_EQ(missed, 0u);
}
