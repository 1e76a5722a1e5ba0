// Pocket clearing against geometry with known truth: the rings of a rectangle, the exact
// offset from the walls, the levels, islands, open edges, entries, and coverage of the floor
// by the swept cutter compared with the pocket's opening, both rasterised.
#include "ErrorOf.h"
#include "Checks.h"

#include <aeronc/toolpath/Levels.h>
#include <aeronc/toolpath/PocketClearing.h>

#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace aeronc::toolpath;
using namespace aeronc::toolpath::test;
using aeronc::test::inputErrorOf;

namespace {

PocketParameters params(double stepOver, double radial = 0, double axial = 0) {
    PocketParameters p;
    p.stepOver = stepOver;
    p.stepDown = 4;
    p.radialAllowance = radial;
    p.axialAllowance = axial;
    return p;
}

// Every segment of the path below `top`, rapids included (between two moves).
template <class F>
void forEachSegmentBelow(const Toolpath& t, double top, F f) {
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Move& a = t.moves[i - 1];
        const Move& b = t.moves[i];
        if (std::max(a.h, b.h) < top - 1e-9) f(Point{a.u, a.v}, Point{b.u, b.v}, b.kind);
    }
}

std::size_t uncovered(const Raster& r, const std::vector<char>& want, const std::vector<char>& got) {
    std::size_t n = 0;
    for (std::size_t k = 0; k < want.size(); ++k) n += want[k] && !got[k];
    return n;
}

}  // namespace

// A 80 x 62 rectangle, D 10, allowance 0.5: the centre region is the rectangle [5.5, 74.5] x
// [5.5, 56.5], and ring k lies k step-overs inside it; ring k exists while k s < 25.5.
TEST(PocketClearing, RectangleRingsAreTheOffsetsOfTheCentreRegion) {
    PocketUnit u{rectangle(0, 0, 80, 62), {}, {}, 0, -20};
    const Cutter c{10, 0};
    const double s = 5, off = 5.5;
    const Toolpath t = pocketClearing(u, c, params(s, 0.5, 0.2));
    const double u0 = off, u1 = 80 - off, v0 = off, v1 = 62 - off;
    const int expectedRings = int(std::ceil(((v1 - v0) / 2) / s));
    ASSERT_EQ(expectedRings, 6);
    auto ringOf = [&](const Point& p) {
        const double d = std::min({p[0] - u0, u1 - p[0], p[1] - v0, v1 - p[1]});
        const double k = std::round(d / s);
        return std::abs(d - k * s) < 1e-6 ? int(k) : -1;
    };
    const auto cuts = cutsAt(t, -19.8);
    // Runs of consecutive cuts along one ring; a ring cut in full runs its whole perimeter.
    std::map<int, int> fullRings;
    double run = 0;
    int runRing = -2;
    auto close = [&] {
        if (runRing < 0) return;
        const double perimeter = 2 * ((u1 - u0 - 2 * runRing * s) + (v1 - v0 - 2 * runRing * s));
        if (run >= perimeter - 1e-6) ++fullRings[runRing];
    };
    for (const auto& [a, b] : cuts) {
        const int ra = ringOf(a), rb = ringOf(b);
        const bool along = ra >= 0 && ra == rb && (std::abs(a[0] - b[0]) < 1e-9 || std::abs(a[1] - b[1]) < 1e-9);
        if (along && ra == runRing) {
            run += dist(a, b);
        } else {
            close();
            runRing = along ? ra : -2;
            run = along ? dist(a, b) : 0;
        }
    }
    close();
    ASSERT_EQ(int(fullRings.size()), expectedRings);
    for (int k = 0; k < expectedRings; ++k) EXPECT_EQ(fullRings[k], 1) << "ring " << k;
}

