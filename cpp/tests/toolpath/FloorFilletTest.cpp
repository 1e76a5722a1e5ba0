// The floor-fillet offset: checked against the geometry it comes from (the grown corner arc of
// the cutter inside the fillet's circle, sampled), and in a pocket whose walls meet the floor in
// a fillet larger than the cutter's corner.
#include "Checks.h"

#include <aeronc/toolpath/FloorFillet.h>
#include <aeronc/toolpath/PocketClearing.h>
#include <aeronc/toolpath/ToolpathJson.h>

#include <ErrorOf.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace aeronc::toolpath;

namespace {

// How far the grown corner arc of a cutter (axis at R + a + e from the wall x = 0, tip at the
// floor + axial) reaches into the fillet's allowance layer, in the plane normal to the wall;
// <= 0: clear. The layer is what the verification holds the cutter grown by a away from.
double intoFillet(double rf, double rc, double a, double e, double height = 0) {
    const double cx = a + e + rc, cz = height + a + rc, rho = rc + a;  // grown arc, lifted to the tip
    double worst = -1e9;
    for (int k = 0; k <= 2000; ++k) {  // the lower-left quarter of the arc faces the fillet
        const double t = M_PI + 0.5 * M_PI * k / 2000.0;
        const double x = cx + rho * std::cos(t), z = cz + rho * std::sin(t);
        if (x >= rf || z >= rf) continue;  // beyond the fillet: wall and floor are held off apart
        worst = std::max(worst, std::hypot(x - rf, z - rf) - rf);  // > 0: into the material
    }
    return worst;
}

}  // namespace

TEST(FloorFillet, OffsetKeepsTheCornerOutOfTheFillet) {
    struct Case { double rf, rc, a; };
    for (const Case c : {Case{3, 2, 0.5}, Case{3, 0, 0.5}, Case{6, 2, 1}, Case{4, 1, 0}, Case{5, 2.5, 0.2}}) {
        const double e = floorFilletOffset(c.rf, c.rc, c.a);
        EXPECT_NEAR(e, c.rf - c.rc - c.a, 1e-12);
        EXPECT_LE(intoFillet(c.rf, c.rc, c.a, e), 1e-9) << c.rf << " " << c.rc << " " << c.a;
        // Any less and the corner cuts into the layer.
        EXPECT_GT(intoFillet(c.rf, c.rc, c.a, e - 0.05), 1e-4) << c.rf << " " << c.rc << " " << c.a;
    }
    // A corner at least as large as the fillet plus the allowance needs nothing.
    EXPECT_EQ(floorFilletOffset(3, 3, 0), 0.0);
    EXPECT_EQ(floorFilletOffset(3, 2, 1), 0.0);
    EXPECT_LE(intoFillet(3, 2, 1, 0), 1e-9);
    EXPECT_EQ(floorFilletOffset(0, 2, 0.5), 0.0);
    EXPECT_NE(aeronc::test::inputErrorOf([] { floorFilletOffset(-1, 2, 0.5); }).find("floorFilletRadius"),
              std::string::npos);
    EXPECT_NE(aeronc::test::inputErrorOf([] { floorFilletOffset(NAN, 2, 0.5); }).find("floorFilletRadius"),
              std::string::npos);
}

// Down a wall, level by level: the least offset that keeps the grown corner out of the fillet,
// shrinking to 0 where the corner's centre reaches the fillet's height.
TEST(FloorFillet, WallOffsetAtEachHeightIsTheLeastThatClearsTheFillet) {
    struct Case { double rf, rc, a; };
    for (const Case c : {Case{6.35, 4, 0}, Case{6.35, 4, 0.2}, Case{3, 0, 0.5}, Case{6, 2, 1}}) {
        EXPECT_DOUBLE_EQ(wallFilletOffset(c.rf, c.rc, c.a, 0), floorFilletOffset(c.rf, c.rc, c.a));
        double last = 1e9;
        for (double h = 0; h <= c.rf + 1; h += 0.25) {
            const double e = wallFilletOffset(c.rf, c.rc, c.a, h);
            EXPECT_LE(e, last + 1e-12) << h;
            last = e;
            EXPECT_LE(intoFillet(c.rf, c.rc, c.a, e, h), 1e-9) << c.rf << " " << c.rc << " " << h;
            if (e > 0.06) EXPECT_GT(intoFillet(c.rf, c.rc, c.a, e - 0.05, h), 1e-6) << c.rf << " " << c.rc << " " << h;
        }
        EXPECT_EQ(wallFilletOffset(c.rf, c.rc, c.a, c.rf - c.rc - c.a), 0.0);
    }
    EXPECT_EQ(wallFilletOffset(0, 2, 0.5, 0), 0.0);
}

