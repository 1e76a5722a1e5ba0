// Winding and branch choice of the rotary axes (see RotaryChoice.h).
#include <aeronc/kinematics/RotaryChoice.h>

#include <algorithm>
#include <cstdio>
#include <limits>

namespace aeronc::kinematics {

namespace {

constexpr double kLimitSlack = 1e-9;  // degrees: a limit reached by rounding is still reached

std::string fmt(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", v);
    return b;
}

}  // namespace

std::optional<double> windNearest(double angle, double previous, double min, double max) {
    const double kmin = std::ceil((min - kLimitSlack - angle) / 360.0);
    const double kmax = std::floor((max + kLimitSlack - angle) / 360.0);
    if (kmin > kmax) return std::nullopt;
    const double k = std::clamp(std::round((previous - angle) / 360.0), kmin, kmax);
    return angle + 360.0 * k;
}

double windNearest(double angle, double previous) {
    return angle + 360.0 * std::round((previous - angle) / 360.0);
}

RotaryChoice chooseRotary(const Kinematics& kin, const Vec3& axis, const std::array<double, 2>& previous) {
    const MachineModel& m = kin.model();
    const auto solutions = kin.orientations(axis, previous);
    auto axisText = [&] {
        return "tool axis (" + fmt(axis.x()) + ", " + fmt(axis.y()) + ", " + fmt(axis.z()) + ")";
    };
    if (solutions.empty())
        throw inputError(axisText() + " cannot be reached by the rotary axes " + m.rotary[0].name + " and " +
                         m.rotary[1].name + " of machine " + m.name);

    auto cost = [&](const std::array<double, 2>& a) {
        return std::abs(a[0] - previous[0]) + std::abs(a[1] - previous[1]);
    };
    double bestFree = std::numeric_limits<double>::infinity();  // nearest solution, limits ignored
    double bestCost = std::numeric_limits<double>::infinity();
    RotaryChoice choice;
    std::string refusals;
    for (const auto& s : solutions) {
        std::array<double, 2> unlimited{}, limited{};
        bool within = true;
        std::string why;
        for (int i = 0; i < 2; ++i) {
            const RotaryAxis& ax = m.rotary[i];
            unlimited[i] = s.free[i] ? s.angles[i] : windNearest(s.angles[i], previous[i]);
            const auto w = s.free[i] ? std::optional<double>(s.angles[i])
                                     : windNearest(s.angles[i], previous[i], ax.min, ax.max);
            if (!w || *w < ax.min - kLimitSlack || *w > ax.max + kLimitSlack) {
                within = false;
                why += (why.empty() ? "" : ", ") + ax.name + " outside [" + fmt(ax.min) + ", " + fmt(ax.max) + "]";
            } else {
                limited[i] = *w;
            }
        }
        bestFree = std::min(bestFree, cost(unlimited));
        if (!within) {
            refusals += (refusals.empty() ? "" : "; ") + m.rotary[0].name + "=" + fmt(s.angles[0]) + " " +
                        m.rotary[1].name + "=" + fmt(s.angles[1]) + " (" + why + ")";
            continue;
        }
        const double c = cost(limited);
        if (c < bestCost) {
            bestCost = c;
            choice.angles = limited;
            choice.pole = s.free[0] || s.free[1];
        }
    }
    if (!std::isfinite(bestCost))
        throw inputError(axisText() + " is out of reach of machine " + m.name + ": " + refusals);
    choice.branchChange = bestCost > bestFree + 1e-6;
    return choice;
}

}  // namespace aeronc::kinematics