TEST(PocketClearing, BoundaryRingIsExactlyRadiusPlusAllowanceFromTheWalls) {
    const Loop contour = roundedRectangle(0, 0, 80, 80, 8);
    PocketUnit u{contour, {}, {}, 10, -10};
    for (double allowance : {0.0, 0.3, 1.0}) {
        const Toolpath t = pocketClearing(u, {16, 0}, params(8, allowance));
        double nearest = 1e9;
        forEachSegmentBelow(t, u.top, [&](const Point& a, const Point& b, Move::Kind) {
            EXPECT_TRUE(inside(contour, a) && inside(contour, b));
            nearest = std::min(nearest, loopSegmentDistance(contour, a, b));
        });
        // The corners (8 mm) are tighter than the cutter (8 mm + allowance): the polygonal
        // contour's vertices there are the nearest points, a chord tolerance away at most.
        EXPECT_NEAR(nearest, 8 + allowance, 0.011) << "allowance " << allowance;
    }
}

TEST(PocketClearing, EveryLevelIsCutAndTheLastIsExact) {
    PocketUnit u{rectangle(0, 0, 50, 40), {}, {}, 3, -18.5};
    PocketParameters p = params(4, 0, 0.25);
    p.stepDown = 3.5;
    const Toolpath t = pocketClearing(u, {8, 0}, p);
    const auto levels = cuttingLevels(3, -18.25, 3.5);
    std::set<double> flat;  // heights of horizontal feed moves
    double lowest = 1e9;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        lowest = std::min(lowest, t.moves[i].h);
        if (t.moves[i].kind == Move::Kind::Feed && t.moves[i].h == t.moves[i - 1].h) flat.insert(t.moves[i].h);
    }
    EXPECT_EQ(flat, std::set<double>(levels.begin(), levels.end()));
    EXPECT_EQ(lowest, -18.25);
    EXPECT_EQ(levels.size(), 7u);
    // Each level is cleared in full: the same cut length at every level.
    const double perLevel = length(cutsAt(t, levels[0]));
    for (double h : levels) EXPECT_NEAR(length(cutsAt(t, h)), perLevel, 1e-6);
    // The tool starts and ends at the clearance plane (no safe height given).
    EXPECT_EQ(t.moves.front().kind, Move::Kind::Rapid);
    EXPECT_DOUBLE_EQ(t.moves.front().h, 3 + p.clearance);
    EXPECT_DOUBLE_EQ(t.moves.back().h, 3 + p.clearance);
}

TEST(PocketClearing, IslandsAreNeverEntered) {
    const Loop contour = roundedRectangle(0, 0, 100, 70, 6);
    const std::vector<Loop> islands{circle({30, 35}, 9), roundedRectangle(60, 20, 80, 50, 3)};
    PocketUnit u{contour, islands, {}, 0, -12};
    const double R = 5, allowance = 0.4;
    const Toolpath t = pocketClearing(u, {2 * R, 0}, params(5, allowance));
    std::size_t segments = 0;
    forEachSegmentBelow(t, u.top, [&](const Point& a, const Point& b, Move::Kind) {
        ++segments;
        EXPECT_GE(loopSegmentDistance(contour, a, b), R + allowance - 0.011);
        for (const Loop& isl : islands) {
            EXPECT_FALSE(inside(isl, a));
            EXPECT_GE(loopSegmentDistance(isl, a, b), R + allowance - 0.011);
        }
    });
    EXPECT_GT(segments, 100u);
}

// The cutter sweeps everything it can reach: the pocket's opening by R (eroded, then dilated),
// at the allowance, less nothing. Checked on the floor level, for step-overs up to the diameter.
class PocketCoverage : public ::testing::TestWithParam<double> {};

