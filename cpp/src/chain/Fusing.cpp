// Fusing the process template with the machining domains: each step of the template, element
// by element, becomes units under the tool ElementTools picks (see the header).
#include <aeronc/chain/ConstructionRules.h>
#include <aeronc/chain/Fusing.h>
#include <aeronc/chain/Sequencing.h>
#include <aeronc/core/Error.h>
#include <aeronc/recognition/SetupFrame.h>
#include <aeronc/toolselect/Selection.h>

#include "ElementTools.h"
#include "UnitOutline.h"
#include "Unmachined.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace aeronc::chain {

using recognition::DomainElement;
using recognition::DomainTree;
using recognition::ElementType;
using toolselect::Tool;
using toolselect::ToolPlan;
using namespace detail;

namespace {

ChainTool chainTool(const Tool& t) {
    ChainTool c;
    c.id = t.id;
    c.type = t.type;
    c.material = t.material;
    c.diameter = t.diameter;
    c.cornerRadius = t.cornerRadius;
    c.fluteLength = t.fluteLength;
    c.reach = t.reach;
    c.neckDiameter = t.neckDiameter;
    c.flutes = t.flutes;
    return c;
}

ToolData toolData(const toolselect::ToolSetting& s) {
    return {s.spindleRpm, s.feedMmMin, s.plungeFeedMmMin, s.ap, s.ae};
}

class Fuser {
public:
    Fuser(const DomainTree& tree, const ToolPlan& plan, const ProcessTemplate& t, const ChainOptions& o,
          ToolSettingOf settingOf)
        : tree_(tree), plan_(plan), tmpl_(t), opt_(o), tools_(tree, plan, t, o, std::move(settingOf)) {}

    MachiningChain run();

private:
    void preorder(int id, std::vector<const DomainElement*>& out) const {
        const DomainElement* e = tools_.element(id);
        if (!e) return;
        out.push_back(e);
        for (int c : e->children) preorder(c, out);
    }

    MachiningUnit& addUnit(const DomainElement& e, const TemplateStep& step, Operation op, int toolIndex, double top,
                           double bottom);
    void makeUnits(const DomainElement& e, const TemplateStep& step);
    void makeEdgeUnits(const DomainElement& e);
    void leaveCorners(const DomainElement& e, const MachiningUnit& u);
    void leaveFillet(const DomainElement& e, const MachiningUnit& u);
    Remainder& remainderOf(const DomainElement& e, const char* kind);
    MachiningUnit& addEdgeUnit(const DomainElement& e, const toolselect::EdgeTool& t, double top, double bottom,
                               double offset);

