// Profiles: the cutter at R + allowance from the drive on the chosen side, in the climb
// direction, with leads that stay off the material, at every level.
#include "ErrorOf.h"
#include "Checks.h"

#include <aeronc/toolpath/FloorFillet.h>
#include <aeronc/toolpath/Levels.h>
#include <aeronc/toolpath/Profile.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

using namespace aeronc::toolpath;
using namespace aeronc::toolpath::test;
using aeronc::test::inputErrorOf;

namespace {

// The feed moves at height h as one polyline per visit (broken at rapids and plunges).
std::vector<std::vector<Point>> passesAt(const Toolpath& t, double h) {
    std::vector<std::vector<Point>> out;
    for (std::size_t i = 0; i < t.moves.size(); ++i) {
        const Move& m = t.moves[i];
        if (m.h != h || m.kind == Move::Kind::Rapid) continue;
        if (m.kind == Move::Kind::Plunge || out.empty() || t.moves[i - 1].h != h) out.push_back({});
        out.back().push_back({m.u, m.v});
    }
    return out;
}

double signedArea(const std::vector<Point>& l) {
    double a = 0;
    for (std::size_t i = 0; i + 1 < l.size(); ++i) a += l[i][0] * l[i + 1][1] - l[i + 1][0] * l[i][1];
    return a / 2;
}

}  // namespace

TEST(Profile, OutsideOfAClosedLoopIsCutCounterClockwiseAtTheOffset) {
    const Loop drive = rectangle(0, 0, 60, 40);
    ProfileParameters p;
    p.radialAllowance = 0.2;
    p.stepDown = 5;
    const Toolpath t = profile({drive, true, {}, {}, 0, -12}, {10, 0}, p);
    const auto levels = cuttingLevels(0, -12, 5);
    for (double h : levels) {
        const auto passes = passesAt(t, h);
        ASSERT_EQ(passes.size(), 1u) << h;
        const auto& pass = passes[0];
        double nearest = 1e9, farthest = 0;
        for (const Point& q : pass) {
            EXPECT_FALSE(inside(drive, q));
            nearest = std::min(nearest, loopDistance(drive, q));
            farthest = std::max(farthest, loopDistance(drive, q));
        }
        EXPECT_NEAR(nearest, 5.2, 1e-4);
        EXPECT_GT(farthest, 5.2 + 1);      // the leads go off the wall
        EXPECT_GT(signedArea(pass), 0);    // climb outside: counter-clockwise
        // Round the whole loop: the path passes every corner at the offset.
        for (const Point& corner : drive) {
            double d = 1e9;
            for (const Point& q : pass) d = std::min(d, dist(q, corner));
            EXPECT_NEAR(d, 5.2, 0.02);
        }
    }
}

TEST(Profile, InsideOfAClosedLoopIsCutClockwise) {
    const Loop drive = roundedRectangle(0, 0, 50, 30, 6);
    ProfileParameters p;
    p.side = ToolSide::Inside;
    p.lead = Lead::Line;
    const Toolpath t = profile({drive, true, {}, {}, 0, -4}, {10, 0}, p);
    const auto passes = passesAt(t, -4);
    ASSERT_EQ(passes.size(), 1u);
    double nearest = 1e9;
    for (std::size_t i = 1; i < passes[0].size(); ++i) {
        EXPECT_TRUE(inside(drive, passes[0][i]));
        nearest = std::min(nearest, loopSegmentDistance(drive, passes[0][i - 1], passes[0][i]));
    }
    EXPECT_NEAR(nearest, 5, 0.011);
    EXPECT_LT(signedArea(passes[0]), 0);
}

TEST(Profile, ClockwiseDriveGetsItsLeadsToo) {
    Loop drive = roundedRectangle(0, 0, 50, 30, 6);
    std::reverse(drive.begin(), drive.end());
    ProfileParameters p;
    p.side = ToolSide::Inside;
    const Toolpath t = profile({drive, true, {}, {}, 0, -2}, {10, 0}, p);
    const auto passes = passesAt(t, -2);
    ASSERT_EQ(passes.size(), 1u);
    double farthest = 0;
    for (const Point& q : passes[0]) {
        EXPECT_TRUE(inside(drive, q));
        EXPECT_GE(loopDistance(drive, q), 5 - 0.011);
        farthest = std::max(farthest, loopDistance(drive, q));
    }
    EXPECT_GT(farthest, 5 + 2);  // the arcs lead in from and out to the middle
    EXPECT_LT(signedArea(passes[0]), 0);
}

