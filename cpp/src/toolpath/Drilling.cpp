#include <aeronc/toolpath/Drilling.h>

#include "HoleChecks.h"
#include "MoveWriter.h"
#include "Validate.h"

#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>

namespace aeronc::toolpath {

double drillTipLength(double diameter, double pointAngleDeg) {
    return diameter / 2 / std::tan(pointAngleDeg / 2 * M_PI / 180);
}

Toolpath drilling(const std::vector<Hole>& holes, const Cutter& drill, const DrillParameters& p) {
    checkHoles(holes);
    checkCutter(drill, "the drill");
    requireFinite(p.clearance, "clearance");
    requireFinite(p.peck, "peck");
    requireFinite(p.dwell, "dwell");
    requireFinite(p.pointAngleDeg, "pointAngle");
    requireFinite(p.breakThrough, "breakThrough");
    if (p.safeHeight) requireFinite(*p.safeHeight, "safeHeight");
    if (p.retractHeight) requireFinite(*p.retractHeight, "retractHeight");
    if (!(p.clearance > 0)) throw inputError("clearance must be positive");
    if (p.peck < 0 || p.dwell < 0 || p.breakThrough < 0) throw inputError("peck, dwell and breakThrough must be at least 0");
    if (!(p.pointAngleDeg > 0 && p.pointAngleDeg < 180)) throw inputError("pointAngle must lie in (0, 180) degrees");
    double top = holes.front().top;
    for (const Hole& h : holes) top = std::max(top, h.top);
    const double plane = std::max(top + p.clearance, p.retractHeight ? *p.retractHeight : top);
    const double safe = p.safeHeight ? *p.safeHeight : plane;
    if (safe < plane - 1e-9) throw inputError("safeHeight lies below the plane of the moves between holes");
    const double tip = drillTipLength(drill.diameter, p.pointAngleDeg);

    Toolpath tp;
    MoveWriter w(tp);
    for (std::size_t i = 0; i < holes.size(); ++i) {
        const Hole& h = holes[i];
        const std::string what = "hole " + std::to_string(i + 1);
        const double r = p.retractHeight ? *p.retractHeight : h.top + p.clearance;
        if (r < h.top) throw inputError(what + ": retractHeight lies below the hole's top");
        const double z = h.through ? h.bottom - tip - p.breakThrough : h.bottom;
        if (p.peck > 0 && (r - z) / p.peck > 1e5) throw inputError(what + ": more than 10^5 pecks");
        if (!w.started()) w.rapid(h.centre[0], h.centre[1], safe);
        w.rapidOver(h.centre, plane, plane);
        w.drill(h.centre[0], h.centre[1], z, r, p.peck, p.dwell);
    }
    w.retract(safe);
    return tp;
}

}  // namespace aeronc::toolpath