    const DomainTree& tree_;
    const ToolPlan& plan_;
    const ProcessTemplate& tmpl_;
    const ChainOptions& opt_;
    ElementTools tools_;
    std::map<int, ElementState> state_;
    std::set<int> usedTools_;
    std::set<std::string> usedEdgeTools_;
    std::set<int> facedTops_;  // island-top faces a floor unit faces
    MachiningChain chain_;
};

MachiningUnit& Fuser::addUnit(const DomainElement& e, const TemplateStep& step, Operation op, int toolIndex,
                              double top, double bottom) {
    const recognition::SetupFrame& frame = tools_.frameOf(e.setup);
    const Tool& t = tools_.tool(toolIndex);
    MachiningUnit u;
    u.id = static_cast<int>(chain_.units.size());
    u.setup = e.setup;
    u.element = e.id;
    u.step = step.code;
    u.operation = op;
    u.featureType = featureTypeOf(e);
    u.tool = t.id;
    u.cutter = {t.diameter, t.cornerRadius, t.type};
    u.top = top;
    u.bottom = bottom;
    // Through an opening a rounded corner must pass the wall's lower edge whole, or it leaves
    // the corner's profile on the wall: the finishing passes go that much deeper, as far as
    // the tool reaches.
    if (e.type == ElementType::Opening && op == Operation::Profile)
        u.bottom = std::max(bottom - t.cornerRadius, std::min(u.bottom, top - t.usableLength()));
    const bool floorless = e.type == ElementType::Opening || e.type == ElementType::Hole;
    u.radialAllowance = tools_.allowanceOf(step, t, &e);
    u.axialAllowance = floorless ? 0.0 : step.axialAllowance;
    u.floorFilletRadius = floorless ? 0.0 : std::max(0.0, e.floorFilletRadius);

    const char* op0 = settingOperation(step.code);
    std::optional<toolselect::ToolSetting> s = tools_.setting(static_cast<std::size_t>(toolIndex), op0);
    if (!s && op != Operation::Drill)
        s = tools_.setting(static_cast<std::size_t>(toolIndex), std::string(op0) == "roughing" ? "finishing" : "roughing");
    if (s) {
        u.setting = {s->spindleRpm, s->feedMmMin, s->plungeFeedMmMin};
        // A layer no higher than the flutes: a necked tool's neck cuts nothing.
        u.stepDown = std::min(s->ap, t.passHeight());
        u.stepOver = s->ae;
    } else {
        u.note = "no cutting data for tool " + t.id + " in " + opt_.material;
    }

    outlineUnit(u, e, frame, tools_.unitTop(e, 0.0), top, bottom);
    usedTools_.insert(toolIndex);
    chain_.units.push_back(std::move(u));
    ++state_[e.id].units;
    state_[e.id].steps.insert(step.code);
    return chain_.units.back();
}

Remainder& Fuser::remainderOf(const DomainElement& e, const char* kind) {
    for (Remainder& r : chain_.remainders)
        if (r.element == e.id && r.kind == kind) return r;
    Remainder r;
    r.element = e.id;
    r.kind = kind;
    chain_.remainders.push_back(r);
    return chain_.remainders.back();
}

// The wall tool is wider than the element's corners and no tool of the crib that reaches fits
// them: what it leaves in plan (the region no disc of its radius inside the outline reaches),
// the wall's height, and the tool they would need. The last wall step's tool counts.
void Fuser::leaveCorners(const DomainElement& e, const MachiningUnit& u) {
    const double radius = 0.5 * u.cutter.diameter;
    double area = 0;
    try {
        const auto m = toolselect::machinableRatio(toolselect::pocketGeometry(e, tools_.direction(e.setup)), radius);
        area = std::max(0.0, m.area - m.machinableArea);
    } catch (const Error&) {
        area = std::numeric_limits<double>::quiet_NaN();  // not measured: said as such (null in JSON)
    }
    Remainder& r = remainderOf(e, "corners");
    r.step = u.step;
    r.tool = u.tool;
    r.toolRadius = radius;
    r.area = area;
    r.depth = tools_.unitTop(e, 0.0) - e.level;
    const double need = std::max(0.0, e.minCornerRadius);
    r.needs = need <= kTol ? "a radius in the part, or another process: the corners are sharp and no end mill cuts them"
                           : "an end mill of radius <= " + fmt(need) + " mm reaching " + fmt(r.depth) + " mm";
}

// The floor tool's corner radius is larger than the floor fillet and no end mill whose corner
// fits reaches the floor: a band along the floor's walls (the open edges have none) as wide as
// the difference of the radii is left on the fillet.
void Fuser::leaveFillet(const DomainElement& e, const MachiningUnit& u) {
    auto loopLength = [](const std::vector<std::array<double, 2>>& loop) {
        double l = 0;
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const auto& a = loop[i];
            const auto& b = loop[(i + 1) % loop.size()];
            l += std::hypot(b[0] - a[0], b[1] - a[1]);
        }
        return l;
    };
    double walls = loopLength(u.contour);
    for (const auto& isl : u.islands) walls += loopLength(isl);
    for (const auto& oe : u.openEdges) walls -= std::hypot(oe[1][0] - oe[0][0], oe[1][1] - oe[0][1]);
    const double fillet = std::max(0.0, e.floorFilletRadius);
    Remainder& r = remainderOf(e, "floor_fillet");
    r.step = u.step;
    r.tool = u.tool;
    r.toolRadius = u.cutter.cornerRadius;
    r.depth = u.cutter.cornerRadius - fillet;
    r.area = std::max(0.0, walls) * r.depth;
    r.needs = "an end mill with a corner radius <= " + fmt(fillet) + " mm reaching the " + fmt(e.top - e.level) +
              " mm deep floor";
}

