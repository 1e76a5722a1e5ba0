// Cutter profiles and the envelope of a cutter swept along a segment, against the formulas and
// against brute-force sampling of the tool positions.
#include <aeronc/verify/Cutter.h>
#include <aeronc/verify/SweptSegment.h>

#include "../ErrorOf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace aeronc::verify;

namespace {

// The envelope by sampling the segment densely: the reference for SweptSegment::envelope.
double sampledEnvelope(const Cutter& c, double x0, double y0, double w0, double x1, double y1, double w1, double x,
                       double y, int samples = 50000) {
    double best = HUGE_VAL;
    for (int k = 0; k <= samples; ++k) {
        const double t = double(k) / samples;
        const double d = std::hypot(x - (x0 + t * (x1 - x0)), y - (y0 + t * (y1 - y0)));
        if (d <= c.radius) best = std::min(best, w0 + t * (w1 - w0) + c.height(d));
    }
    return best;
}

}  // namespace

TEST(Cutter, ProfilesFollowTheirFormulas) {
    const Cutter flat = Cutter::fromDiameter(10, 0), ball = Cutter::fromDiameter(10, 5),
                 bull = Cutter::fromDiameter(10, 2);
    for (double r : {0.0, 1.0, 2.9, 3.0, 3.5, 4.0, 4.9, 5.0}) {
        EXPECT_DOUBLE_EQ(flat.height(r), 0.0) << r;
        EXPECT_NEAR(ball.height(r), 5 - std::sqrt(25 - r * r), 1e-12) << r;
        const double bullExpected = r <= 3 ? 0 : 2 - std::sqrt(4 - (r - 3) * (r - 3));
        EXPECT_NEAR(bull.height(r), bullExpected, 1e-12) << r;
    }
    EXPECT_NEAR(ball.height(5), 5, 1e-12);  // the equator
    EXPECT_NEAR(bull.height(5), 2, 1e-12);
    EXPECT_DOUBLE_EQ(ball.slope(0), 0);
    EXPECT_NEAR(ball.slope(3), 3.0 / 4.0, 1e-12);
    EXPECT_GT(ball.slope(5), 1e6);
}

TEST(Cutter, GrowsByAnAllowanceAllRound) {
    const Cutter flat = Cutter::fromDiameter(10, 0).grownBy(0.5);
    EXPECT_DOUBLE_EQ(flat.radius, 5.5);
    EXPECT_DOUBLE_EQ(flat.cornerRadius, 0.5);  // a flat end mill grown by a ball is a bull nose
    const Cutter ball = Cutter::fromDiameter(10, 5).grownBy(0.5);
    EXPECT_DOUBLE_EQ(ball.radius, 5.5);
    EXPECT_DOUBLE_EQ(ball.cornerRadius, 5.5);
    // Grown by a: every point of the profile is a further away along the normal.
    const Cutter bull = Cutter::fromDiameter(10, 2), g = bull.grownBy(1);
    for (double r : {3.2, 4.0, 4.8}) {
        const double q = r - 3, h = 2 - std::sqrt(4 - q * q);  // on the bull's corner, centre (3, 2)
        const double nx = q / 2, nz = (h - 2) / 2;               // unit normal there
        EXPECT_NEAR(g.height(r + nx) - 1, h + nz, 1e-12) << r;   // the grown tip is 1 lower
    }
}

TEST(Cutter, RejectsImpossibleShapes) {
    using aeronc::test::inputErrorOf;
    EXPECT_NE(inputErrorOf([] { Cutter::fromDiameter(0, 0); }).find("diameter"), std::string::npos);
    EXPECT_NE(inputErrorOf([] { Cutter::fromDiameter(-6, 0); }).find("diameter"), std::string::npos);
    EXPECT_NE(inputErrorOf([] { Cutter::fromDiameter(6, 3.5); }).find("corner radius"), std::string::npos);
    EXPECT_NE(inputErrorOf([] { Cutter::fromDiameter(6, -1); }).find("corner radius"), std::string::npos);
    EXPECT_NE(inputErrorOf([] { Cutter::fromDiameter(NAN, 0); }).find("diameter"), std::string::npos);
}

TEST(SweptSegment, HorizontalMoveLeavesTheProfileAcrossIt) {
    const Cutter ball = Cutter::fromDiameter(6, 3);
    const SweptSegment s(0, 0, 10, 20, 0, 10);
    for (double p : {0.0, 1.0, 2.5, 2.99})
        EXPECT_NEAR(s.envelope(ball, 7.3, p), 10 + 3 - std::sqrt(9 - p * p), 1e-12) << p;
    EXPECT_EQ(s.envelope(ball, 7.3, 3.01), HUGE_VAL);
    // Beyond the end the cutter's own shape, centred on the end point.
    EXPECT_NEAR(s.envelope(ball, 22, 1), 10 + 3 - std::sqrt(9 - 5), 1e-12);
    EXPECT_NEAR(s.distance(22, 1), std::sqrt(5), 1e-12);
}