TEST_P(PocketCoverage, FloorIsSweptWhereverTheCutterFits) {
    const Loop contour = roundedRectangle(0, 0, 90, 64, 3);  // corners tighter than the cutter
    const std::vector<Loop> islands{circle({30, 30}, 7), roundedRectangle(55, 18, 70, 46, 2)};
    PocketUnit u{contour, islands, {}, 0, -8};
    const double R = 6, allowance = 0.25;
    const Toolpath t = pocketClearing(u, {2 * R, 0}, params(GetParam() * 2 * R, allowance));
    const Raster r(-1, -1, 91, 65, 0.2);
    const auto want = opening(r, contour, islands, R, allowance);
    const auto cuts = cutsAt(t, -8);
    const auto got = swept(r, cuts, R + 0.02);
    EXPECT_EQ(uncovered(r, want, got), 0u);
    // The check can fail: without the moves that come within 10 mm of (80, 32), the floor
    // there is not swept.
    std::vector<std::pair<Point, Point>> part;
    for (const auto& sg : cuts)
        if (pointSegment({80, 32}, sg.first, sg.second) > 10) part.push_back(sg);
    EXPECT_GT(uncovered(r, want, swept(r, part, R + 0.02)), 1000u);
    // And nothing outside the opening (beyond the chord tolerance) is cut.
    std::size_t beyond = 0;
    const auto cut = swept(r, cuts, R - 0.02);
    const auto allowed = opening(r, contour, islands, R, allowance - r.px);  // sampling by pixels
    for (std::size_t k = 0; k < cut.size(); ++k) beyond += cut[k] && !allowed[k];
    EXPECT_EQ(beyond, 0u);
}

INSTANTIATE_TEST_SUITE_P(StepOvers, PocketCoverage, ::testing::Values(0.3, 0.5, 0.75, 1.0));

