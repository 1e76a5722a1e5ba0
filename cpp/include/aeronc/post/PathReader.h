#pragma once
// Reads FreeCAD Path commands, as Path.toGCode() writes them, into a CL program, applying
// AeroNC's orientation convention (docs/post.md):
//   - U V W on a move or drilling command: the unit tool axis (tip -> spindle) in the Job's
//     workpiece frame; all three or none; modal within an operation; +Z at the start of each
//     operation, so FreeCAD's own 3-axis operations post unchanged.
//   - G2/G3 under a tool axis: centre = start + (I, J, K), in the plane normal to the axis.
//   - G81/G82/G83/G73 under a tool axis: (X, Y, Z) is the hole bottom; R - Z is the distance
//     from the bottom to the R level along the axis.
// F is FreeCAD's mm/s and becomes mm/min. Anything that does not fit is an error naming the
// operation, the command number and the command.
#include <aeronc/kinematics/ClProgram.h>

namespace aeronc::post {

// One object of the post's object list, already taken apart by the Python side.
struct PathSection {
    enum class Kind { WorkOffset, ToolChange, Operation };
    Kind kind = Kind::Operation;
    std::string label;
    std::string gcode;        // Path.toGCode() of the object (WorkOffset, Operation)
    kinematics::ClTool tool;  // ToolChange
    double rpm = 0.0;         // ToolChange
    int spindleDir = 0;       // ToolChange
    std::string coolant;      // Operation: "none", "flood", "mist"
    bool hasToolController = true;  // Operation: false when the operation has none
};

kinematics::ClProgram readFreeCadPath(const std::vector<PathSection>& sections, const std::string& programName);

// Tolerance on |(U,V,W)| - 1. FreeCAD keeps 6 decimals of each parameter, so a unit vector
// comes back off by up to ~1e-6; anything further off is a wrong vector, not rounding.
constexpr double kUnitTolerance = 1e-4;

}  // namespace aeronc::post
