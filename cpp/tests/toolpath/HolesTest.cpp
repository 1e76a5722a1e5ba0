// Helical hole milling and drilling against their known geometry: the helix and finishing
// radii, the pitch, the floor, the drilling cycles' heights.
#include "ErrorOf.h"
#include "Checks.h"

#include <aeronc/toolpath/Drilling.h>
#include <aeronc/toolpath/HelicalHole.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <vector>

using namespace aeronc::toolpath;
using namespace aeronc::toolpath::test;
using aeronc::test::inputErrorOf;

namespace {
// Signed angle swept from a to b round c, in (-pi, pi].
double turn(const Point& c, const Point& a, const Point& b) {
    return std::atan2((a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]),
                      (a[0] - c[0]) * (b[0] - c[0]) + (a[1] - c[1]) * (b[1] - c[1]));
}
}  // namespace

TEST(HelicalHole, HelixAndFinishingCircleHaveTheirRadii) {
    const Point c{30, -12};
    HelicalHoleParameters p;
    p.radialAllowance = 0.3;
    p.stepDown = 2;
    p.rampAngleDeg = 5;
    const Toolpath t = helicalHole({{c, 20, 5, -10, false}}, {12, 0}, p);
    const double rough = 10 - 6 - 0.3, finish = 10 - 6;
    std::size_t onRough = 0, onFinish = 0;
    double lowest = 1e9, turned = 0, pitchWorst = 0;
    double lastH = 1e9, turnAtLastH = 0;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Move &a = t.moves[i - 1], &b = t.moves[i];
        if (b.kind == Move::Kind::Rapid) continue;
        const double r = dist({b.u, b.v}, c);
        lowest = std::min(lowest, b.h);
        // Everything cut lies on one of the two circles, or on the way in or out.
        if (std::abs(r - rough) < 1e-9) ++onRough;
        else if (std::abs(r - finish) < 1e-9) ++onFinish;
        else EXPECT_TRUE(r < rough + 1e-9) << r;
        if (std::abs(r - rough) < 1e-9 && std::abs(dist({a.u, a.v}, c) - rough) < 1e-9) {
            turned += turn(c, {a.u, a.v}, {b.u, b.v});
            if (b.h < lastH - 1e-12) {  // descending: the fall per turn is the pitch
                pitchWorst = std::max(pitchWorst, (a.h - b.h) / std::abs(turn(c, {a.u, a.v}, {b.u, b.v})) * 2 * M_PI);
                lastH = b.h, turnAtLastH = turned;
            }
        }
    }
    EXPECT_GT(onRough, 100u);
    EXPECT_GT(onFinish, 40u);
    EXPECT_EQ(lowest, -10);  // blind: the floor exactly
    EXPECT_LE(pitchWorst, 2 + 1e-9);
    EXPECT_LT(turned, 0);  // climb: clockwise
    // A full turn flat at the floor after the last descent.
    EXPECT_LE(turned - turnAtLastH, -2 * M_PI + 1e-6);
    EXPECT_EQ(t.moves.back().kind, Move::Kind::Rapid);
    EXPECT_DOUBLE_EQ(t.moves.back().h, 5 + p.clearance);
}

TEST(HelicalHole, ThroughHoleBreaksThroughBeyondTheCornerRadius) {
    HelicalHoleParameters p;
    p.breakThrough = 0.7;
    const Toolpath t = helicalHole({{{0, 0}, 25, 0, -15, true}, {{60, 0}, 25, 0, -15, true}}, {16, 1.5}, p);
    double lowest = 1e9;
    for (const Move& m : t.moves) lowest = std::min(lowest, m.h);
    EXPECT_DOUBLE_EQ(lowest, -15 - 0.7 - 1.5);
    // Between the holes the tool rises to the clearance plane.
    bool crossed = false;
    for (std::size_t i = 1; i < t.moves.size(); ++i)
        if (t.moves[i - 1].u < 30 && t.moves[i].u > 30) {
            crossed = true;
            EXPECT_EQ(t.moves[i].kind, Move::Kind::Rapid);
            EXPECT_DOUBLE_EQ(t.moves[i].h, p.clearance);
        }
    EXPECT_TRUE(crossed);
}