void Fuser::makeUnits(const DomainElement& e, const TemplateStep& step) {
    ElementState& st = state_[e.id];
    auto gap = [&](const std::string& why) {
        if (!st.gaps.count(step.code)) st.gaps[step.code] = why;
    };
    const double ar = step.radialAllowance;

    if (e.type == ElementType::Hole) {
        if (!e.hole || !(e.hole->diameter > 0)) {
            gap("hole element " + std::to_string(e.id) + ": no diameter was recognised");
            return;
        }
        const recognition::HoleInfo& h = *e.hole;
        const double top = tools_.frameOf(e.setup).height(h.location);
        const double bottom = top - h.depth - (h.through ? opt_.breakthrough : 0);
        if (st.holeMachined) return;
        if (h.overhung) {
            gap("hole element " + std::to_string(e.id) + " (diameter " + fmt(h.diameter) +
                " mm): material stands within its mouth along the axis (a wall over part of it); no tool as "
                "wide as the hole comes down to it from this setup");
            return;
        }
        if (step.code == StepCode::Drill) {
            // A drill leaves a cone: a flat-bottomed blind hole (a counterbore) is milled instead.
            if (!h.through && !e.floorFaces.empty()) {
                gap("hole element " + std::to_string(e.id) + " has a flat bottom; it is milled, not drilled");
                return;
            }
            const auto hc = tools_.holeChoice(e.id);
            const int d = hc ? hc->drill : -1;
            if (d < 0) {
                gap(tools_.planError(e).empty() ? "no drill was planned for hole element " + std::to_string(e.id)
                                                : tools_.planError(e));
                return;
            }
            const std::string why = tools_.mismatch(tools_.tool(d), e, step, Operation::Drill, bottom);
            if (!why.empty()) {
                gap(why);
                return;
            }
            addUnit(e, step, Operation::Drill, d, top, bottom).stepOver = 0;
            st.holeMachined = true;
        } else if (step.code == StepCode::HoleMill) {
            std::string why;
            const int m = tools_.helixTool(e, why);
            if (m < 0) {
                gap(why);
                return;
            }
            MachiningUnit& u = addUnit(e, step, Operation::Helix, m, top, bottom);
            if (!h.through && !e.floorFaces.empty()) u.note = "flat-bottomed blind hole: milled, a drill would leave a cone";
            else u.note = "no drill of " + fmt(h.diameter) + " mm: helical interpolation";
            st.holeMachined = true;
        } else {
            gap("step " + std::string(toString(step.code)) + " does not machine holes");
        }
        return;
    }

    const double top = tools_.unitTop(e, e.type == ElementType::Opening ? 0.0 : step.axialAllowance);
    const double bottom = tools_.bottomOf(e);
    switch (step.code) {
        case StepCode::Rough:
        case StepCode::CutOff: {
            const int r = tools_.roughingTool(e);
            if (r < 0) {
                const std::string why = tools_.planError(e, true);
                gap(why.empty() ? "no roughing tool was planned for " + elementName(e) : why);
                return;
            }
            const Operation op = step.code == StepCode::CutOff ? Operation::Profile : Operation::Pocket;
            const std::string why = tools_.mismatch(tools_.tool(r), e, step, op, bottom);
            if (!why.empty()) {
                gap(why);
                return;
            }
            // No roughing end mill leaves room for its centre with the allowance (strokes of
            // lettering narrower than the smallest tool plus twice its allowance): a roughing unit
            // would get no toolpath and take the element's finishing units down with it. The
            // finishing tool, when one fits, cuts the element alone.
            // An element no deeper than the floor allowance roughing leaves: it would cut nothing
            // (the toolpath refuses it). The floor unit cuts it from the top.
            if (op == Operation::Pocket && top - bottom <= step.axialAllowance + kTol) {
                std::string fwhy;
                if (tools_.finisher(e, fwhy) < 0)
                    gap(elementName(e) + " is " + fmt(top - bottom) + " mm deep, no deeper than the roughing's " +
                        fmt(step.axialAllowance) + " mm floor allowance" + (fwhy.empty() ? "" : "; " + fwhy));
                return;
            }
            if (op == Operation::Pocket && !tools_.roughingReaches(e, r)) {
                std::string fwhy;
                if (tools_.finisher(e, fwhy) < 0)
                    gap(tools_.tool(r).id + " (D" + fmt(tools_.tool(r).diameter) + ") with its roughing allowance "
                        "leaves no room for its centre in " + elementName(e) + (fwhy.empty() ? "" : "; " + fwhy));
                return;
            }
            MachiningUnit& u = addUnit(e, step, op, r, top, bottom);
            const toolselect::ElementChoice* c = tools_.choice(e.id);
            if (c && c->roughingTool == r) u.eta = c->ratio.eta;
            if (r != tools_.plannedRoughingTool(e))
                u.note = "open to the blank: roughed from the open side with the wider finishing tool";
            if (op == Operation::Pocket) {
                st.floorAllowance = u.axialAllowance;
                st.roughUnit = u.id;
            }
            return;
        }
        case StepCode::Web: {
            if (e.type == ElementType::Opening) return;  // no floor
            if (st.floorAllowance <= step.axialAllowance + 1e-9) return;  // nothing left on the floor
            std::string why;
            const int f = tools_.floorTool(e, step, why);
            if (f < 0) {
                gap(why);
                return;
            }
            const double webTop = std::isfinite(st.floorAllowance) ? std::min(top, e.level + st.floorAllowance)
                                                                    : tools_.unitTop(e, 0.0);
            MachiningUnit& u = addUnit(e, step, Operation::Pocket, f, webTop, bottom);
            if (!u.islandTops.empty()) {
                u.faceIslandTops = true;
                for (const recognition::AttachedFeature& a : e.attached)
                    if (a.kind == "island_top") facedTops_.insert(a.faces.begin(), a.faces.end());
            }
            // A floor pass clears an area: the roughing width of cut with the finishing speeds.
            if (const auto rs = tools_.setting(static_cast<std::size_t>(f), "roughing")) u.stepOver = rs->ae;
            else u.stepOver = 0.5 * u.cutter.diameter;
            // ... but no wider than leaves a scallop within the floor's tolerance.
            u.stepOver = std::min(u.stepOver, floorStepOver(u.cutter.diameter, u.cutter.cornerRadius, opt_.floorScallop));
            st.floorAllowance = u.axialAllowance;
            if (st.roughUnit < 0) st.roughUnit = u.id;
            if (tools_.leaves(e.id).fillet && u.cutter.cornerRadius > std::max(0.0, e.floorFilletRadius) + kTol)
                leaveFillet(e, u);
            return;
        }
        case StepCode::Corner: {
            if (st.roughUnit < 0) return;  // nothing went before
            std::string why;
            const int c = tools_.finisher(e, why);
            if (c < 0) return;  // the wall steps report it
            // Corners no tool fits: the walls' passes take what the roughing left in them. A rest
            // unit's toolpath took the region the previous cutter cleared as cleared down to the
            // rest unit's own radial allowance, and its entries came through the band between
            // (rapids through material on the small sharp pockets of CTC-03 and CTC-05). It now
            // takes the roughing's allowance (previousAllowance below); rest units for these
            // corners are not made again until measured on those parts.
            if (tools_.leaves(e.id).corners) return;
            const Cutter before = chain_.units[static_cast<std::size_t>(st.roughUnit)].cutter;
            const Tool& ct = tools_.tool(c);
            if (ct.diameter >= before.diameter - 1e-9) return;  // the finishing tool reaches no further
            const toolselect::ElementChoice* choice = tools_.choice(e.id);
            const bool passages = choice && choice->ratio.narrowPassages > 0;
            const bool corners = e.minCornerRadius >= 0 && 0.5 * before.diameter + ar > e.minCornerRadius + kTol;
            if (!corners && !passages) return;
            double rest = 0;
            std::optional<double> eta;
            try {
                const auto dir = tools_.direction(e.setup);
                const toolselect::PocketGeometry g = toolselect::pocketGeometry(e, dir);
                const auto wide = toolselect::machinableRatio(g, 0.5 * before.diameter + ar);
                rest = wide.area - wide.machinableArea;
                // The finishing tool fits the corners; only passages narrower than it leave
                // some of that to the wall steps.
                if (passages) {
                    const auto thin = toolselect::machinableRatio(g, ct.radius() + tools_.allowanceOf(step, ct, &e));
                    rest -= thin.area - thin.machinableArea;
                    eta = thin.eta;
                }
            } catch (const Error& err) {
                gap(elementName(e) + ": its corners could not be measured (" + err.what() + ")");
                return;
            }
            if (rest <= opt_.restMinArea) return;
            const std::string bad = tools_.mismatch(ct, e, step, Operation::Rest, bottom, tools_.leaves(e.id));
            if (!bad.empty()) {
                gap(bad);
                return;
            }
            MachiningUnit& u = addUnit(e, step, Operation::Rest, c, top, bottom);
            u.previousCutter = before;
            u.previousAllowance = chain_.units[static_cast<std::size_t>(st.roughUnit)].radialAllowance;
            // Where it reaches the floor's final height it finishes the floor in the corners: no
            // wider a step-over than leaves the floor's scallop.
            if (u.axialAllowance <= 1e-9 && e.type != ElementType::Opening)
                u.stepOver = std::min(u.stepOver, floorStepOver(u.cutter.diameter, u.cutter.cornerRadius, opt_.floorScallop));
            u.eta = eta;
            u.note = "rest: " + fmt(rest) + " mm2 in corners and passages the " + fmt(before.diameter) +
                     " mm tool cannot reach";
            return;
        }
        case StepCode::SemiWall:
        case StepCode::SemiFlange:
        case StepCode::FinishWall:
        case StepCode::FinishFlange: {
            std::string why;
            const int f = tools_.finisher(e, why);
            if (f < 0) {
                gap(why);
                return;
            }
            const std::string bad = tools_.mismatch(tools_.tool(f), e, step, Operation::Profile, bottom, tools_.leaves(e.id));
            if (!bad.empty()) {
                gap(bad);
                return;
            }
            const MachiningUnit& u = addUnit(e, step, Operation::Profile, f, top, bottom);
            if (tools_.leaves(e.id).corners) leaveCorners(e, u);
            return;
        }
        case StepCode::Drill:
        case StepCode::HoleMill:
            gap("step " + std::string(toString(step.code)) + " machines holes only");
            return;
    }
}

