#include <aeronc/toolpath/Levels.h>

#include <aeronc/core/Error.h>

#include <cmath>

namespace aeronc::toolpath {

std::vector<double> cuttingLevels(double top, double floor, double stepDown) {
    if (!std::isfinite(top) || !std::isfinite(floor) || !std::isfinite(stepDown))
        throw inputError("the levels need finite top, floor and stepDown");
    if (!(floor < top)) throw inputError("the floor must lie below the top");
    if (!(stepDown > 0)) throw inputError("stepDown must be positive");
    // Equal steps load the cutter evenly; the 1e-9 keeps an exact multiple from adding a level.
    const double steps = std::ceil((top - floor) / stepDown - 1e-9);
    if (steps > 10000) throw inputError("stepDown is too small for the depth: more than 10,000 levels");
    const int n = std::max(1, int(steps));
    std::vector<double> levels(n);
    for (int i = 0; i < n; ++i) levels[i] = top - (top - floor) * (i + 1) / n;
    levels.back() = floor;
    return levels;
}

}  // namespace aeronc::toolpath