// A blind counterbore (21.8 mm, R2 fillet between wall and floor; milled_002's four) milled
// with a flat 16 mm end mill: going round at the full radius down to the floor the cutter
// took the fillet away (0.46 mm by the verification). Near the floor it is drawn in as the
// fillet rises: no position, at any height, reaches past the fillet's surface there.
TEST(HelicalHole, BlindHoleKeepsOutOfItsFloorFillet) {
    const Point c{5, 7};
    Hole h{c, 21.8, 20, 6, false};
    h.floorFilletRadius = 2;
    HelicalHoleParameters p;
    p.stepDown = 1;
    const Toolpath t = helicalHole({h}, {16, 0}, p);
    const double R = 8, rf = 2, wall = 21.8 / 2;
    double worst = -1e9, lowest = 1e9, reach = 0;
    for (const Move& m : t.moves) {
        if (m.kind == Move::Kind::Rapid) continue;
        const double above = m.h - h.bottom, rho = dist({m.u, m.v}, c) + R;
        lowest = std::min(lowest, m.h);
        // The part's surface at the cutter's bottom: the fillet's arc below rf, the wall above.
        const double surface = above >= rf ? wall : wall - rf + std::sqrt(rf * rf - (rf - above) * (rf - above));
        worst = std::max(worst, rho - surface);
        if (above > rf) reach = std::max(reach, rho);
    }
    EXPECT_DOUBLE_EQ(lowest, 6);
    EXPECT_LE(worst, 1e-9);
    EXPECT_NEAR(reach, wall, 1e-9);  // above the fillet the wall is cut to size
    // Through holes have no floor: the fillet does not apply.
    h.through = true;
    const Toolpath through = helicalHole({h}, {16, 0}, p);
    double widest = 0;
    for (const Move& m : through.moves)
        if (m.kind != Move::Kind::Rapid && m.h < h.bottom) widest = std::max(widest, dist({m.u, m.v}, c) + R);
    EXPECT_NEAR(widest, wall, 1e-9);
}

namespace {
// Distance from q to the segment ab in the plane.
double segmentDistance(const Point& q, const Point& a, const Point& b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
    return dist(q, {a[0] + t * dx, a[1] + t * dy});
}

// The feed segments that run flat at height h.
std::vector<std::pair<Point, Point>> flatAt(const Toolpath& t, double h) {
    std::vector<std::pair<Point, Point>> out;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Move &a = t.moves[i - 1], &b = t.moves[i];
        if (b.kind != Move::Kind::Rapid && std::abs(a.h - h) < 1e-9 && std::abs(b.h - h) < 1e-9)
            out.push_back({{a.u, a.v}, {b.u, b.v}});
    }
    return out;
}
}  // namespace

