// The geometry the impeller strategies share (see Strategies.h).
#include "Strategies.h"

#include <algorithm>
#include <cmath>

namespace aeronc::impellerpath {

std::vector<double> stations(double a, double b, int n) {
    std::vector<double> s;
    for (int i = 0; i < n; ++i) s.push_back(lerp(a, b, (i + 0.5) / n));
    return s;
}

Vec3 blendedAxis(const Channel& ch, double r, double z, double thetaA, double thetaB, double u) {
    Vec3 ra, na, rb, nb;
    ch.wallFrame(false, ch.frame().at(r, thetaA, z), ra, na);
    ch.wallFrame(true, ch.frame().at(r, thetaB, z), rb, nb);
    return ((1 - u) * ra + u * rb).normalized();
}

double arcMargin(const Channel& ch, bool b, double r, double theta, double z, double keep) {
    Vec3 ruling, normal;
    const Vec3 p = ch.frame().at(r, theta, z);
    ch.wallFrame(b, p, ruling, normal);
    const Vec3 tangential = ch.frame().z().cross(p - ch.frame().at(0, 0, z)).normalized();
    return keep / std::max(0.2, std::abs(normal.dot(tangential)));
}

}  // namespace aeronc::impellerpath
