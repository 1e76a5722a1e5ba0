#pragma once
// Geometry-driven tool selection (DESIGN.md §3): finishing and roughing tools from the
// pocket shape, and merging of roughing-tool groups to save tool changes.
#include "PocketGeometry.h"
#include "Tool.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace aeronc::toolselect {

struct MachinableRatio {
    double eta = 0;             // machinableArea / area
    double area = 0;            // A, mm²
    double machinableArea = 0;  // A_m: the region eroded by r and swept back out by r
    // Pieces of the unreachable region that are more than corner leftovers: a passage
    // narrower than the tool (the reachable region splits or loses an island's way
    // round), a dead end, or a corner sharper than 60° that leaves material farther
    // than r from where the tool can go.
    int narrowPassages = 0;
};

// Throws aeronc::inputError for a degenerate pocket or a non-positive radius.
MachinableRatio machinableRatio(const PocketGeometry& pocket, double toolRadius);

// Largest end mill with radius <= minCornerRadius, corner radius <= floorFilletRadius
// (one equal to the fillet wins when there is one) and usable length >= depth.
// Throws aeronc::inputError naming the pocket and what a tool would need.
const Tool* finishingTool(const PocketGeometry& pocket, const std::vector<Tool>& tools);

// From the largest diameter down, the first end mill reaching the depth with
// eta >= etaThreshold. `ratio`, when given, receives that tool's full MachinableRatio.
// Throws aeronc::inputError when none qualifies.
const Tool* roughingTool(const PocketGeometry& pocket, const std::vector<Tool>& tools,
                         double etaThreshold, MachinableRatio* ratio = nullptr);

// Cutting data of one tool for the time model.
struct CuttingData {
    double ae = 0;             // w: radial width of cut, mm
    double feedPerMinute = 0;  // f·n, mm/min
    double ap = 0;             // axial depth per layer, mm
    double delta = 0;          // a remainder thinner than this needs no extra layer, mm
};

// T = t·N minutes, t = A / (w·f·n), N = nn if H − a_p·nn < δ else nn + 1, nn = int(H / a_p).
double unitTime(double area, double depth, const CuttingData& data);

struct MachiningUnit {
    double area = 0;   // mm²
    double depth = 0;  // H, mm
};

struct ToolGroup {
    std::size_t tool = 0;  // index into the tool list
    std::vector<MachiningUnit> units;
};

struct MergeReport {
    int toolChangesBefore = 0, toolChangesAfter = 0;  // groups − 1
    double timeBefore = 0, timeAfter = 0;             // minutes, cutting only
    struct Step {
        std::size_t keptTool, droppedTool;
        double mu;
    };
    std::vector<Step> merges;  // in the order they were made
};

using CuttingDataOf = std::function<CuttingData(std::size_t toolIndex)>;

// Repeatedly merges the pair of groups with the largest
// mu = (ΣT_i + ΣT_j) / ΣT_k (T_k: every unit of both timed with the smaller tool)
// onto the smaller tool while mu > muThreshold and the smaller tool reaches every
// unit's depth.
std::vector<ToolGroup> mergeGroups(std::vector<ToolGroup> groups, const std::vector<Tool>& tools,
                                   double muThreshold, const CuttingDataOf& cuttingDataOf,
                                   MergeReport* report = nullptr);

}  // namespace aeronc::toolselect