// A 60 mm blind hole with a 12 mm end mill (a fifth of it): one helix at the wall would leave a
// 36 mm core. Level by level the cutter clears the whole disc, never past the roughing radius,
// never descending faster than the step-down; of a through hole the axis is cut at the last
// level before the outer ring, so no slug is left to drop.
TEST(HelicalHole, WideHoleIsClearedInRingsLeavingNoCore) {
    const Point c{-4, 9};
    HelicalHoleParameters p;
    p.radialAllowance = 0.4;
    p.stepDown = 3;
    p.stepOver = 5;
    const double R = 6, wall = 30, rough = wall - R - p.radialAllowance;
    const Toolpath t = helicalHole({{c, 60, 0, -10, false}}, {12, 0}, p);
    double widest = 0, lowest = 1e9, worstFall = 0;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Move &a = t.moves[i - 1], &b = t.moves[i];
        if (b.kind == Move::Kind::Rapid) continue;
        widest = std::max(widest, dist({b.u, b.v}, c));
        lowest = std::min(lowest, b.h);
        const double run = dist({a.u, a.v}, {b.u, b.v});
        if (a.h > b.h && b.h < 0) worstFall = std::max(worstFall, (a.h - b.h) / std::max(run, 1e-12));
    }
    EXPECT_LE(widest, wall - R - p.finishingAllowance + 1e-9);
    EXPECT_EQ(lowest, -10);
    EXPECT_LE(worstFall, std::tan(p.rampAngleDeg * M_PI / 180) * 1.01);  // helical ramps, no plunge
    // Every point of the disc the roughing leaves open is under the cutter at the floor and at
    // each level above it (levels at most the step-down apart).
    std::set<double, std::greater<double>> levels;  // top down
    for (std::size_t i = 1; i < t.moves.size(); ++i)
        if (t.moves[i].kind != Move::Kind::Rapid && t.moves[i].h < 0 && t.moves[i].h == t.moves[i - 1].h)
            levels.insert(t.moves[i].h);
    ASSERT_GE(levels.size(), 4u);  // 11 mm from the entry down, at most 3 mm a level
    double above = 1;               // the helix starts 1 mm over the top
    for (double level : levels) {
        EXPECT_LE(above - level, p.stepDown + 1e-9);
        above = level;
    }
    for (double level : levels) {
        SCOPED_TRACE(level);
        const auto flat = flatAt(t, level);
        ASSERT_FALSE(flat.empty());
        double worstGap = 0;
        for (double r = 0; r <= rough + R - 0.05; r += 0.5)
            for (double q = 0; q < 2 * M_PI; q += 0.1) {
                const Point x{c[0] + r * std::cos(q), c[1] + r * std::sin(q)};
                double nearest = 1e9;
                for (const auto& [a, b] : flat) nearest = std::min(nearest, segmentDistance(x, a, b));
                worstGap = std::max(worstGap, nearest - R);
            }
        EXPECT_LE(worstGap, 1e-6);
    }
    // Through: at the last level the axis is cut before the outer ring.
    const Toolpath through = helicalHole({{c, 60, 0, -10, true}}, {12, 0}, p);
    double bottom = 1e9;
    for (const Move& m : through.moves) bottom = std::min(bottom, m.h);
    std::size_t firstAxis = 0, firstOuter = 0;
    for (std::size_t i = 0; i < through.moves.size(); ++i) {
        const Move& m = through.moves[i];
        if (std::abs(m.h - bottom) > 1e-9 || m.kind == Move::Kind::Rapid) continue;
        const double r = dist({m.u, m.v}, c);
        if (!firstAxis && r < R) firstAxis = i;
        if (!firstOuter && r > rough - 1e-6) firstOuter = i;
    }
    ASSERT_GT(firstAxis, 0u);
    ASSERT_GT(firstOuter, 0u);
    EXPECT_LT(firstAxis, firstOuter);
}

TEST(HelicalHole, BadInputIsAClearError) {
    const HelicalHoleParameters p;
    EXPECT_NE(inputErrorOf([&] { helicalHole({{{0, 0}, 12, 0, -5, false}}, {12, 0}, p); }).find("not larger"),
              std::string::npos);
    EXPECT_NE(inputErrorOf([&] { helicalHole({}, {12, 0}, p); }).find("no holes"), std::string::npos);
    EXPECT_NE(inputErrorOf([&] { helicalHole({{{0, 0}, 20, -5, 0, false}}, {12, 0}, p); }).find("below"),
              std::string::npos);
    EXPECT_NE(inputErrorOf([&] { helicalHole({{{NAN, 0}, 20, 0, -5, false}}, {12, 0}, p); }).find("finite"),
              std::string::npos);
    HelicalHoleParameters q;
    q.stepDown = 0;
    EXPECT_NE(inputErrorOf([&] { helicalHole({{{0, 0}, 20, 0, -5, false}}, {12, 0}, q); }).find("stepDown"),
              std::string::npos);
}

TEST(Drilling, TipLengthOfA118DegreePointIsAboutAThirdOfTheDiameter) {
    EXPECT_NEAR(drillTipLength(10, 118), 0.3 * 10, 0.01);
    EXPECT_NEAR(drillTipLength(10, 90), 5, 1e-12);
}