TEST(SweptSegment, PlungeLeavesTheCutterShapeAtTheBottom) {
    const Cutter bull = Cutter::fromDiameter(8, 1);
    const SweptSegment s(5, 5, 30, 5, 5, 12);
    EXPECT_DOUBLE_EQ(s.envelope(bull, 5, 5), 12);
    EXPECT_DOUBLE_EQ(s.envelope(bull, 8, 5), 12);
    EXPECT_NEAR(s.envelope(bull, 8.5, 5), 12 + 1 - std::sqrt(1 - 0.25), 1e-12);
    EXPECT_EQ(s.envelope(bull, 9.01, 5), HUGE_VAL);
}

TEST(SweptSegment, RampsMatchBruteForceForEveryCutter) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (double corner : {0.0, 1.5, 4.0}) {
        const Cutter c = Cutter::fromDiameter(8, corner);
        for (int seg = 0; seg < 6; ++seg) {
            const double x0 = 10 * u(rng), y0 = 10 * u(rng), w0 = 5 * u(rng);
            const double x1 = 10 * u(rng), y1 = 10 * u(rng), w1 = w0 + 6 * u(rng);
            const SweptSegment s(x0, y0, w0, x1, y1, w1);
            for (int k = 0; k < 40; ++k) {
                const double x = 0.5 * (x0 + x1) + 8 * u(rng), y = 0.5 * (y0 + y1) + 8 * u(rng);
                const double ref = sampledEnvelope(c, x0, y0, w0, x1, y1, w1, x, y);
                const double got = s.envelope(c, x, y);
                if (ref == HUGE_VAL) {
                    // Sampling may miss a sliver at the rim; the exact envelope can only be lower.
                    if (got != HUGE_VAL) EXPECT_LE(s.distance(x, y), c.radius + 1e-9);
                    continue;
                }
                // Sampling only sees a finite set of positions: it is never below the exact value.
                EXPECT_LE(got, ref + 1e-9) << corner << " " << seg << " " << k;
                EXPECT_GT(got, ref - 2e-3) << corner << " " << seg << " " << k;
            }
        }
    }
}

TEST(SweptSegment, RowSpanHoldsExactlyThePointsWithinReach) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-10, 10);
    for (int seg = 0; seg < 20; ++seg) {
        const double x0 = u(rng), y0 = u(rng), x1 = seg % 5 == 0 ? x0 : u(rng), y1 = seg % 7 == 0 ? y0 : u(rng);
        const SweptSegment s(x0, y0, 0, x1, y1, 0);
        const double reach = 3;
        for (double y = -15; y <= 15; y += 0.37) {
            double xa, xb;
            const bool any = s.rowSpan(y, reach, xa, xb);
            for (double x = -16; x <= 16; x += 0.013) {
                const bool within = s.distance(x, y) <= reach;
                if (within) {
                    ASSERT_TRUE(any) << seg << " " << y << " " << x;
                    EXPECT_GE(x, xa - 1e-9);
                    EXPECT_LE(x, xb + 1e-9);
                } else if (any && s.distance(x, y) > reach + 1e-6) {
                    EXPECT_TRUE(x < xa || x > xb) << seg << " " << y << " " << x;
                }
            }
        }
    }
}

TEST(Cutter, ChamferMillIsAFlatTipThenACone) {
    const Cutter c90 = Cutter::cone(10, 1, 90), c60 = Cutter::cone(10, 0, 60);
    EXPECT_TRUE(c90.isCone());
    EXPECT_FALSE(Cutter::fromDiameter(10, 0).isCone());
    for (double r : {0.0, 0.3, 0.5, 1.0, 2.5, 5.0}) {
        EXPECT_NEAR(c90.height(r), std::max(0.0, r - 0.5), 1e-12) << r;
        EXPECT_NEAR(c60.height(r), r * std::sqrt(3.0), 1e-12) << r;
    }
    EXPECT_DOUBLE_EQ(c90.slope(0.2), 0.0);
    EXPECT_NEAR(c90.slope(3), 1.0, 1e-12);
    const Cutter grown = c90.grownBy(0.2);
    EXPECT_NEAR(grown.radius, 5.2, 1e-12);
    EXPECT_NEAR(grown.height(3.2), c90.height(3.0), 1e-12);  // moved out sideways by the allowance
    EXPECT_NE(aeronc::test::errorOf([] { Cutter::cone(10, 10, 90); }).find("tip diameter"), std::string::npos);
    EXPECT_NE(aeronc::test::errorOf([] { Cutter::cone(10, 1, 180); }).find("included angle"), std::string::npos);
    // Swept along slanted and level segments, the envelope is the sampled one.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-6, 6);
    for (int k = 0; k < 200; ++k) {
        const double x = u(rng), y = u(rng), w1 = k % 2 ? 0.0 : u(rng);
        const SweptSegment s(-3, 0, 0, 3, 1, w1);
        const double e = s.envelope(c90, x, y), ref = sampledEnvelope(c90, -3, 0, 0, 3, 1, w1, x, y);
        if (ref == HUGE_VAL) {
            EXPECT_EQ(e, HUGE_VAL) << x << " " << y;
            continue;
        }
        EXPECT_NEAR(e, ref, 2e-3) << x << " " << y << " " << w1;
    }
}