// Each level is entered once by a helix (in the widest place of the innermost rings); loops
// that no short link reaches are entered by a plunge onto a loop already cut at that level.
TEST(PocketClearing, ClosedPocketIsEnteredByAHelixThenPlungesOnlyWhereCleared) {
    const Loop contour = roundedRectangle(0, 0, 80, 80, 8);
    PocketUnit u{contour, {circle({40, 40}, 6)}, {}, 0, -20};
    PocketParameters p = params(8);
    p.rampAngleDeg = 4;
    const Toolpath t = pocketClearing(u, {16, 0}, p);
    const auto levels = cuttingLevels(0, -20, 4);
    // A descent is a run of feed moves with falling h; each must be a helix: points on one
    // circle, no steeper than the ramp angle, ending at a level.
    std::size_t helices = 0, plunges = 0;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        if (t.moves[i].kind == Move::Kind::Plunge) {
            // Onto a point that a feed move at that level has passed before.
            const Move& m = t.moves[i];
            bool cleared = false;
            for (std::size_t k = 1; k < i && !cleared; ++k)
                cleared = t.moves[k].kind == Move::Kind::Feed && t.moves[k].h == m.h && t.moves[k - 1].h == m.h &&
                          pointSegment({m.u, m.v}, {t.moves[k - 1].u, t.moves[k - 1].v}, {t.moves[k].u, t.moves[k].v}) < 1e-6;
            EXPECT_TRUE(cleared) << "plunge at " << m.u << ", " << m.v << ", " << m.h;
            ++plunges;
        }
        if (!(t.moves[i].kind == Move::Kind::Feed && t.moves[i].h < t.moves[i - 1].h - 1e-12)) continue;
        std::size_t j = i;
        while (j + 1 < t.moves.size() && t.moves[j + 1].kind == Move::Kind::Feed && t.moves[j + 1].h < t.moves[j].h - 1e-12)
            ++j;
        std::vector<Point> pts;
        for (std::size_t k = i - 1; k <= j; ++k) pts.push_back({t.moves[k].u, t.moves[k].v});
        // Circle through three of its points.
        const Point &a = pts[0], &b = pts[pts.size() / 3], &c = pts[2 * pts.size() / 3];
        const double d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
        ASSERT_GT(std::abs(d), 1e-9);
        const double a2 = a[0] * a[0] + a[1] * a[1], b2 = b[0] * b[0] + b[1] * b[1], c2 = c[0] * c[0] + c[1] * c[1];
        const Point o{(a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d,
                      (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d};
        const double radius = dist(o, a);
        EXPECT_NEAR(radius, 4, 1e-6);  // half the cutter radius
        for (const Point& q : pts) EXPECT_NEAR(dist(o, q), radius, 1e-6);
        for (std::size_t k = i; k <= j; ++k) {
            const Move& m0 = t.moves[k - 1];
            const Move& m1 = t.moves[k];
            const double run = std::hypot(m1.u - m0.u, m1.v - m0.v);
            EXPECT_LE(m0.h - m1.h, run * std::tan(4 * M_PI / 180) + 1e-9);
        }
        EXPECT_TRUE(std::find(levels.begin(), levels.end(), t.moves[j].h) != levels.end());
        ++helices;
        i = j;
    }
    EXPECT_EQ(helices, levels.size());
    EXPECT_LE(plunges, levels.size());
}

TEST(PocketClearing, OpenPocketPassesTheOpenEdge) {
    // Open along its top side (v = 40), which lies on the blank's edge.
    PocketUnit u{rectangle(0, 0, 60, 40), {}, {{{60, 40}, {0, 40}}}, 0, -10};
    const double R = 5, allowance = 0.5;
    PocketParameters p = params(5, allowance);
    const Toolpath t = pocketClearing(u, {2 * R, 0}, p);
    double highest = -1e9;
    forEachSegmentBelow(t, u.top, [&](const Point& a, const Point& b, Move::Kind) {
        highest = std::max({highest, a[1], b[1]});
        // Held back by the closed walls only.
        EXPECT_GE(std::min({a[0], b[0]}), R + allowance - 1e-6);
        EXPECT_LE(std::max({a[0], b[0]}), 60 - R - allowance + 1e-6);
        EXPECT_GE(std::min({a[1], b[1]}), R + allowance - 1e-6);
    });
    // The tool centre goes beyond the open edge far enough to clear it by the clearance.
    EXPECT_NEAR(highest, 40 + R + allowance + p.clearance, 1e-3);
    // And the whole material up to the open edge is swept, the open corners included.
    const Raster r(-1, -1, 61, 41, 0.1);
    const double ext = 2 * (R + allowance) + p.clearance;
    const auto reach = opening(r, rectangle(0, 0, 60, 40 + ext), {}, R, allowance);
    const auto got = swept(r, cutsAt(t, -10), R + 0.02);
    std::size_t missed = 0, openCorner = 0;
    for (int j = 0; j < r.nv; ++j)
        for (int i = 0; i < r.nu; ++i) {
            const Point q = r.centre(i, j);
            if (q[1] > 40 || !reach[r.at(i, j)]) continue;
            missed += !got[r.at(i, j)];
            openCorner += q[1] > 39 && q[0] > R + allowance - 0.2 && q[0] < R + allowance && got[r.at(i, j)];
        }
    EXPECT_EQ(missed, 0u);
    EXPECT_GT(openCorner, 0u);  // square at the open side, unlike at a closed corner
}

TEST(PocketClearing, NarrowOpenSlotIsEnteredFromOutside) {
    // 12 mm wide, open at v = 50: too narrow for a helix of a 10 mm cutter.
    PocketUnit u{rectangle(0, 0, 12, 50), {}, {{{0, 50}, {12, 50}}}, 0, -6};
    const Toolpath t = pocketClearing(u, {10, 0}, params(5));
    std::size_t plunges = 0;
    for (const Move& m : t.moves) {
        EXPECT_FALSE(m.kind == Move::Kind::Feed && m.h < 0 && m.h != -3 && m.h != -6) << "a ramp or helix";
        if (m.kind != Move::Kind::Plunge) continue;
        ++plunges;
        EXPECT_GE(m.v, 50 + 5 - 1e-6);  // the cutter clear of the material
    }
    EXPECT_EQ(plunges, 2u);  // one per level
}

TEST(PocketClearing, NarrowClosedSlotRampsAlongItsRing) {
    PocketUnit u{rectangle(0, 0, 11, 60), {}, {}, 0, -4};
    const Toolpath t = pocketClearing(u, {10, 0}, params(5));
    double descent = 0, run = 0;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Move &a = t.moves[i - 1], &b = t.moves[i];
        EXPECT_NE(b.kind, Move::Kind::Plunge);
        if (b.kind == Move::Kind::Feed && b.h < a.h) {
            descent += a.h - b.h, run += std::hypot(b.u - a.u, b.v - a.v);
            EXPECT_GE(b.u, 5 - 1e-6);
            EXPECT_LE(b.u, 6 + 1e-6);
        }
    }
    EXPECT_NEAR(descent, 4 + 1, 1e-9);  // from 1 mm above the top
    EXPECT_NEAR(descent / run, std::tan(3 * M_PI / 180), 1e-9);
}

