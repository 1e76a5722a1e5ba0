#include <aeronc/core/Error.h>
#include <aeronc/verify/Cutter.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace aeronc::verify {

Cutter Cutter::fromDiameter(double diameter, double cornerRadius) {
    if (!(diameter > 0) || !std::isfinite(diameter))
        throw inputError("the cutter diameter must be a positive number of mm (got " + std::to_string(diameter) + ")");
    const double r = diameter / 2;
    if (!(cornerRadius >= 0) || cornerRadius > r * (1 + 1e-9))
        throw inputError("the cutter's corner radius must lie between 0 and half its diameter (got " +
                         std::to_string(cornerRadius) + " for diameter " + std::to_string(diameter) + ")");
    return Cutter{r, std::min(cornerRadius, r)};
}

// The profile is a flat disc of radius radius - cornerRadius, then a quarter circle of radius
// cornerRadius: one formula for flat (cornerRadius 0), bull and ball (cornerRadius = radius).
double Cutter::height(double r) const {
    const double q = r - (radius - cornerRadius);
    if (q <= 0) return 0;
    return cornerRadius - std::sqrt(std::max(0.0, cornerRadius * cornerRadius - q * q));
}

double Cutter::slope(double r) const {
    const double q = r - (radius - cornerRadius);
    if (q <= 0) return 0;
    return q / std::sqrt(std::max(1e-300, cornerRadius * cornerRadius - q * q));
}

double Cutter::curvature(double r) const {
    const double q = r - (radius - cornerRadius);
    if (q <= 0) return 0;
    const double e = std::max(1e-300, cornerRadius * cornerRadius - q * q);
    return cornerRadius * cornerRadius / (e * std::sqrt(e));
}

Cutter Cutter::grownBy(double a) const {
    Cutter c;
    c.radius = std::max(0.0, radius + a);
    c.cornerRadius = std::clamp(cornerRadius + a, 0.0, c.radius);
    return c;
}

}  // namespace aeronc::verify
