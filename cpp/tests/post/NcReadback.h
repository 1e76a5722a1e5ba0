#pragma once
// Test-only reader of posted NC programs, written apart from the formatters: it interprets the
// 840D and LinuxCNC text the way the controller would (modal words, CYCLE800 frames, TRAORI,
// drilling cycles) and runs the machine positions through the forward kinematics, giving back
// the tool tip and axis at the end of every move in the workpiece frame.
#include <aeronc/kinematics/Kinematics.h>

#include <string>
#include <vector>

namespace readback {

using aeronc::kinematics::Vec3;

enum class Kind { Rapid, Feed, Arc, HoleBottom };

struct Pose {
    Vec3 tip;
    Vec3 axis;
    Kind kind;
    int line;          // line of the NC text
    bool full = true;  // false: a move that did not give every coordinate
    double a = 0, c = 0;  // LinuxCNC: the rotary words (first, second rotary axis)
    double inverseTimeF = 0;  // G93 F of this block, 0 otherwise
};

// Throws std::runtime_error on anything it cannot interpret.
std::vector<Pose> readSinumerik(const std::string& text, const aeronc::kinematics::Kinematics& kin, bool vectors);
std::vector<Pose> readLinuxCnc(const std::string& text, const aeronc::kinematics::Kinematics& kin);

}  // namespace readback