TEST(Profile, LeftAndRightOfAClosedLoopFollowItsOrientation) {
    const Loop ccw = rectangle(0, 0, 30, 30);
    ProfileParameters p;
    p.side = ToolSide::Left;  // inside a counter-clockwise loop
    const Toolpath t = profile({ccw, true, {}, {}, 0, -1}, {6, 0}, p);
    for (const auto& pass : passesAt(t, -1))
        for (const Point& q : pass) EXPECT_TRUE(inside(ccw, q));
}

TEST(Profile, OpenPolylineIsFollowedOnItsSideWithinTheLimits) {
    // A wall along v = 0 from u = 0 to 100 with a bend; the material to remove above it.
    const Loop drive{{0, 0}, {60, 0}, {100, 20}};
    ProfileParameters p;
    p.side = ToolSide::Left;
    const Toolpath t = profile({drive, false, Point{10, -3}, Point{80, 5}, 0, -3}, {8, 0}, p);
    const auto passes = passesAt(t, -3);
    ASSERT_EQ(passes.size(), 1u);
    const auto& pass = passes[0];
    // Climb with the cutter on the left of the drive: travel against the drive's direction.
    EXPECT_GT(pass.front()[0], pass.back()[0]);
    for (const Point& q : pass) {
        double d = 1e9;
        for (std::size_t i = 0; i + 1 < drive.size(); ++i) d = std::min(d, pointSegment(q, drive[i], drive[i + 1]));
        EXPECT_GE(d, 4 - 0.1);
    }
    // The offset path itself (leads aside) runs from above the end limit to above the start limit.
    double minU = 1e9, maxU = -1e9;
    for (const Point& q : pass)
        if (q[1] > 3.9) minU = std::min(minU, q[0]), maxU = std::max(maxU, q[0]);
    EXPECT_LT(minU, 10 + 1e-6);
    EXPECT_GT(maxU, 60);
}

TEST(Profile, BadInputIsAClearError) {
    auto err = [&](ProfileUnit u, ProfileParameters q = {}) { return inputErrorOf([&] { profile(u, {10, 0}, q); }); };
    ProfileParameters left;
    left.side = ToolSide::Left;
    EXPECT_NE(err({{{0, 0}}, false, {}, {}, 0, -5}, left).find("2 distinct"), std::string::npos);
    EXPECT_NE(err({{{0, 0}, {10, 0}, {10, 10}, {5, -5}}, false, {}, {}, 0, -5}, left).find("crosses"), std::string::npos);
    EXPECT_NE(err({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}, true, {}, {}, 0, -5}).find("crosses"), std::string::npos);
    EXPECT_NE(err({rectangle(0, 0, 8, 8), true, {}, {}, 0, -5}, [] {
                  ProfileParameters q;
                  q.side = ToolSide::Inside;
                  return q;
              }()).find("does not fit"),
              std::string::npos);
    EXPECT_NE(err({{{0, 0}, {10, 0}}, false, {}, {}, 0, -5}).find("left or right"), std::string::npos);
    EXPECT_NE(err({{{0, 0}, {10, 0}}, false, Point{8, 0}, Point{2, 0}, 0, -5}, [] {
                  ProfileParameters q;
                  q.side = ToolSide::Right;
                  return q;
              }()).find("before the end limit"),
              std::string::npos);
    EXPECT_NE(err({rectangle(0, 0, 40, 40), true, {}, {}, -5, 0}).find("below top"), std::string::npos);
    ProfileParameters q;
    q.leadRadius = -1;
    EXPECT_NE(err({rectangle(0, 0, 40, 40), true, {}, {}, 0, -5}, q).find("leadRadius"), std::string::npos);
}

