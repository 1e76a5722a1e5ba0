#pragma once
// What the kinematics and post tests share: the shipped machine files and tool-axis geometry.
#include <aeronc/kinematics/Kinematics.h>

#include <cmath>
#include <string>

namespace aeronc::kinematics::test {

inline MachineModel machine(const std::string& name) {
    return loadMachineFile(std::string(AERONC_MACHINES) + "/" + name + ".json");
}

inline double angleBetween(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

// The unit axis at polar angle polarDeg from +Z and azimuth azimuthDeg from +X.
inline Vec3 axisAt(double polarDeg, double azimuthDeg) {
    const double p = toRadians(polarDeg), a = toRadians(azimuthDeg);
    return {std::sin(p) * std::cos(a), std::sin(p) * std::sin(a), std::cos(p)};
}

}  // namespace aeronc::kinematics::test
