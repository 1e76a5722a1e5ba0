#pragma once
// Fusing the process template with the machining domains (the patent's step 2): each step's
// tool is matched to the domain elements by height, minimum width, side fillet and floor
// fillet; its machinable region for the step's allowances decides rest machining; each
// match becomes a machining unit under its tool. buildChain then orders the units
// (Sequencing.h), arranges the seven-level tree and checks the construction rules
// (ConstructionRules.h).
#include <aeronc/chain/MachiningChain.h>
#include <aeronc/recognition/DomainTree.h>
#include <aeronc/toolselect/EdgeTools.h>
#include <aeronc/toolselect/ElementPlanning.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <limits>
#include <string>

namespace aeronc::chain {

// Cutting data of a tool (an index into ToolPlan::tools) for "roughing", "finishing" or
// "drilling"; nullopt when there is none for the workpiece material.
using ToolSettingOf =
    std::function<std::optional<toolselect::ToolSetting>(std::size_t tool, const std::string& operation)>;

struct ChainOptions {
    std::string material;
    std::string machine;
    double breakthrough = 1.0;   // openings and through holes are cut this far past the part, mm
    double restMinArea = 0.5;    // a rest unit when the roughing tool leaves more than this, mm²
    double helixMinRatio = 0.5;  // helical interpolation: end-mill diameter / hole diameter from ...
    double helixMaxRatio = 0.8;  // ... to; below half the hole the helix clears it in rings
    double floorScallop = 0.01;  // a floor (web) pass leaves scallops at most this high, mm
    // A unit's radial allowance is at most this times its tool's diameter: a 1 mm end mill cannot
    // leave the 1 mm a roughing step asks for in a groove it just fits (engraving). Below it, every
    // step's allowance is scaled alike (ElementTools::allowanceOf).
    double allowanceRatio = std::numeric_limits<double>::infinity();
    // The chamfer mills the edge step may use, with their cutting data (docs/edges.md); none:
    // chamfers and countersinks are listed, not cut.
    std::vector<toolselect::EdgeTool> edgeTools;
    bool optimiseTravel = true;
    bool listCandidateTools = true;  // also list the tools the chain could use instead (for editing)
};

// The units of every element (unordered: `order` is empty) and what could not be machined.
// Throws aeronc::inputError for an invalid template or a tree with no domain element.
MachiningChain fuse(const recognition::DomainTree& tree, const toolselect::ToolPlan& plan,
                    const ProcessTemplate& processTemplate, const ChainOptions& options,
                    const ToolSettingOf& settingOf = {});

// fuse(), then the sequencing rules and travel optimisation, the seven-level tree, and the
// construction-rule checks. Without settingOf the plan's own settings are used.
MachiningChain buildChain(const recognition::DomainTree& tree, const toolselect::ToolPlan& plan,
                          const ProcessTemplate& processTemplate, const ChainOptions& options,
                          const ToolSettingOf& settingOf = {});

// The widest step-over of passes of a cutter (corner radius r) over a flat floor that leaves
// scallops at most `scallop` high: the flat bottom's width 2 (R - r), and where the corners of
// neighbouring passes meet, the chord of the corner arc at that height, 2 sqrt(r^2 - (r - h)^2).
double floorStepOver(double diameter, double cornerRadius, double scallop);

// The feature type a template step names for an element: hole, opening, flange (a pocket
// carrying a flange), open_pocket or closed_pocket.
std::string featureTypeOf(const recognition::DomainElement& element);

}  // namespace aeronc::chain