// A 100 x 60 pocket with a 3 mm floor fillet, a 16 mm bull end mill with a 2 mm corner and
// 0.5 mm radial allowance: every tool position keeps 8 + 0.5 + 0.5 mm from the walls; without
// the fillet, 8.5 mm as before.
TEST(FloorFillet, PocketClearingHoldsBackFromTheFillet) {
    PocketUnit u;
    u.contour = {{0, 0}, {100, 0}, {100, 60}, {0, 60}};
    u.top = 10;
    u.bottom = 0;
    PocketParameters p;
    p.stepDown = 5;
    p.stepOver = 6;
    p.radialAllowance = 0.5;
    const Cutter bull{16, 2};
    auto nearestWall = [](const Toolpath& tp) {
        double d = 1e9;
        for (const Move& m : tp.moves)
            if (m.kind != Move::Kind::Rapid)
                d = std::min({d, m.u, 100 - m.u, m.v, 60 - m.v});
        return d;
    };
    const double plain = nearestWall(pocketClearing(u, bull, p));
    EXPECT_NEAR(plain, 8.5, 0.02);
    u.floorFilletRadius = 3;
    const double held = nearestWall(pocketClearing(u, bull, p));
    EXPECT_NEAR(held, 9.0, 0.02);
    EXPECT_GE(held, 9.0 - 1e-6);
    // The same through the JSON contract.
    const auto out = nlohmann::json::parse(toolpathJson(
        R"({"operation": "pocket", "cutter": {"diameter": 16, "cornerRadius": 2}, "top": 10, "bottom": 0,
            "stepDown": 5, "stepOver": 6, "radialAllowance": 0.5, "floorFilletRadius": 3,
            "contour": [[0, 0], [100, 0], [100, 60], [0, 60]]})"));
    double viaJson = 1e9;
    for (const auto& m : out.at("moves"))
        if (m[0].get<int>() != 0) {
            const double x = m[1].get<double>(), y = m[2].get<double>();
            viaJson = std::min({viaJson, x, 100 - x, y, 60 - y});
        }
    EXPECT_NEAR(viaJson, 9.0, 0.02);
}

// A 20 mm square island in a 100 x 60 pocket, all with a 3 mm floor fillet: the island's four
// fillets meet in mitres at its corners. Round a corner every cutting position keeps 8 + 0.5
// + 0.5 mm from both walls' lines (out to the mitre point); rolled round the corner's edge at
// that distance the cutter would cut the mitre (the simulation found 0.14 to 0.76 mm so on
// NIST CTC-01's islands). Without a fillet the cutter still rolls round the edge.
TEST(FloorFillet, ClearingGoesRoundAConvexCornerOutToTheFilletsMitre) {
    PocketUnit u;
    u.contour = {{0, 0}, {100, 0}, {100, 60}, {0, 60}};
    u.islands = {{{40, 20}, {40, 40}, {60, 40}, {60, 20}}};
    u.top = 10;
    u.bottom = 0;
    PocketParameters p;
    p.stepDown = 5;
    p.stepOver = 6;
    p.radialAllowance = 0.5;
    p.finishingPass = true;
    p.finishingAllowance = 0.5;
    const Cutter bull{16, 2};
    // The least distance of a cutting position from the island's walls' lines (the largest of
    // its distances beyond each line), and from the island itself.
    auto nearest = [](const Toolpath& tp) {
        double fromLines = 1e9, fromIsland = 1e9;
        for (const Move& m : tp.moves) {
            if (m.kind == Move::Kind::Rapid) continue;
            const double dx = std::max({40 - m.u, 0.0, m.u - 60}), dy = std::max({20 - m.v, 0.0, m.v - 40});
            fromLines = std::min(fromLines, std::max(dx, dy));
            fromIsland = std::min(fromIsland, std::hypot(dx, dy));
        }
        return std::make_pair(fromLines, fromIsland);
    };
    const auto plain = nearest(pocketClearing(u, bull, p));
    EXPECT_NEAR(plain.second, 8.5, 0.02);
    EXPECT_LT(plain.first, 8.5 / std::sqrt(2.0) + 0.1);  // rolled round the edge
    u.floorFilletRadius = 3;
    const auto held = nearest(pocketClearing(u, bull, p));
    EXPECT_GE(held.first, 9.0 - 0.006);
    EXPECT_NEAR(held.second, 9.0, 0.02);
}
