#pragma once
// Basic types of the 5-axis kinematics core. Lengths in mm, machine angles in degrees,
// vectors in the workpiece frame unless a name says otherwise.
// Every failure of the kinematics and the posts is an aeronc::inputError whose message is
// complete and says what to change.
#include <aeronc/core/Error.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <string>

namespace aeronc::kinematics {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

constexpr double kPi = 3.14159265358979323846;
inline double toDegrees(double rad) { return rad * (180.0 / kPi); }
inline double toRadians(double deg) { return deg * (kPi / 180.0); }

// Where the tool is relative to the workpiece: the tip, and the unit tool axis pointing from
// the tip towards the spindle (the APT i,j,k convention).
struct ToolPose {
    Vec3 tip = Vec3::Zero();
    Vec3 axis = Vec3::UnitZ();
};

// Positions of the machine's axes: linear X Y Z (mm) and the two rotary axes (degrees) in
// the order of MachineModel::rotary.
struct Joints {
    Vec3 linear = Vec3::Zero();
    std::array<double, 2> rotary{0.0, 0.0};
};

}  // namespace aeronc::kinematics