// Round a 20 mm square island with a 3 mm floor fillet, a flat 8 mm end mill, levels every 1 mm
// from 6 down to 0: the floor level runs 3 mm further out (the fillet's width), the levels
// above the fillet at the radius, the ones between by wallFilletOffset.
TEST(Profile, FloorFilletHoldsTheLowLevelsOffTheWall) {
    ProfileUnit u;
    u.drive = {{0, 0}, {20, 0}, {20, 20}, {0, 20}};
    u.top = 6, u.bottom = 0;
    u.floorFilletRadius = 3;
    ProfileParameters p;
    p.side = ToolSide::Outside;
    p.lead = Lead::None;
    p.stepDown = 1;
    const Toolpath t = profile(u, {8, 0}, p);
    std::map<double, double> nearest;  // level -> least distance of its cutting moves from the square
    for (const Move& m : t.moves) {
        if (m.kind != Move::Kind::Feed) continue;
        const double dx = std::max({0.0 - m.u, 0.0, m.u - 20}), dy = std::max({0.0 - m.v, 0.0, m.v - 20});
        const double d = std::hypot(dx, dy);
        auto it = nearest.find(m.h);
        if (it == nearest.end() || d < it->second) nearest[m.h] = d;
    }
    ASSERT_EQ(nearest.size(), 6u);
    for (const auto& [h, d] : nearest) {
        const double want = 4 + wallFilletOffset(3, 0, 0, h);
        EXPECT_NEAR(d, want, 0.006) << "level " << h;
    }
    EXPECT_NEAR(nearest.at(0), 7, 0.006);
    EXPECT_NEAR(nearest.at(5), 4, 0.006);
    // The four fillets meet in mitres at the square's corners: round a corner the cutter keeps
    // its distance from both walls' lines (out to the mitre point), not only from the corner's
    // edge, where it would cut the mitre.
    for (const Move& m : t.moves) {
        if (m.kind != Move::Kind::Feed) continue;
        const double fromLines = std::max({0.0 - m.u, m.u - 20, 0.0 - m.v, m.v - 20});
        EXPECT_GE(fromLines, 4 + wallFilletOffset(3, 0, 0, m.h) - 0.006) << m.u << " " << m.v << " level " << m.h;
    }
}

// Across a slot 6.38 mm wide a D4 cutter's quarter-arc lead of radius R, started R in from its
// path at 0.2 mm allowance, would come 0.02 mm into the far wall's allowance: the leads shrink
// to fit, and no move, leads included, comes nearer any wall than R + allowance (less the
// chord tolerance).
TEST(Profile, LeadsKeepTheAllowanceAcrossANarrowSlot) {
    const Loop drive = roundedRectangle(0, 0, 40, 6.38, 3.19);
    ProfileParameters p;
    p.side = ToolSide::Inside;
    p.radialAllowance = 0.2;
    p.stepDown = 2;
    const Toolpath t = profile({drive, true, {}, {}, 0, -3}, {4, 2}, p);
    std::size_t leadMoves = 0;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Move& a = t.moves[i - 1];
        const Move& b = t.moves[i];
        if (b.kind == Move::Kind::Rapid || std::max(a.h, b.h) >= 0) continue;
        const double d = loopSegmentDistance(drive, {a.u, a.v}, {b.u, b.v});
        EXPECT_GE(d, 2.2 - p.chordTolerance - 1e-9) << "move " << i;
        leadMoves += d > 2.2 + 0.05;  // off the offset path: a lead
    }
    EXPECT_GT(leadMoves, 0u);
}

// Two bosses 20 mm in front of the long walls' middles: a D16 cutter's quarter-arc lead of
// radius R would come 3.8 mm from one; told of them (clearOf), the leads keep R + allowance from
// them too (the path itself passes 11.8 mm off).
TEST(Profile, LeadsKeepClearOfTheElementsOtherWalls) {
    const Loop drive = rectangle(0, 0, 100, 60);
    const std::vector<Loop> bosses{rectangle(40, 20, 60, 26), rectangle(40, 34, 60, 40)};
    ProfileParameters p;
    p.side = ToolSide::Inside;
    p.radialAllowance = 0.2;
    p.stepDown = 5;
    ProfileUnit u{drive, true, {}, {}, 0, -5};
    auto nearest = [&](const Toolpath& t) {
        double d = 1e9;
        for (std::size_t i = 1; i < t.moves.size(); ++i) {
            const Move& a = t.moves[i - 1];
            const Move& b = t.moves[i];
            if (b.kind == Move::Kind::Rapid || std::max(a.h, b.h) >= 0) continue;
            for (const Loop& boss : bosses) d = std::min(d, loopSegmentDistance(boss, {a.u, a.v}, {b.u, b.v}));
        }
        return d;
    };
    // Alone the lead comes near a boss (the check can fail) ...
    EXPECT_LT(nearest(profile(u, {16, 0}, p)), 8.2 - 0.01);
    // ... told of the bosses, never nearer than R + allowance.
    for (const Loop& b : bosses) {
        std::vector<Point> closed(b.begin(), b.end());
        closed.push_back(b.front());
        u.clearOf.push_back(closed);
    }
    EXPECT_GE(nearest(profile(u, {16, 0}, p)), 8.2 - p.chordTolerance - 1e-9);
}