TEST(PocketClearing, FinishingPassRunsAtTheFinalAllowance) {
    const Loop contour = rectangle(0, 0, 60, 50);
    PocketUnit u{contour, {circle({30, 25}, 8)}, {}, 0, -8};
    PocketParameters p = params(5, 0.5);
    p.finishingPass = true;
    p.finishingAllowance = 0.1;
    const Toolpath t = pocketClearing(u, {10, 0}, p);
    double nearest = 1e9;
    forEachSegmentBelow(t, 0, [&](const Point& a, const Point& b, Move::Kind) {
        nearest = std::min(nearest, loopSegmentDistance(contour, a, b));
    });
    EXPECT_NEAR(nearest, 5.1, 1e-4);
    PocketParameters rough = p;
    rough.finishingPass = false;
    EXPECT_GT(t.cutLength, pocketClearing(u, {10, 0}, rough).cutLength);
}

TEST(PocketClearing, CutAndRapidLengthsAddUp) {
    PocketUnit u{rectangle(0, 0, 40, 30), {}, {}, 0, -5};
    const Toolpath t = pocketClearing(u, {8, 0}, params(4));
    double cut = 0, rapid = 0;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Move &a = t.moves[i - 1], &b = t.moves[i];
        const double d = std::sqrt((b.u - a.u) * (b.u - a.u) + (b.v - a.v) * (b.v - a.v) + (b.h - a.h) * (b.h - a.h));
        (b.kind == Move::Kind::Rapid ? rapid : cut) += d;
    }
    EXPECT_NEAR(t.cutLength, cut, 1e-9);
    EXPECT_NEAR(t.rapidLength, rapid, 1e-9);
    EXPECT_GT(cut, 0);
}

