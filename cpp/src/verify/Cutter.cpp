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

Cutter Cutter::cone(double diameter, double tipDiameter, double includedAngle) {
    if (!(diameter > 0) || !std::isfinite(diameter))
        throw inputError("the chamfer mill's diameter must be a positive number of mm (got " +
                         std::to_string(diameter) + ")");
    if (!(tipDiameter >= 0) || !(tipDiameter < diameter))
        throw inputError("the chamfer mill's tip diameter must lie in [0, its diameter) (got " +
                         std::to_string(tipDiameter) + " for diameter " + std::to_string(diameter) + ")");
    if (!(includedAngle > 0 && includedAngle < 180))
        throw inputError("the chamfer mill's included angle must lie between 0 and 180 degrees (got " +
                         std::to_string(includedAngle) + ")");
    Cutter c;
    c.radius = diameter / 2;
    c.tipRadius = tipDiameter / 2;
    c.coneSlope = 1 / std::tan(includedAngle / 2 * M_PI / 180);
    return c;
}

// The profile is a flat disc of radius radius - cornerRadius, then a quarter circle of radius
// cornerRadius: one formula for flat (cornerRadius 0), bull and ball (cornerRadius = radius).
double Cutter::height(double r) const {
    if (isCone()) return r <= tipRadius ? 0 : (r - tipRadius) * coneSlope;
    const double q = r - (radius - cornerRadius);
    if (q <= 0) return 0;
    return cornerRadius - std::sqrt(std::max(0.0, cornerRadius * cornerRadius - q * q));
}

double Cutter::slope(double r) const {
    if (isCone()) return r <= tipRadius ? 0 : coneSlope;
    const double q = r - (radius - cornerRadius);
    if (q <= 0) return 0;
    return q / std::sqrt(std::max(1e-300, cornerRadius * cornerRadius - q * q));
}

double Cutter::curvature(double r) const {
    if (isCone()) return 0;  // straight flanks; the kink at the tip's rim is bracketed by bisection
    const double q = r - (radius - cornerRadius);
    if (q <= 0) return 0;
    const double e = std::max(1e-300, cornerRadius * cornerRadius - q * q);
    return cornerRadius * cornerRadius / (e * std::sqrt(e));
}

Cutter Cutter::grownBy(double a) const {
    Cutter c;
    c.radius = std::max(0.0, radius + a);
    c.cornerRadius = std::clamp(cornerRadius + a, 0.0, c.radius);
    if (isCone()) {
        c.cornerRadius = 0;
        c.tipRadius = std::clamp(tipRadius + a, 0.0, c.radius);
        c.coneSlope = coneSlope;
    }
    return c;
}

}  // namespace aeronc::verify
