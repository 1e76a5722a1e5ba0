// A toolpath as a FreeCAD Path's G-code and its time, worked out by hand.
#include <aeronc/toolpath/PathText.h>

#include <gtest/gtest.h>

using namespace aeronc::toolpath;

namespace {
Move mv(Move::Kind k, double u, double v, double h, double r = 0, double q = 0, double dwell = 0) {
    Move m;
    m.kind = k, m.u = u, m.v = v, m.h = h, m.r = r, m.q = q, m.dwell = dwell;
    return m;
}
using K = Move::Kind;
}  // namespace

TEST(PathText, MovesAndCyclesAsFreeCadWords) {
    Toolpath t;
    t.moves = {mv(K::Rapid, 1, 2, 30),         mv(K::Plunge, 1, 2, 5),          mv(K::Feed, 4.125, 2, 5),
               mv(K::Rapid, 4.125, 2, 30),     mv(K::Drill, 7, 8, -10, 3),      mv(K::Drill, 9, 8, -10, 3, 2.5),
               mv(K::Drill, 11, 8, -10, 3, 0, 0.5), mv(K::Rapid, 11, 8, 30)};
    EXPECT_EQ(pathText(t, {20, 5}, "Op (a)"),
              "(Op [a])\n"
              "G0 X1 Y2 Z30\n"
              "G1 Z5 F5\n"
              "G1 X4.125 F20\n"
              "G0 Z30\n"
              "G99\n"
              "G81 X7 Y8 Z-10 R3 F5\n"
              "G83 X9 Y8 Z-10 R3 Q2.5 F5\n"
              "G82 X11 Y8 Z-10 R3 P0.5 F5\n"
              "G80\n"
              "G0 Z30\n");
    // A move that stays writes all its coordinates; the feed after a cycle is written again.
    Toolpath stay;
    stay.moves = {mv(K::Feed, 1, 2, 3), mv(K::Feed, 1, 2, 3), mv(K::Drill, 1, 2, -5, 3), mv(K::Feed, 1, 2, 0)};
    EXPECT_EQ(pathText(stay, {20, 5}, "s"),
              "(s)\nG1 X1 Y2 Z3 F20\nG1 X1 Y2 Z3\nG99\nG81 X1 Y2 Z-5 R3 F5\nG80\nG1 Z0 F20\n");
    // Coordinates read back exactly.
    Toolpath third;
    third.moves = {mv(K::Feed, 1.0 / 3, -2.0 / 3, 0.1)};
    EXPECT_EQ(pathText(third, {2, 1}, "x"), "(x)\nG1 X0.3333333333333333 Y-0.6666666666666666 Z0.1 F2\n");
}

// A hole's centre on an axis comes out of a rotation as -5.4e-16: in exponent form FreeCAD reads
// "X-5.413158415923821e-16" as X -5.41 and a word E-16, and the cutter went 5 mm astray into
// the hole's wall (four holes of NIST CTC-05). Every word is written in fixed notation.
TEST(PathText, TinyAndLargeValuesInFixedNotation) {
    Toolpath t;
    t.moves = {mv(K::Rapid, -5.413158415923821e-16, -222.25, 30), mv(K::Feed, 1.5e-5, -0.0, 2.5e-9),
               mv(K::Feed, 123456789.125, 1e-3, -7.0e-12)};
    const std::string text = pathText(t, {20, 5}, "tiny");
    EXPECT_EQ(text, "(tiny)\n"
                    "G0 X0 Y-222.25 Z30\n"
                    "G1 X0.000015 Y0 Z0.0000000025 F20\n"
                    "G1 X123456789.125 Y0.001 Z0\n");
    EXPECT_EQ(text.find_first_of("eE", 7), std::string::npos);
}

TEST(PathText, TimeByHand) {
    // 3 mm plunge at 1 mm/s, 4 mm feed at 2 mm/s, a 10 mm drill cycle at 1 mm/s in; rapids off.
    Toolpath t;
    t.moves = {mv(K::Rapid, 0, 0, 3), mv(K::Plunge, 0, 0, 0), mv(K::Feed, 4, 0, 0), mv(K::Drill, 4, 0, -8, 2)};
    EXPECT_DOUBLE_EQ(estimatedSeconds(t, {2, 1}), 3 + 2 + 10);
    // Rapids of 10 mm/s: back up the 10 mm of the cycle; the first rapid is where the tool starts.
    EXPECT_DOUBLE_EQ(estimatedSeconds(t, {2, 1, 10, 10}), 3 + 2 + 10 + 1);
    // A rapid's horizontal and vertical parts at their own rates.
    Toolpath r;
    r.moves = {mv(K::Rapid, 0, 0, 0), mv(K::Rapid, 3, 4, 10)};
    EXPECT_DOUBLE_EQ(estimatedSeconds(r, {1, 1, 5, 2}), 5.0 / 5 + 10.0 / 2);
}
