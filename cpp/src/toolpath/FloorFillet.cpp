#include <aeronc/toolpath/FloorFillet.h>

#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>

namespace aeronc::toolpath {

double floorFilletOffset(double floorFilletRadius, double cornerRadius, double radialAllowance) {
    if (!std::isfinite(floorFilletRadius) || floorFilletRadius < 0)
        throw inputError("floorFilletRadius must be a finite length, at least 0");
    if (floorFilletRadius == 0) return 0;
    return std::max(0.0, floorFilletRadius - (cornerRadius + radialAllowance));
}

double wallFilletOffset(double floorFilletRadius, double cornerRadius, double radialAllowance, double height) {
    const double e0 = floorFilletOffset(floorFilletRadius, cornerRadius, radialAllowance);
    if (e0 <= 0) return 0;
    const double rho = cornerRadius + radialAllowance;
    const double below = floorFilletRadius - (std::max(0.0, height) + rho);  // of the fillet's centre
    if (below <= 0) return 0;
    if (below >= e0) return e0;
    return e0 - std::sqrt(e0 * e0 - below * below);
}

}  // namespace aeronc::toolpath
