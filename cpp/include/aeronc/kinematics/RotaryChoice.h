#pragma once
// Choosing the rotary angles for a tool axis: of the two solutions (A+ and A-) and of all the
// 360-degree equivalents of each angle, the one within the limits that is nearest the previous
// angles; and telling when the limits force a jump (a branch change or an unwinding of C).
#include <aeronc/kinematics/Kinematics.h>

#include <optional>

namespace aeronc::kinematics {

// The equivalent of `angle` (+ k*360) nearest `previous` within [min, max]; none when no
// equivalent lies within the limits.
std::optional<double> windNearest(double angle, double previous, double min, double max);

// The equivalent of `angle` nearest `previous`, limits ignored.
double windNearest(double angle, double previous);

struct RotaryChoice {
    std::array<double, 2> angles{0.0, 0.0};  // within the limits
    // The limits forced a jump: the solution nearest the previous angles (limits ignored) is
    // out of reach, so the machine must leave the continuous branch (retract, reposition and
    // re-enter when cutting).
    bool branchChange = false;
    bool pole = false;  // an axis was undetermined and kept its previous angle
};

// Throws an Error whose message names the tool axis, the solutions and the limits they break.
RotaryChoice chooseRotary(const Kinematics& kin, const Vec3& axis, const std::array<double, 2>& previous);

}  // namespace aeronc::kinematics
