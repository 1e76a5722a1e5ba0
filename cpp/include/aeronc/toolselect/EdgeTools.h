#pragma once
// Chamfer mills for the edges of elements (issue 26 §3): the knowledge base's edge tools, and
// the choice of one for a chamfer or a countersink (docs/edges.md).
//
// A chamfer mill is a flat tip of diameter tipDiameter under a cone of the included angle that
// widens to its diameter. It cuts a chamfer of the half angle when its axis runs at
// tipRadius + kEdgeTipClearance from the edge's lower line (the wall below the chamfer), its tip
// kEdgeTipClearance x coneSlope below that line: the cone then lies on the chamfer from its
// lower line up to the top, if the cone is wide enough there.
#include <string>
#include <vector>

namespace aeronc::toolselect {

// The tip's rim keeps this far off the wall below the chamfer, mm.
constexpr double kEdgeTipClearance = 0.2;
// An included angle matches the chamfer's within this many degrees.
constexpr double kEdgeAngleTolerance = 0.5;

struct EdgeTool {
    std::string id;
    std::string kind;  // "chamfer" or "corner_rounding"
    std::string material;
    double diameter = 0;        // largest diameter of the cutting edge
    double tipDiameter = 0;     // chamfer mill: flat tip; corner-rounding mill: pilot
    double includedAngle = 0;   // chamfer mill, degrees
    double profileRadius = 0;   // corner-rounding mill
    int flutes = 0;
    double reach = 0;
    // Finishing data for the part's material (the knowledge base's end-mill row of the tool's
    // diameter); 0: none.
    double spindleRpm = 0, feedMmMin = 0, plungeFeedMmMin = 0;

    double radius() const { return diameter / 2; }
    double tipRadius() const { return tipDiameter / 2; }
    // Rise of the cone per mm of radius: 1 / tan(half the included angle).
    double coneSlope() const;
};

// A chamfer to cut: the included angle of the mill it needs (twice the chamfer's angle to the
// tool axis), its width across the axis and its height along it; for a countersink, the
// diameter of the hole under it (the tip must pass inside).
struct EdgeNeed {
    double includedAngle = 0;
    double width = 0;
    double height = 0;
    double holeDiameter = 0;  // 0: not a hole
};

struct EdgeToolChoice {
    const EdgeTool* tool = nullptr;  // nullptr: none fits (see why)
    std::string why;
};

// Among the chamfer mills of the included angle (within kEdgeAngleTolerance), those whose cone
// covers the width (tipRadius + kEdgeTipClearance + width <= radius), whose tip passes inside
// the hole (tipRadius + kEdgeTipClearance < holeDiameter / 2) and whose reach is at least the
// depth the tip goes below the top: the smallest, then the first by id. Without one, `why`
// names what a mill would need.
EdgeToolChoice chamferTool(const std::vector<EdgeTool>& tools, const EdgeNeed& need);

// Where the pass runs: the axis at `offset` from the chamfer's lower line, the tip `tipBelow`
// below that line.
struct ChamferPass {
    double offset = 0;
    double tipBelow = 0;
};
ChamferPass chamferPass(const EdgeTool& tool);

}  // namespace aeronc::toolselect
