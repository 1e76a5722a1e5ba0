#pragma once
// Basic types of the compensation core (drilling seed, DESIGN.md section 3 "Datum holes and
// compensation"). Lengths in mm. Points are in the part frame unless a name says otherwise.
#include <aeronc/core/Error.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

namespace aeronc::compensation {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;

// Every failure of the compensation core is bad input: the message names the hole, the line or
// the value at fault and says what to change.
inline Error compensationError(const std::string& m) { return inputError(m); }

inline bool finite(const Vec3& v) { return v.allFinite(); }

}  // namespace aeronc::compensation
