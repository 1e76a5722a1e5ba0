// Choosing a chamfer mill for a chamfer or a countersink (see the header).
#include <aeronc/toolselect/EdgeTools.h>

#include <cmath>
#include <sstream>

namespace aeronc::toolselect {

namespace {

std::string mm(double v) {
    std::ostringstream s;
    s << std::round(v * 100) / 100;
    return s.str();
}

}  // namespace

double EdgeTool::coneSlope() const { return 1 / std::tan(includedAngle / 2 * M_PI / 180); }

ChamferPass chamferPass(const EdgeTool& tool) {
    return {tool.tipRadius() + kEdgeTipClearance, kEdgeTipClearance * tool.coneSlope()};
}

EdgeToolChoice chamferTool(const std::vector<EdgeTool>& tools, const EdgeNeed& need) {
    EdgeToolChoice out;
    int ofAngle = 0;
    for (const EdgeTool& t : tools) {
        if (t.kind != "chamfer" || !(std::fabs(t.includedAngle - need.includedAngle) <= kEdgeAngleTolerance)) continue;
        ++ofAngle;
        const ChamferPass p = chamferPass(t);
        if (p.offset + need.width > t.radius()) continue;
        if (need.holeDiameter > 0 && !(p.offset < need.holeDiameter / 2)) continue;
        if (t.reach < need.height + p.tipBelow) continue;
        if (!out.tool || t.diameter < out.tool->diameter || (t.diameter == out.tool->diameter && t.id < out.tool->id))
            out.tool = &t;
    }
    if (out.tool) return out;
    std::ostringstream why;
    why << "no chamfer mill of the crib fits it: it needs a " << mm(need.includedAngle)
        << " degree chamfer mill of diameter >= " << mm(2 * (need.width + kEdgeTipClearance))
        << " mm plus its tip";
    if (need.holeDiameter > 0) why << ", the tip below " << mm(need.holeDiameter - 2 * kEdgeTipClearance) << " mm";
    why << " (the crib has " << ofAngle << " chamfer mill(s) of that angle)";
    out.why = why.str();
    return out;
}

}  // namespace aeronc::toolselect