TEST(Drilling, OneCyclePerHoleWithItsHeights) {
    DrillParameters p;
    p.peck = 2.5;
    p.dwell = 0.4;
    p.clearance = 3;
    p.breakThrough = 0.5;
    const std::vector<Hole> holes{{{0, 0}, 6.6, 0, -12, true}, {{25, 10}, 6.6, -4, -9, false}, {{50, 0}, 6.6, 0, -3, false}};
    const Toolpath t = drilling(holes, {6.6, 0}, p);
    std::vector<Move> cycles;
    for (const Move& m : t.moves)
        if (m.kind == Move::Kind::Drill) cycles.push_back(m);
    ASSERT_EQ(cycles.size(), 3u);
    EXPECT_NEAR(cycles[0].h, -12 - 6.6 * 0.3 - 0.5, 0.01);
    EXPECT_DOUBLE_EQ(cycles[0].h, -12 - drillTipLength(6.6, 118) - 0.5);
    EXPECT_DOUBLE_EQ(cycles[1].h, -9);  // blind: no tip added
    EXPECT_DOUBLE_EQ(cycles[0].r, 3);   // each hole's top + clearance
    EXPECT_DOUBLE_EQ(cycles[1].r, -1);
    double cut = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_DOUBLE_EQ(cycles[i].u, holes[i].centre[0]);
        EXPECT_DOUBLE_EQ(cycles[i].v, holes[i].centre[1]);
        EXPECT_DOUBLE_EQ(cycles[i].q, 2.5);
        EXPECT_DOUBLE_EQ(cycles[i].dwell, 0.4);
        cut += cycles[i].r - cycles[i].h;
    }
    EXPECT_NEAR(t.cutLength, cut, 1e-9);
    // Between holes: rapids at the plane above the highest top.
    for (std::size_t i = 1; i < t.moves.size(); ++i)
        if (t.moves[i].kind == Move::Kind::Rapid && t.moves[i].u != t.moves[i - 1].u) EXPECT_DOUBLE_EQ(t.moves[i].h, 3);
}

TEST(Drilling, RetractHeightIsTheRPlane) {
    DrillParameters p;
    p.retractHeight = 1;
    const Toolpath t = drilling({{{0, 0}, 5, 0, -8, false}}, {5, 0}, p);
    std::size_t n = 0;
    for (const Move& m : t.moves)
        if (m.kind == Move::Kind::Drill) {
            EXPECT_DOUBLE_EQ(m.r, 1);
            ++n;
        }
    EXPECT_EQ(n, 1u);
}

TEST(Drilling, BadInputIsAClearError) {
    auto err = [](std::vector<Hole> h, DrillParameters p, Cutter c = {5, 0}) {
        return inputErrorOf([&] { drilling(h, c, p); });
    };
    const std::vector<Hole> one{{{0, 0}, 5, 0, -8, false}};
    EXPECT_NE(err({}, {}).find("no holes"), std::string::npos);
    EXPECT_NE(err({{{0, 0}, 5, -8, 0, false}}, {}).find("below top"), std::string::npos);
    EXPECT_NE(err({{{0, INFINITY}, 5, 0, -8, false}}, {}).find("finite"), std::string::npos);
    EXPECT_NE(err(one, {}, {0, 0}).find("diameter"), std::string::npos);
    DrillParameters p;
    p.peck = -1;
    EXPECT_NE(err(one, p).find("peck"), std::string::npos);
    p = {}, p.peck = 1e-6;
    EXPECT_NE(err(one, p).find("pecks"), std::string::npos);
    p = {}, p.retractHeight = -1;
    EXPECT_NE(err(one, p).find("retractHeight"), std::string::npos);
    p = {}, p.dwell = NAN;
    EXPECT_NE(err(one, p).find("dwell"), std::string::npos);
}

// An uncut counterbore above the hole (stockTop): the R plane clears it.
TEST(Drilling, StockTopRaisesTheRPlane) {
    DrillParameters p;
    p.clearance = 3;
    p.stockTop = 6;
    const Toolpath t = drilling({{{0, 0}, 6.6, 0, -12, true}, {{20, 0}, 6.6, 8, -12, true}}, {6.6, 0}, p);
    std::vector<double> r;
    double lowestRapid = 1e9;
    for (const Move& m : t.moves) {
        if (m.kind == Move::Kind::Drill) r.push_back(m.r);
        if (m.kind == Move::Kind::Rapid) lowestRapid = std::min(lowestRapid, m.h);
    }
    ASSERT_EQ(r.size(), 2u);
    EXPECT_DOUBLE_EQ(r[0], 9);   // stockTop + clearance, not the hole's top + clearance (3)
    EXPECT_DOUBLE_EQ(r[1], 11);  // a hole whose top is higher keeps it
    EXPECT_GE(lowestRapid, 11 - 1e-9);
}