TEST(PocketClearing, BadInputIsAClearError) {
    const PocketParameters p = params(5);
    const Cutter c{10, 0};
    auto pocket = [](Loop contour, double top = 0, double bottom = -5) { return PocketUnit{contour, {}, {}, top, bottom}; };
    auto err = [&](const PocketUnit& u, const Cutter& cut, const PocketParameters& q) {
        return inputErrorOf([&] { pocketClearing(u, cut, q); });
    };
    EXPECT_NE(err(pocket({}), c, p).find("at least 3"), std::string::npos);
    EXPECT_NE(err(pocket({{0, 0}, {10, 0}}), c, p).find("at least 3"), std::string::npos);
    EXPECT_NE(err(pocket({{0, 0}, {10, 0}, {20, 0}}), c, p).find("no area"), std::string::npos);
    EXPECT_NE(err(pocket({{0, 0}, {40, 40}, {40, 0}, {0, 40}}), c, p).find("crosses"), std::string::npos);
    EXPECT_NE(err(pocket({{0, 0}, {NAN, 0}, {40, 40}}), c, p).find("finite"), std::string::npos);
    EXPECT_NE(err(pocket({{0, 0}, {INFINITY, 0}, {40, 40}}), c, p).find("finite"), std::string::npos);
    EXPECT_NE(err(pocket(rectangle(0, 0, 9, 40)), c, p).find("does not fit"), std::string::npos);
    EXPECT_NE(err(pocket(rectangle(0, 0, 40, 40), -5, 0), c, p).find("below top"), std::string::npos);
    EXPECT_NE(err(pocket(rectangle(0, 0, 40, 40), NAN, 0), c, p).find("finite"), std::string::npos);
    EXPECT_NE(err(pocket(rectangle(0, 0, 40, 40)), {0, 0}, p).find("diameter"), std::string::npos);
    EXPECT_NE(err(pocket(rectangle(0, 0, 40, 40)), {NAN, 0}, p).find("diameter"), std::string::npos);
    EXPECT_NE(err(pocket(rectangle(0, 0, 40, 40)), {10, 6}, p).find("corner radius"), std::string::npos);
    for (double s : {0.0, -1.0, 10.5, double(NAN)})
        EXPECT_NE(err(pocket(rectangle(0, 0, 40, 40)), c, params(s)).find("stepOver"), std::string::npos) << s;
    PocketParameters q = p;
    q.stepDown = 0;
    EXPECT_NE(err(pocket(rectangle(0, 0, 40, 40)), c, q).find("stepDown"), std::string::npos);
    q = p, q.rampAngleDeg = 0;
    EXPECT_NE(err(pocket(rectangle(0, 0, 40, 40)), c, q).find("rampAngle"), std::string::npos);
    q = p, q.safeHeight = -1;
    EXPECT_NE(err(pocket(rectangle(0, 0, 40, 40)), c, q).find("safeHeight"), std::string::npos);
    q = p, q.finishingPass = true, q.finishingAllowance = 0.5;
    EXPECT_NE(err(pocket(rectangle(0, 0, 40, 40)), c, q).find("finishingAllowance"), std::string::npos);
    // A step-over so small the rings would never end is refused, not computed.
    EXPECT_NE(err(pocket(rectangle(0, 0, 4000, 4000)), c, params(1e-3)).find("rings"), std::string::npos);
    PocketUnit open = pocket(rectangle(0, 0, 40, 40));
    open.openEdges = {{{0, 50}, {40, 50}}};
    EXPECT_NE(err(open, c, p).find("open edge 1"), std::string::npos);
    PocketUnit island = pocket(rectangle(0, 0, 40, 40));
    island.islands = {{{5, 5}, {30, 30}, {30, 5}, {5, 30}}};
    EXPECT_NE(err(island, c, p).find("island 1"), std::string::npos);
    island.islands = {rectangle(-1, -1, 41, 41)};
    EXPECT_NE(err(island, c, p).find("islands cover"), std::string::npos);
}

// Material standing above the unit's top (stockTop): no rapid goes below it, the first level is
// entered from just above it at feed, the rapids between cuts clear it; the levels stay the unit's.
TEST(PocketClearing, StockTopIsClearedByEveryRapidAndEnteredAtFeed) {
    const Loop contour = roundedRectangle(0, 0, 100, 70, 6);
    const std::vector<Loop> islands{circle({30, 35}, 9)};
    PocketUnit u{contour, islands, {}, 0, -8};
    PocketParameters p = params(5);
    const Toolpath plain = pocketClearing(u, {10, 0}, p);
    p.stockTop = 6;
    const Toolpath t = pocketClearing(u, {10, 0}, p);
    double lowestRapid = 1e9, plainLowestRapid = 1e9, highestFeed = -1e9, lowest = 1e9;
    for (const Move& m : plain.moves)
        if (m.kind == Move::Kind::Rapid) plainLowestRapid = std::min(plainLowestRapid, m.h);
    // A rapid goes below stockTop + approach only down to just above a level this unit has cut.
    for (const Move& m : t.moves) {
        if (m.kind == Move::Kind::Rapid) {
            if (m.h < 6 + 1 - 1e-9) EXPECT_GE(m.h, lowest + 1 - 1e-9) << m.u << " " << m.v;
            lowestRapid = std::min(lowestRapid, m.h);
        } else {
            highestFeed = std::max(highestFeed, m.h), lowest = std::min(lowest, m.h);
        }
    }
    EXPECT_LT(plainLowestRapid, 6);  // without it the tool drops to the unit's top
    EXPECT_LT(lowestRapid, 6);       // the deeper levels are entered from the one above
    EXPECT_GT(highestFeed, 6);             // fed down through what may stand there
    EXPECT_DOUBLE_EQ(lowest, -8);
    EXPECT_DOUBLE_EQ(t.moves.back().h, 6 + p.clearance);
    // A safe height below stockTop + clearance is refused.
    p.safeHeight = 5;
    EXPECT_NE(inputErrorOf([&] { pocketClearing(u, {10, 0}, p); }).find("stockTop"), std::string::npos);
}

