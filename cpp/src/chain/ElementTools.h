#pragma once
// The tool of a template step on a domain element, for fusing (Fusing.cpp): the tool plan's
// choices (the roughing group's tool, the element's finishing tool, the hole's drill), checked
// against what the step needs (reach, corner radius, narrowest width, floor fillet), and the
// plan's best other tool where they do not fit.
#include <aeronc/chain/Fusing.h>
#include <aeronc/recognition/SetupFrame.h>
#include <aeronc/toolselect/PocketGeometry.h>

#include <algorithm>
#include <limits>
#include <map>
#include <string>

namespace aeronc::chain::detail {

constexpr double kTol = 1e-3;  // mm: dimensions compared on recognised geometry
constexpr double kInf = std::numeric_limits<double>::infinity();

// A length for messages, to the micrometre.
std::string fmt(double x);

// "element <id> (<feature type>)", for messages.
std::string elementName(const recognition::DomainElement& e);

// What an element's tools may leave where no tool of the crib fits: its concave vertical
// corners (a wall tool wider than their radius) or its floor fillet (a floor tool with a larger
// corner radius). The chain lists what they leave (Remainder).
struct Leaves {
    bool corners = false, fillet = false;
};

class ElementTools {
public:
    // The radial allowance a unit of `step` with tool `t` leaves in element `e`: the step's own,
    // or, for a tool too small to leave the template's largest allowance (ChainOptions::
    // allowanceRatio of its diameter), every step's scaled down alike, so each step still leaves
    // less than the one before (a cap alone would give a micro tool's steps one allowance, and
    // the later ones would cut nothing). In a closed groove wider than the tool but narrower than
    // it with its finishing allowances (engraved strokes), the finishing steps are scaled down
    // alike to a quarter of the room the width leaves, so the floor pass's centre line stays inside.
    double allowanceOf(const TemplateStep& step, const toolselect::Tool& t,
                       const recognition::DomainElement* e = nullptr) const;
    // settingOf: the cutting data of a tool; empty: the plan's own settings.
    ElementTools(const recognition::DomainTree& tree, const toolselect::ToolPlan& plan, const ProcessTemplate& t,
                 const ChainOptions& o, ToolSettingOf settingOf);

    ElementTools(const ElementTools&) = delete;  // its default settings refer to it
    ElementTools& operator=(const ElementTools&) = delete;

    void addSetup(int id, const recognition::SetupFrame& frame, const Vec3& direction);
    bool hasSetup(int id) const { return frames_.count(id) > 0; }
    const recognition::SetupFrame& frameOf(int setup) const { return frames_.at(setup); }
    const Vec3& direction(int setup) const { return directions_.at(setup); }
    const recognition::DomainElement* element(int id) const;  // null for an unknown id

    const toolselect::Tool& tool(int i) const { return plan_.tools.at(static_cast<std::size_t>(i)); }
    std::optional<toolselect::ToolSetting> setting(std::size_t tool, const std::string& operation) const {
        return settingOf_(tool, operation);
    }
    bool hasSetting(int i, const char* op) const { return settingOf_(static_cast<std::size_t>(i), op).has_value(); }
    // The plan's choice for a milled element or a hole; null when it has none.
    const toolselect::ElementChoice* choice(int element) const;
    const toolselect::HoleChoice* holeChoice(int element) const;

    // The parent's floor bounds a child's unit from above: the cavity over it is the parent's.
    double unitTop(const recognition::DomainElement& e, double axialAllowance) const;
    double bottomOf(const recognition::DomainElement& e) const;

    // What the tools chosen for `e` leave (none until finisher or floorTool gave way).
    Leaves leaves(int element) const {
        const auto it = leaves_.find(element);
        return it == leaves_.end() ? Leaves{} : it->second;
    }

    // Why `t` cannot do `step` on `e` down to `bottom`; empty when it can. `leave` waives the
    // corner or floor-fillet check.
    std::string mismatch(const toolselect::Tool& t, const recognition::DomainElement& e, const TemplateStep& step,
                         Operation op, double bottom, Leaves leave = Leaves{}) const;

    int plannedRoughingTool(const recognition::DomainElement& e) const;
    // The planned roughing tool; for a pocket open to the blank, the finishing tool when that is
    // wider: the tool comes in from the open side, so the narrow width that chose a small
    // roughing tool does not bind it.
    int roughingTool(const recognition::DomainElement& e) const;
    // Whether roughing tool `r`, grown by the rough step's radial allowance (and by what a floor
    // fillet larger than its corner adds, as the toolpath offsets it), leaves a region for its
    // centre in the closed element; open pockets are entered from their open side.
    bool roughingReaches(const recognition::DomainElement& e, int r) const;
    // The element's one finishing tool for all its finishing steps; -1 with the reason in `why`.
    int finisher(const recognition::DomainElement& e, std::string& why);
    int floorTool(const recognition::DomainElement& e, const TemplateStep& step, std::string& why);
    int widestFloorTool(const recognition::DomainElement& e, const TemplateStep& step) const;
    int helixTool(const recognition::DomainElement& e, std::string& why) const;
    // The planner's reason for a missing tool; for a pocket, the lines about roughing tools
    // (`roughing`) or the others.
    std::string planError(const recognition::DomainElement& e, bool roughing = false) const;

private:
    bool millingData(int i) const { return hasSetting(i, "roughing") || hasSetting(i, "finishing"); }
    int roughingToolWithAllowance(const recognition::DomainElement& e, int r, double ar) const;
    bool reachesWith(const toolselect::PocketGeometry& g, const recognition::DomainElement& e,
                     const toolselect::Tool& t, double ar) const;
    double roughingAllowance() const;
    int finishingTool(const recognition::DomainElement& e, std::string& why) const;

    const toolselect::ToolPlan& plan_;
    const ProcessTemplate& tmpl_;
    const ChainOptions& opt_;
    ToolSettingOf settingOf_;
    std::map<int, const recognition::DomainElement*> byId_;
    std::map<int, const toolselect::ElementChoice*> choice_;
    std::map<int, const toolselect::HoleChoice*> holeChoice_;
    std::map<int, int> groupTool_;
    std::map<int, recognition::SetupFrame> frames_;
    std::map<int, Vec3> directions_;
    mutable std::map<int, int> roughWithAllowance_;         // element -> roughing tool fitted to the allowance
    std::map<int, std::pair<int, std::string>> finishers_;  // element -> tool and why none
    std::map<int, Leaves> leaves_;                          // element -> what its tools leave
};

}  // namespace aeronc::chain::detail
