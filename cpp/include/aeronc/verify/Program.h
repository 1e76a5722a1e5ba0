#pragma once
// What the verification simulates: the blank, then operations as lists of tool-tip moves in
// world coordinates, and which faces the plan says are finished.
#include <aeronc/verify/Cutter.h>

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace aeronc::verify {

enum class MoveKind { Rapid = 0, Feed = 1, Plunge = 2, DrillCycle = 3 };

struct Move {
    MoveKind kind = MoveKind::Feed;
    double x = 0, y = 0, z = 0;   // the tip; for a drill cycle, the hole's bottom
    double retract = 0;           // drill cycle: the R plane
    double peck = 0, dwell = 0;   // drill cycle: kept for the record; they change no material
};

struct Operation {
    std::string label;
    int axis = 1;  // +1: tool axis +Z (cuts from above); -1: tool axis -Z (cuts from below)
    Cutter cutter;
    double radialAllowance = 0, axialAllowance = 0;  // the material the operation must leave
    std::vector<Move> moves;
};

struct Program {
    double cellSize = 0.5;
    bool hasBlank = false;
    std::array<double, 6> blank{};  // xmin, ymin, zmin, xmax, ymax, zmax
    std::vector<Operation> operations;
    std::vector<int> finishedFaces;
    std::vector<std::pair<std::string, std::vector<int>>> elements;  // element id -> its faces
};

// A straight piece of tool motion; a drill cycle expands into several.
struct Segment {
    std::array<double, 3> from{}, to{};
    bool rapid = false;
    int move = 0;  // index of the move it comes from in the operation
};

// The operation's moves as segments. The first move starts where it ends (a tool that arrives
// there from out of the part); a drill cycle [x, y, bottom, R] is a rapid to (x, y) at the
// current height, a rapid to R, a feed to the bottom and a rapid back to R.
std::vector<Segment> segmentsOf(const Operation& op);

// The JSON contract of docs/verification.md ("cellSize", "blank", "ops", "finishedFaces",
// "elements"). Throws aeronc::Error (input) naming the offending entry.
Program programFromJson(const nlohmann::json& j);

}  // namespace aeronc::verify