// An island stopping 5 mm under the top: above its top (plus the axial allowance) it is material
// to clear, a level at that height clears over and round it, and below it the island is kept.
TEST(PocketClearing, LowerIslandIsClearedDownToItsTopAndKeptBelow) {
    const Loop contour = roundedRectangle(0, 0, 100, 70, 6);
    const Loop low = circle({30, 35}, 9), high = roundedRectangle(60, 20, 80, 50, 3);
    PocketUnit u{contour, {low, high}, {}, 0, -12};
    u.islandTops = {-5, std::nan("")};
    const double R = 5, ra = 0.4, aa = 0.25;
    const Toolpath t = pocketClearing(u, {2 * R, 0}, params(5, ra, aa));
    const double face = -5 + aa;
    double lowestOver = 1e9;  // the lowest cutting height over the low island
    std::size_t below = 0;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Move& a = t.moves[i - 1];
        const Move& b = t.moves[i];
        if (b.kind == Move::Kind::Rapid) continue;
        if (inside(low, {b.u, b.v})) lowestOver = std::min(lowestOver, b.h);
        const double h = std::max(a.h, b.h);
        if (h >= u.top - 1e-9) continue;
        EXPECT_GE(loopSegmentDistance(high, {a.u, a.v}, {b.u, b.v}), R + ra - 0.011);
        EXPECT_GE(loopSegmentDistance(contour, {a.u, a.v}, {b.u, b.v}), R + ra - 0.011);
        if (h < face - 1e-9) {
            ++below;
            EXPECT_FALSE(inside(low, {a.u, a.v}));
            EXPECT_GE(loopSegmentDistance(low, {a.u, a.v}, {b.u, b.v}), R + ra - 0.011);
        }
    }
    EXPECT_GT(below, 100u);
    EXPECT_DOUBLE_EQ(lowestOver, face);
    // At the island's top level and the level above it, the whole island is swept.
    const Raster r(20, 25, 40, 45, 0.2);
    for (double h : {face, cuttingLevels(0, -12 + aa, 4).front()}) {
        SCOPED_TRACE(h);
        const auto got = swept(r, cutsAt(t, h), R);
        std::size_t missed = 0, in = 0;
        for (int j = 0; j < r.nv; ++j)
            for (int i = 0; i < r.nu; ++i)
                if (inside(low, r.centre(i, j))) ++in, missed += !got[r.at(i, j)];
        EXPECT_GT(in, 5000u);
        EXPECT_EQ(missed, 0u);
    }
    // Without the island's height it is kept at every level (the check can fail).
    PocketUnit kept = u;
    kept.islandTops.clear();
    const Toolpath k = pocketClearing(kept, {2 * R, 0}, params(5, ra, aa));
    for (const Move& m : k.moves)
        if (m.kind != Move::Kind::Rapid && m.h < u.top - 1e-9) EXPECT_FALSE(inside(low, {m.u, m.v}));
}

