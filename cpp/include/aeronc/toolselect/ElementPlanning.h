#pragma once
// Tool selection for a whole recognised part (DESIGN.md §3): every pocket, open pocket and
// opening of a machining-domain tree gets a finishing and a roughing tool, every hole a
// drill; the roughing-tool groups are then merged to save tool changes.
//
// The planner never stops at the first element it cannot serve: each element carries its
// own error text and the rest are still planned.
#include <aeronc/recognition/DomainTree.h>
#include <aeronc/toolselect/PocketGeometry.h>
#include <aeronc/toolselect/Selection.h>
#include <aeronc/toolselect/Tool.h>

#include <functional>
#include <string>
#include <vector>

namespace aeronc::toolselect {

// The element's drive loops projected onto its setup plane (frame built from the setup
// direction as recognition does), with its depth, corner and floor-fillet radii and the name
// "element <id>". Throws aeronc::inputError for a zero setup direction.
PocketGeometry pocketGeometry(const recognition::DomainElement& element, const Vec3& setupDirection);

// A pocket, open pocket or opening: the elements that are milled.
bool isMilled(recognition::ElementType type);

struct ElementChoice {
    int element = -1;
    recognition::ElementType type = recognition::ElementType::ClosedPocket;
    int finishingTool = -1;  // index into the tool list; -1: none (see error)
    int roughingTool = -1;   // index into the tool list; -1: none (see error)
    MachinableRatio ratio;   // of the roughing tool, when there is one
    double depth = 0;
    std::string error;       // empty when both tools were found; else one line per failure
    // No end mill reaches the depth: the roughing tool for the depth the crib's longest end mill
    // reaches (the region is roughed that far down and the rest listed); -1: none.
    int partialRoughingTool = -1;
    double partialDepth = 0;
};

struct HoleChoice {
    int element = -1;
    double diameter = 0;
    double depth = 0;
    int drill = -1;  // index into the tool list; -1: none (see error)
    std::string error;
};

struct GroupElements {
    int tool = -1;              // index into the tool list
    std::vector<int> elements;  // element ids roughed with it
};

struct PlanSettings {
    double etaMin = 0.85;
    double muMerge = 0.70;
    // Roughing cutting data of a tool (index into the tool list), for the time model.
    CuttingDataOf roughingData;
    // Optional filters: may this tool finish / rough / drill this part? Empty: every tool may.
    std::function<bool(const Tool&)> mayFinish, mayRough, mayDrill;
};

// Spindle speed and feeds of one tool in one operation; what a FreeCAD ToolController
// carries. The knowledge-base planner (kb/ToolPlanning.h) fills them.
struct ToolSetting {
    int tool = -1;          // index into the tool list
    std::string operation;  // "roughing", "finishing", "drilling"
    double spindleRpm = 0;  // n = 1000·v_c/(π·D), capped at the machine's maximum
    double feedMmMin = 0;   // horizontal: f_z·Z·n
    double plungeFeedMmMin = 0;  // vertical: the horizontal feed × plunge_feed_ratio; drilling: f_z·Z·n
    double vc = 0, fz = 0, ap = 0, ae = 0;
};

struct ToolPlan {
    std::vector<Tool> tools;  // the list the indices refer to
    std::vector<ToolSetting> settings;  // per (tool, operation) used; filled by kb::planTools
    std::vector<ElementChoice> elements;
    std::vector<HoleChoice> holes;
    std::vector<GroupElements> groupsBefore, groupsAfter;  // roughing groups, before/after merging
    MergeReport merge;
};

// Plans every element of `tree` with `tools`. Elements without a roughing tool take no part
// in the grouping. Throws only for bad settings (an empty roughingData with groups to time).
ToolPlan planTools(const recognition::DomainTree& tree, const std::vector<Tool>& tools,
                   const PlanSettings& settings);

// Roughing cutting data of one tool from a knowledge-base cutting condition; n is capped at
// maxSpindleRpm when that is positive.
CuttingData roughingCuttingData(const Tool& tool, double vc, double fz, double ap, double aeRatio, double delta,
                                double maxSpindleRpm = 0);

}  // namespace aeronc::toolselect
