#pragma once
// From a CL program to machine motion: inverse kinematics of every move with continuity of
// the rotary axes, retract / reposition / re-enter where the limits force a branch change,
// approach moves of drilling cycles, optional linearisation of arcs, and the split of each
// operation into segments: constant tool axis (3+2 indexed, or 3-axis when vertical) or
// simultaneous 5-axis.
#include <aeronc/kinematics/ClProgram.h>
#include <aeronc/kinematics/Kinematics.h>

#include <optional>

namespace aeronc::kinematics {

struct PlanOptions {
    std::optional<Vec3> partZero;          // overrides the machine file
    std::optional<double> retractDistance;  // overrides the machine file
    bool linearizeSimultaneousArcs = false;  // arcs inside simultaneous segments become lines
    double chordTolerance = 0.001;           // mm, for that linearisation
};

// Why a planned move exists: the input's own move, or one the planner added.
enum class MoveOrigin { Input, Retract, Reposition, ReEnter, ArcPoint, CycleApproach };

enum class SegmentMode { Plane, Simultaneous };

struct Segment {
    SegmentMode mode = SegmentMode::Plane;
    int op = -1;
    Vec3 axis = Vec3::UnitZ();               // Plane: the constant tool axis
    std::array<double, 2> rotary{0.0, 0.0};  // Plane: the chosen rotary angles
    std::optional<std::array<double, 2>> otherRotary;  // Plane: the other solution, if any
};

struct PlannedStep {
    int record = -1;  // the CL record this step comes from (added moves: the move that caused them)
    ClKind kind = ClKind::Comment;
    MoveOrigin origin = MoveOrigin::Input;
    Motion motion = Motion::Rapid;
    ToolPose pose;                 // end of the move; Cycle: the hole bottom
    Vec3 centre = Vec3::Zero();   // arcs
    std::array<bool, 3> known{true, true, true};
    Joints joints;                 // machine axes at the end of the move (Cycle: at the bottom)
    double feed = 0.0;             // mm/min
    double minutes = 0.0;          // duration at the programmed feed (feed moves)
    bool rotaryMoved = false;
    int segment = -1;              // moves and cycles
    bool tipKnown() const { return known[0] && known[1] && known[2]; }
};

struct Plan {
    const ClProgram* program = nullptr;
    MachineModel machine;
    std::vector<PlannedStep> steps;
    std::vector<Segment> segments;
    int branchChanges = 0;  // retract / reposition / re-enter sequences inserted
};

// Errors name the operation and the move (ClProgram::where).
Plan planProgram(const ClProgram& program, const MachineModel& machine, const PlanOptions& options);

}  // namespace aeronc::kinematics