MachiningUnit& Fuser::addEdgeUnit(const DomainElement& e, const toolselect::EdgeTool& t, double top, double bottom,
                                  double offset) {
    MachiningUnit u;
    u.id = static_cast<int>(chain_.units.size());
    u.setup = e.setup;
    u.element = e.id;
    u.step = StepCode::Edge;
    u.operation = Operation::Chamfer;
    u.featureType = featureTypeOf(e);
    u.tool = t.id;
    u.cutter = {t.diameter, 0, "chamfer", t.tipDiameter, t.includedAngle};
    u.top = top;
    u.bottom = bottom;
    u.edgeOffset = offset;
    if (t.spindleRpm > 0) {
        u.setting = {t.spindleRpm, t.feedMmMin, t.plungeFeedMmMin};
        u.stepDown = top - bottom;  // one pass at the chamfer's depth
        u.stepOver = 2 * offset;    // one pass across
    } else {
        u.note = "no cutting data for tool " + t.id + " in " + opt_.material;
    }
    usedEdgeTools_.insert(t.id);
    chain_.units.push_back(std::move(u));
    ++state_[e.id].units;
    state_[e.id].steps.insert(StepCode::Edge);
    return chain_.units.back();
}

// Countersinks of the holes the chain made: a pass of a chamfer mill round the hole's edge, its
// cone on the countersink (toolselect/EdgeTools.h).
void Fuser::makeEdgeUnits(const DomainElement& e) {
    ElementState& st = state_[e.id];
    // Chamfers along a pocket's edges are not cut yet (the pass must follow only the chamfered
    // stretches of a loop): listed with what they are and the mill that would cut them.
    for (const recognition::AttachedFeature& a : e.attached) {
        if (a.kind != "chamfer" || a.faces.empty()) continue;
        if (!(a.angle > 0 && a.size > 0)) {
            st.chamferWhy = " (not planes facing this setup's tool at one angle) are not cut: a chamfer mill along "
                            "the axis cannot follow them";
            continue;
        }
        toolselect::EdgeNeed need;
        need.includedAngle = a.angle;
        need.width = a.size;
        need.height = a.size / std::tan(a.angle / 2 * M_PI / 180);
        const toolselect::EdgeToolChoice c = toolselect::chamferTool(opt_.edgeTools, need);
        st.chamferWhy = " (" + fmt(0.5 * (180 - a.angle)) + " degrees to the top, up to " + fmt(a.size) +
                        " mm wide) along the element's edges are not cut: the edge step cuts countersinks only; " +
                        (c.tool ? "chamfer mill " + c.tool->id + " (" + fmt(c.tool->includedAngle) + " degrees, D" +
                                      fmt(c.tool->diameter) + ") would fit them"
                                : c.why);
    }
    if (!e.hole || !(e.hole->countersinkDiameter > 0)) return;
    const recognition::HoleInfo& h = *e.hole;
    if (!st.holeMachined) {
        st.countersinkWhy = "the hole under it is not machined";
        return;
    }
    if (h.overhung) {
        st.countersinkWhy = "material stands over the hole's mouth";
        return;
    }
    toolselect::EdgeNeed need;
    need.includedAngle = h.countersinkAngle;
    need.width = 0.5 * (h.countersinkDiameter - h.diameter);
    need.holeDiameter = h.diameter;
    if (!(need.width > 0) || !(need.includedAngle > 0 && need.includedAngle < 180)) {
        st.countersinkWhy = "its size was not recognised";
        return;
    }
    const double slope = 1 / std::tan(need.includedAngle / 2 * M_PI / 180);
    need.height = need.width * slope;
    const toolselect::EdgeToolChoice c = toolselect::chamferTool(opt_.edgeTools, need);
    if (!c.tool) {
        st.countersinkWhy = c.why;
        return;
    }
    if (!(c.tool->spindleRpm > 0)) {
        st.countersinkWhy = "chamfer mill " + c.tool->id + " has no cutting data in " + opt_.material;
        return;
    }
    // The hole's top (its location) is the countersink's lower line; the cone rises from it.
    const recognition::SetupFrame& frame = tools_.frameOf(e.setup);
    const double lower = frame.height(h.location);
    const toolselect::ChamferPass pass = toolselect::chamferPass(*c.tool);
    MachiningUnit& u = addEdgeUnit(e, *c.tool, lower + need.height, lower - pass.tipBelow, pass.offset);
    // The drive loop is the hole's edge under the countersink, counter-clockwise.
    const recognition::P2 centre = frame.project(h.location);
    const int n = std::max(32, static_cast<int>(std::ceil(M_PI * h.diameter / 0.5)));
    for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n;
        u.contour.push_back({centre.x + 0.5 * h.diameter * std::cos(a), centre.y + 0.5 * h.diameter * std::sin(a)});
    }
    u.at = {centre.x, centre.y};
    u.note = "countersink " + fmt(h.countersinkAngle) + " degrees, diameter " + fmt(h.countersinkDiameter) + " mm";
    st.countersunk = true;
}

