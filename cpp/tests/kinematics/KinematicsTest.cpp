// Forward and inverse kinematics of the two machines, the pole, winding and branch choice.
#include "Fixtures.h"

#include <aeronc/kinematics/Kinematics.h>
#include <aeronc/kinematics/RotaryChoice.h>

#include <gtest/gtest.h>

#include <random>

using namespace aeronc::kinematics;
using namespace aeronc::kinematics::test;

namespace {

// Every solution the inverse kinematics gives must take the machine to the pose.
void expectRoundTrip(const Kinematics& kin, const ToolPose& pose, const std::array<double, 2>& keep) {
    const auto sols = kin.orientations(pose.axis, keep);
    ASSERT_FALSE(sols.empty());
    for (const auto& s : sols) {
        Joints j;
        j.rotary = s.angles;
        j.linear = kin.linearFor(pose.tip, s.angles);
        const ToolPose back = kin.forward(j);
        EXPECT_LT((back.tip - pose.tip).norm(), 1e-9);
        EXPECT_LT(angleBetween(back.axis, pose.axis), 1e-12);
    }
}

}  // namespace

TEST(Kinematics, TableTableKnownPoseByHand) {
    const Kinematics kin(machine("AC-5AX"));
    // Tool tilted by 30 degrees towards +Y of the part: A=+30, C=0 or A=-30, C=180.
    const Vec3 u(0, 0.5, std::sqrt(3.0) / 2);
    const auto sols = kin.orientations(u, {0, 0});
    ASSERT_EQ(sols.size(), 2u);
    bool plus = false, minus = false;
    for (const auto& s : sols) {
        if (std::abs(s.angles[0] - 30) < 1e-9 && std::abs(s.angles[1]) < 1e-9) plus = true;
        if (std::abs(s.angles[0] + 30) < 1e-9 && std::abs(std::abs(s.angles[1]) - 180) < 1e-9) minus = true;
    }
    EXPECT_TRUE(plus && minus);
    // The part zero turns about the A axis through (0, 20, -80): y = 20 - 20 cos30 - 80 sin30,
    // z = -80 - 20 sin30 + 80 cos30.
    const double c30 = std::sqrt(3.0) / 2, s30 = 0.5;
    const Vec3 lin = kin.linearFor(Vec3::Zero(), {30, 0});
    EXPECT_NEAR(lin.x(), 0.0, 1e-12);
    EXPECT_NEAR(lin.y(), 20 - 20 * c30 - 80 * s30, 1e-12);
    EXPECT_NEAR(lin.z(), -80 - 20 * s30 + 80 * c30, 1e-12);
}

TEST(Kinematics, HeadHeadKnownPoseByHand) {
    MachineSetup setup;
    setup.toolLength = 100;
    const Kinematics kin(machine("AC-HEAD"), setup);
    // Head tilted by A=+30 about X: the tool axis turns from +Z to (0, -sin30, cos30); the tip,
    // 280 mm below the A axis, swings by 280 sin30 in +Y and rises by 280 (1 - cos30).
    Joints j;
    j.rotary = {0, 30};  // C, A
    j.linear = {10, 20, 30};
    const ToolPose p = kin.forward(j);
    EXPECT_LT((p.axis - Vec3(0, -0.5, std::sqrt(3.0) / 2)).norm(), 1e-12);
    EXPECT_LT((p.tip - Vec3(10, 20 + 280 * 0.5, 30 + 280 * (1 - std::sqrt(3.0) / 2))).norm(), 1e-9);
}

