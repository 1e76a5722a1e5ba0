#pragma once
// A cutter-location (CL) program: the tool tip and tool axis of every move in the workpiece
// frame, with tools, spindle, coolant and drilling cycles. Both inputs of the posts produce it
// (FreeCAD's Path commands and APT CL files) and both NC dialects are written from it.
#include <aeronc/kinematics/Types.h>

#include <string>
#include <vector>

namespace aeronc::kinematics {

enum class ClKind { Comment, Operation, WorkOffset, LoadTool, Spindle, Coolant, Move, Cycle, Dwell, Stop };
enum class Motion { Rapid, Linear, ArcCW, ArcCCW };
// Drilling cycles: G81 (drill), G82 (drill, dwell at the bottom), G83 (peck, full retract),
// G73 (peck, chip break).
enum class CycleKind { Drill, DrillDwell, Peck, ChipBreak };

struct ClTool {
    int number = 0;
    std::string name;
    double diameter = 0.0;
    double cornerRadius = 0.0;
    double length = 0.0;  // gauge point to tip; matters on head machines
};

struct ClRecord {
    ClKind kind = ClKind::Comment;
    int op = -1;    // index into ClProgram::operations (-1: before the first operation)
    int line = 0;   // 1-based: command number in the operation's Path, or line of the APT file

    // Move: the end of the move. Cycle: the hole bottom. Arc: `centre` lies in the plane through
    // the start normal to `axis`; ArcCW turns clockwise seen from the spindle (looking along -axis).
    Motion motion = Motion::Rapid;
    Vec3 tip = Vec3::Zero();
    Vec3 axis = Vec3::UnitZ();
    Vec3 centre = Vec3::Zero();
    // FreeCAD's first moves often give only Z: which tip coordinates are known.
    std::array<bool, 3> known{true, true, true};
    double feed = 0.0;  // mm/min (Linear, arcs, Cycle)

    // Cycle: distances along the axis from the bottom to the R level (rapid down to it, feed
    // below it) and to the level the tool returns to; peck depth; dwell at the bottom (s).
    CycleKind cycle = CycleKind::Drill;
    double retract = 0.0, clearance = 0.0, peck = 0.0;

    std::string text;        // Comment, Operation label, WorkOffset ("G54"), Coolant ("flood", "mist", "off"),
                             // LoadTool and Spindle from a tool controller: its label
    ClTool tool;             // LoadTool
    double rpm = 0.0;        // Spindle
    int spindleDir = 0;      // Spindle: +1 clockwise (M3), -1 counter-clockwise (M4), 0 stop
    double seconds = 0.0;    // Dwell; Cycle dwell at the bottom

    bool tipKnown() const { return known[0] && known[1] && known[2]; }
};

struct ClOperation {
    std::string label;
};

struct ClProgram {
    std::string name;
    std::vector<ClOperation> operations;
    std::vector<ClRecord> records;

    // "operation 'Pocket', move 17" or "APT line 17": where a record came from, for messages.
    std::string where(const ClRecord& r) const;
    bool fromApt = false;
};

}  // namespace aeronc::kinematics