// A boss 10 mm from the wall leaves a D16 cutter no room there: told of it, the pass breaks off
// on both sides of it, never nearer the boss than R + allowance, and runs on elsewhere.
TEST(Profile, PassBreaksOffWhereAnotherWallLeavesNoRoom) {
    const Loop drive = rectangle(0, 0, 100, 60);
    const Loop boss = rectangle(40, 10, 60, 20);
    ProfileParameters p;
    p.side = ToolSide::Inside;
    p.radialAllowance = 0.2;
    p.stepDown = 5;
    ProfileUnit u{drive, true, {}, {}, 0, -5};
    u.clearOf = {{{40, 10}, {60, 10}, {60, 20}, {40, 20}, {40, 10}}};
    const Toolpath t = profile(u, {16, 0}, p);
    double nearest = 1e9, length = 0;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Move& a = t.moves[i - 1];
        const Move& b = t.moves[i];
        if (b.kind == Move::Kind::Rapid || std::max(a.h, b.h) >= 0) continue;
        nearest = std::min(nearest, loopSegmentDistance(boss, {a.u, a.v}, {b.u, b.v}));
        length += dist({a.u, a.v}, {b.u, b.v});
    }
    EXPECT_GE(nearest, 8.2 - p.chordTolerance - 1e-9);
    // Most of the 2 (83.6 + 43.6) mm round is still cut.
    EXPECT_GT(length, 200);
    // Without it the pass runs 1.8 mm from the boss (the check can fail).
    u.clearOf.clear();
    const Toolpath plain = profile(u, {16, 0}, p);
    double plainNearest = 1e9;
    for (std::size_t i = 1; i < plain.moves.size(); ++i) {
        const Move& a = plain.moves[i - 1];
        const Move& b = plain.moves[i];
        if (b.kind == Move::Kind::Rapid || std::max(a.h, b.h) >= 0) continue;
        plainNearest = std::min(plainNearest, loopSegmentDistance(boss, {a.u, a.v}, {b.u, b.v}));
    }
    EXPECT_LT(plainNearest, 2);
}

// A wall that turns towards the pocket just before its open end (milled_005's ledge running
// out at the blank through a chamfer): the first stretch's offset runs on past the last
// segment's butt end, and the band's outline meets that end 3.6 mm from the drive's end
// point. The pass must start at the end's offset corner, never on the butt end: every cut
// keeps R + allowance from the whole drive, its end point included.
TEST(Profile, OpenDriveNeverStartsOnItsButtEnd) {
    const Loop drive{{0, 40}, {0, 8}, {3, 6}};
    for (Lead lead : {Lead::None, Lead::Arc}) {
        ProfileParameters p;
        p.side = ToolSide::Left;
        p.lead = lead;
        p.radialAllowance = 0.2;
        const Toolpath t = profile({drive, false, {}, {}, 0, -2}, {10, 0}, p);
        double nearest = 1e9;
        for (std::size_t i = 1; i < t.moves.size(); ++i) {
            const Move& a = t.moves[i - 1];
            const Move& b = t.moves[i];
            if (b.kind == Move::Kind::Rapid || std::max(a.h, b.h) >= 0) continue;
            for (std::size_t k = 0; k + 1 < drive.size(); ++k)
                nearest = std::min(nearest, segmentSegment({a.u, a.v}, {b.u, b.v}, drive[k], drive[k + 1]));
        }
        EXPECT_GE(nearest, 5.2 - p.chordTolerance - 1e-9) << (lead == Lead::None ? "no leads" : "arc leads");
    }
}