MachiningChain Fuser::run() {
    validateTemplate(tmpl_);
    if (tree_.elements.empty())
        throw inputError("the part has no domain element: recognition found no pocket, opening or hole to machine");
    chain_.family = tmpl_.family;
    chain_.material = opt_.material;
    chain_.machine = opt_.machine;
    chain_.processTemplate = tmpl_;

    for (const auto& s : tree_.setups) {
        if (!(norm(s.direction) > 0))
            throw inputError("setup " + s.name + ": its direction is the zero vector");
        const recognition::SetupFrame f(s.direction);
        tools_.addSetup(s.id, f, s.direction);
        ChainSetup cs;
        cs.id = s.id;
        cs.name = s.name;
        cs.direction = s.direction;
        cs.u = f.u, cs.v = f.v, cs.w = f.w;
        if (std::isfinite(s.blankTop)) cs.blankTop = s.blankTop;
        chain_.setups.push_back(cs);
    }
    for (const DomainElement& e : tree_.elements) {
        if (!tools_.hasSetup(e.setup))
            throw inputError("element " + std::to_string(e.id) + ": unknown setup " + std::to_string(e.setup));
        ChainElement ce;
        ce.id = e.id;
        ce.setup = e.setup;
        ce.parent = e.parent;
        ce.featureType = featureTypeOf(e);
        ce.level = e.level;
        ce.top = e.top;
        ce.depth = e.depth;
        ce.minWidth = e.minWidth;
        ce.minCornerRadius = e.minCornerRadius;
        ce.floorFilletRadius = e.floorFilletRadius;
        if (e.hole) ce.holeDiameter = e.hole->diameter;
        const toolselect::ElementChoice* c = tools_.choice(e.id);
        if (c && c->roughingTool >= 0) ce.narrowPassages = c->ratio.narrowPassages;
        chain_.elements.push_back(ce);
    }

    for (const auto& s : tree_.setups) {
        std::vector<const DomainElement*> elements;
        for (int root : s.elements) preorder(root, elements);
        // Elements the setup's roots do not reach (a tree written by hand) still count.
        std::set<int> seen;
        for (const auto* e : elements) seen.insert(e->id);
        for (const DomainElement& e : tree_.elements)
            if (e.setup == s.id && !seen.count(e.id)) elements.push_back(&e);
        for (const TemplateStep& step : tmpl_.steps) {
            if (step.existence == Existence::MustNot) continue;
            for (const DomainElement* e : elements)
                if (step.machines(featureTypeOf(*e))) makeUnits(*e, step);
        }
        for (const DomainElement* e : elements) makeEdgeUnits(*e);
        for (const DomainElement* e : elements) listUnmachined(*e, state_[e->id], tmpl_, chain_.unmachined);
    }
    listIslandTops(tree_, facedTops_, chain_.unmachined);

    // The tools: those used, then (for editing) those that could be.
    for (std::size_t i = 0; i < plan_.tools.size(); ++i) {
        const Tool& t = plan_.tools[i];
        const bool used = usedTools_.count(static_cast<int>(i)) > 0;
        if (!used && !(opt_.listCandidateTools && (t.isEndMill() || t.type == "drill"))) continue;
        ChainTool ct = chainTool(t);
        for (const char* op : {"roughing", "finishing", "drilling"})
            if (const auto s = tools_.setting(i, op)) ct.settings[op] = toolData(*s);
        if (!used && ct.settings.empty()) continue;
        chain_.tools.push_back(ct);
    }
    for (const toolselect::EdgeTool& t : opt_.edgeTools) {
        if (!usedEdgeTools_.count(t.id)) continue;
        ChainTool ct;
        ct.id = t.id;
        ct.type = "chamfer";
        ct.material = t.material;
        ct.diameter = t.diameter;
        ct.fluteLength = ct.reach = t.reach;
        ct.flutes = t.flutes;
        ct.tipDiameter = t.tipDiameter;
        ct.includedAngle = t.includedAngle;
        ct.settings["finishing"] = {t.spindleRpm, t.feedMmMin, t.plungeFeedMmMin, t.reach, 0};
        chain_.tools.push_back(ct);
    }
    return std::move(chain_);
}

}  // namespace