TEST(Kinematics, RandomPosesRoundTripOnBothMachines) {
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<double> az(-180, 180), coord(-150, 150);
    for (const auto& [name, maxTilt] : {std::pair<std::string, double>{"AC-5AX", 118}, {"AC-HEAD", 98}}) {
        std::uniform_real_distribution<double> tilt(0, maxTilt), keep(-90, 90), length(0, 200);
        for (int i = 0; i < 2000; ++i) {
            MachineSetup setup;
            setup.toolLength = length(rng);
            setup.partZero = Vec3(coord(rng), coord(rng), coord(rng) / 3);
            const Kinematics kin(machine(name), setup);
            ToolPose pose;
            pose.tip = {coord(rng), coord(rng), coord(rng)};
            pose.axis = axisAt(tilt(rng), az(rng));
            expectRoundTrip(kin, pose, {keep(rng), keep(rng)});
        }
    }
}

TEST(Kinematics, ThePoleKeepsThePreviousC) {
    const Kinematics table(machine("AC-5AX"));
    auto sols = table.orientations(Vec3::UnitZ(), {12.5, 47.25});
    ASSERT_EQ(sols.size(), 1u);
    EXPECT_DOUBLE_EQ(sols[0].angles[1], 47.25);
    EXPECT_TRUE(sols[0].free[1]);
    EXPECT_FALSE(sols[0].free[0]);
    EXPECT_NEAR(sols[0].angles[0], 0.0, 1e-12);

    const Kinematics head(machine("AC-HEAD"));
    sols = head.orientations(Vec3::UnitZ(), {-33, 5});
    ASSERT_EQ(sols.size(), 1u);
    EXPECT_DOUBLE_EQ(sols[0].angles[0], -33);  // C is the head's first axis
    EXPECT_NEAR(sols[0].angles[1], 0.0, 1e-12);

    // Just off the pole the kept C still reaches the axis far inside 1e-9 rad.
    const Vec3 nearPole = axisAt(1e-12 * 180 / kPi, 40);
    sols = table.orientations(nearPole, {0, -100});
    ASSERT_EQ(sols.size(), 1u);
    Joints j;
    j.rotary = sols[0].angles;
    EXPECT_LT(angleBetween(table.forward(j).axis, nearPole), 1e-10);
}

TEST(Kinematics, WindingPicksTheEquivalentNearestThePreviousWithinLimits) {
    EXPECT_DOUBLE_EQ(*windNearest(-5, 350, -360, 360), 355);
    EXPECT_DOUBLE_EQ(*windNearest(5, 355, -360, 360), 5);  // 365 is beyond the limit
    EXPECT_DOUBLE_EQ(windNearest(5, 355), 365);
    EXPECT_DOUBLE_EQ(*windNearest(170, -170, -200, 200), -190);
    EXPECT_FALSE(windNearest(150, 0, -120, 120).has_value());
    EXPECT_DOUBLE_EQ(*windNearest(-120, 0, -120, 120), -120);
}

TEST(Kinematics, ContinuousPathNeedsNoBranchChange) {
    const Kinematics kin(machine("AC-5AX"));
    std::array<double, 2> prev{0, 0};
    // Tool tilted 40 degrees and swept around the part by 350 degrees: C follows, past 300.
    for (int k = 0; k <= 70; ++k) {
        const double az = -90 + 5.0 * k;
        const Vec3 u = axisAt(40, az);
        const RotaryChoice c = chooseRotary(kin, u, prev);
        if (k > 0) {
            EXPECT_LT(std::abs(c.angles[1] - prev[1]), 5.0 + 1e-6);
            EXPECT_LT(std::abs(c.angles[0] - prev[0]), 1e-6);
        }
        EXPECT_FALSE(c.branchChange) << "step " << k;
        prev = c.angles;
    }
    EXPECT_GT(std::abs(prev[1]), 300.0);  // wound beyond one turn
}

