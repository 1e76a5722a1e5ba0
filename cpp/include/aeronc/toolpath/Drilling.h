#pragma once
// Drilling: one canned cycle per hole (G81 plain, G82 with dwell, G83 with pecking).
#include <aeronc/toolpath/Hole.h>

namespace aeronc::toolpath {

struct DrillParameters {
    std::optional<double> safeHeight;     // absolute h where the unit starts and ends
    double clearance = 2;                 // above the highest top: the plane of the moves between holes
    std::optional<double> retractHeight;  // absolute R plane; each hole's top + clearance if unset
    double peck = 0;                      // mm per peck, 0: no pecking
    double dwell = 0;                     // s at the bottom
    double pointAngleDeg = 118;           // a through hole adds the tip length (D/2) / tan(angle/2)
    double breakThrough = 0.5;            // below the tip's full diameter for a through hole
};

// The holes in the order given (the machining chain orders them).
Toolpath drilling(const std::vector<Hole>& holes, const Cutter& drill, const DrillParameters& parameters);

// The length of a drill's conical tip: 0.30 D for 118 degrees.
double drillTipLength(double diameter, double pointAngleDeg);

}  // namespace aeronc::toolpath