double floorStepOver(double diameter, double cornerRadius, double scallop) {
    const double R = 0.5 * diameter, r = std::clamp(cornerRadius, 0.0, R), h = std::clamp(scallop, 0.0, r);
    return std::min(diameter, 2 * (R - r) + 2 * std::sqrt(std::max(0.0, r * r - (r - h) * (r - h))));
}

std::string featureTypeOf(const DomainElement& e) {
    if (e.type == ElementType::Hole) return "hole";
    if (e.type == ElementType::Opening) return "opening";
    for (const auto& a : e.attached)
        if (a.kind == "flange") return "flange";
    return e.type == ElementType::OpenPocket ? "open_pocket" : "closed_pocket";
}

MachiningChain fuse(const DomainTree& tree, const ToolPlan& plan, const ProcessTemplate& processTemplate,
                    const ChainOptions& options, const ToolSettingOf& settingOf) {
    return Fuser(tree, plan, processTemplate, options, settingOf).run();
}

MachiningChain buildChain(const DomainTree& tree, const ToolPlan& plan, const ProcessTemplate& processTemplate,
                          const ChainOptions& options, const ToolSettingOf& settingOf) {
    MachiningChain chain = fuse(tree, plan, processTemplate, options, settingOf);
    sequence(chain, options.optimiseTravel);
    arrange(chain);
    chain.checks = checkRules(chain);
    return chain;
}

}  // namespace aeronc::chain