TEST(Kinematics, CLimitForcesAnUnwind) {
    const Kinematics kin(machine("AC-5AX"));
    std::array<double, 2> prev{0, 0};
    bool forced = false;
    for (int k = 0; k <= 200 && !forced; ++k) {
        const RotaryChoice c = chooseRotary(kin, axisAt(40, -90 + 5.0 * k), prev);
        if (c.branchChange) {
            // Beyond C's +-360 the machine either unwinds C by a turn or flips to the other
            // A branch (C by half a turn), whichever moves less: a jump either way.
            forced = true;
            EXPECT_GT(std::abs(c.angles[1] - prev[1]), 170.0);
            Joints j;
            j.rotary = c.angles;
            EXPECT_LT(angleBetween(kin.forward(j).axis, axisAt(40, -90 + 5.0 * k)), 1e-12);
        } else if (k > 0) {
            EXPECT_LT(std::abs(c.angles[1] - prev[1]), 5.0 + 1e-6);
        }
        for (int i = 0; i < 2; ++i) {
            EXPECT_GE(c.angles[i], kin.model().rotary[i].min - 1e-9);
            EXPECT_LE(c.angles[i], kin.model().rotary[i].max + 1e-9);
        }
        prev = c.angles;
    }
    EXPECT_TRUE(forced);
}

TEST(Kinematics, ALimitForcesTheOtherBranch) {
    MachineModel m = machine("AC-5AX");
    m.rotary[0].min = -30;  // a trunnion that tilts little one way
    const Kinematics kin(m);
    const RotaryChoice first = chooseRotary(kin, axisAt(20, -90), {0, 0});
    ASSERT_FALSE(first.branchChange);
    // Continuing on A's branch would need A beyond -30: the other branch (A+, C+180) is taken.
    const Vec3 steeper = axisAt(40, -90);
    const auto sols = kin.orientations(steeper, first.angles);
    ASSERT_EQ(sols.size(), 2u);
    const RotaryChoice next = chooseRotary(kin, steeper, first.angles);
    EXPECT_TRUE(next.branchChange);
    EXPECT_NEAR(std::abs(next.angles[0]), 40, 1e-9);
    EXPECT_GE(next.angles[0], -30);
    Joints j;
    j.rotary = next.angles;
    EXPECT_LT(angleBetween(kin.forward(j).axis, steeper), 1e-12);
}

TEST(Kinematics, OrientationBeyondTheALimitsIsAClearError) {
    const Kinematics kin(machine("AC-5AX"));
    try {
        chooseRotary(kin, axisAt(150, 30), {0, 0});
        FAIL() << "no error";
    } catch (const aeronc::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("out of reach"), std::string::npos) << m;
        EXPECT_NE(m.find("A outside [-120.000, 120.000]"), std::string::npos) << m;
    }
    EXPECT_THROW(chooseRotary(kin, -Vec3::UnitZ(), {0, 0}), aeronc::Error);
}

TEST(MachineFile, BadEntriesAreNamed) {
    auto err = [](const std::string& text) {
        try {
            machineFromJson(text, "m.json");
        } catch (const aeronc::Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string axes =
        R"("rotaryAxes":[{"name":"A","carrier":"table","direction":[1,0,0],"point":[0,0,0],"min":-90,"max":90},)"
        R"({"name":"C","carrier":"table","direction":[0,0,1],"point":[0,0,0],"min":-360,"max":360}])";
    EXPECT_EQ(err(R"({"name":"M",)" + axes + "}"), "no error");
    EXPECT_NE(err(R"({"name":"M"})").find("missing \"rotaryAxes\""), std::string::npos);
    EXPECT_NE(err("{not json").find("not valid JSON"), std::string::npos);
    std::string bad = axes;
    bad.replace(bad.find("[1,0,0]"), 7, "[1,1,0]");
    EXPECT_NE(err(R"({"name":"M",)" + bad + "}").find("unit vector"), std::string::npos);
    bad = axes;
    bad.replace(bad.find("[1,0,0]"), 7, "[0,0,1]");
    EXPECT_NE(err(R"({"name":"M",)" + bad + "}").find("parallel"), std::string::npos);
    bad = axes;
    bad.replace(bad.find("-90"), 3, "100");
    EXPECT_NE(err(R"({"name":"M",)" + bad + "}").find("\"min\" > \"max\""), std::string::npos);
}