// A floor unit faces the lower island's top at its height, over the island and round its edge,
// keeping off the walls and the island that stands through; then the floor.
TEST(PocketClearing, FloorUnitFacesTheLowerIslandTops) {
    const Loop contour = roundedRectangle(0, 0, 100, 70, 6);
    const Loop low = circle({30, 35}, 9), high = roundedRectangle(60, 20, 80, 50, 3);
    PocketUnit u{contour, {low, high}, {}, -11.75, -12};
    u.islandTops = {-5, std::nan("")};
    u.faceIslandTops = true;
    const double R = 8, ra = 0.2;
    PocketParameters p = params(6, ra, 0);
    const Toolpath t = pocketClearing(u, {2 * R, 2}, p);
    std::set<double> flat;
    for (std::size_t i = 1; i < t.moves.size(); ++i)
        if (t.moves[i].kind == Move::Kind::Feed && t.moves[i].h == t.moves[i - 1].h) flat.insert(t.moves[i].h);
    EXPECT_EQ(flat, (std::set<double>{-12, -5}));
    const auto top = cutsAt(t, -5);
    for (const auto& [a, b] : top) {
        EXPECT_GE(loopSegmentDistance(high, a, b), R + ra - 0.011);
        EXPECT_GE(loopSegmentDistance(contour, a, b), R + ra - 0.011);
        // Round the island only: the rest of the floor is no business of this level.
        EXPECT_LE(loopSegmentDistance(low, a, b), 2 * R + ra);
    }
    // The flat of the bull cutter (radius 6) sweeps the whole top.
    const Raster r(20, 25, 40, 45, 0.2);
    const auto got = swept(r, top, R - 2);
    std::size_t missed = 0;
    for (int j = 0; j < r.nv; ++j)
        for (int i = 0; i < r.nu; ++i) missed += inside(low, r.centre(i, j)) && !got[r.at(i, j)];
    EXPECT_EQ(missed, 0u);
    // The 0.25 mm left on the top is entered at feed: no rapid goes lower with the cutter over it.
    for (const Move& m : t.moves)
        if (m.kind == Move::Kind::Rapid && loopDistance(low, {m.u, m.v}) < R) EXPECT_GE(m.h, -5 + 0.25 - 1e-9);
    // A plain floor unit cuts the floor only.
    u.faceIslandTops = false;
    std::set<double> plain;
    const Toolpath f = pocketClearing(u, {2 * R, 2}, p);
    for (std::size_t i = 1; i < f.moves.size(); ++i)
        if (f.moves[i].kind == Move::Kind::Feed && f.moves[i].h == f.moves[i - 1].h) plain.insert(f.moves[i].h);
    EXPECT_EQ(plain, (std::set<double>{-12}));
}

// A slot 3 x 22 mm open to the blank on three sides (FTC-09's flanges): only the wall at v = 22
// holds material. The D32 with its 1 mm allowance is far wider than the slot, but open on two
// adjacent sides it passes round the corners beyond them: it cuts the slot up to R + allowance
// from the wall, and no cutting position comes nearer the wall than that.
TEST(PocketClearing, PocketOpenOnThreeSidesIsClearedByACutterWiderThanIt) {
    PocketUnit u{rectangle(0, 0, 3, 22), {}, {}, 0, -6};
    u.openEdges = {{{0, 0}, {3, 0}}, {{3, 0}, {3, 22}}, {{0, 22}, {0, 0}}};
    const Cutter c{32, 4};
    const double keep = 16 + 1;
    const Toolpath t = pocketClearing(u, c, params(16, 1.0, 0.5));
    int overSlot = 0;
    for (const Move& m : t.moves)
        if (m.kind != Move::Kind::Rapid && m.h < u.top) EXPECT_LE(m.v, 22 - keep + 1e-3) << m.u << " " << m.v;
    // A cut at the floor along the line the wall allows, across the slot's width.
    forEachSegmentBelow(t, u.top, [&](const Point& a, const Point& b, Move::Kind k) {
        overSlot += k == Move::Kind::Feed && std::min(a[1], b[1]) >= 22 - keep - 0.5 &&
                    std::min(a[0], b[0]) - 16 <= 0 && std::max(a[0], b[0]) + 16 >= 3;
    });
    EXPECT_GT(overSlot, 0);
}
