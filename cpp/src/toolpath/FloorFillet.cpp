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

}  // namespace aeronc::toolpath
