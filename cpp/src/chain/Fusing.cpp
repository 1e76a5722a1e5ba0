#include <aeronc/chain/ConstructionRules.h>
#include <aeronc/chain/Fusing.h>
#include <aeronc/chain/Sequencing.h>
#include <aeronc/core/Error.h>
#include <aeronc/recognition/SetupFrame.h>
#include <aeronc/toolselect/Selection.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace aeronc::chain {

using recognition::DomainElement;
using recognition::DomainTree;
using recognition::ElementType;
using toolselect::Tool;
using toolselect::ToolPlan;

namespace {

constexpr double kTol = 1e-3;  // mm: dimensions compared on recognised geometry
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string fmt(double x) {
    std::ostringstream s;
    s << std::round(x * 1000) / 1000;
    return s.str();
}

double signedArea(const Loop& l) {
    double a = 0;
    for (std::size_t i = 0; i < l.size(); ++i) {
        const Point2& p = l[i];
        const Point2& q = l[(i + 1) % l.size()];
        a += p[0] * q[1] - q[0] * p[1];
    }
    return 0.5 * a;
}

Point2 centroid(const Loop& l) {
    const double a = signedArea(l);
    if (std::fabs(a) < 1e-9) {
        Point2 m{0, 0};
        for (const Point2& p : l) m[0] += p[0], m[1] += p[1];
        if (!l.empty()) m[0] /= static_cast<double>(l.size()), m[1] /= static_cast<double>(l.size());
        return m;
    }
    double cx = 0, cy = 0;
    for (std::size_t i = 0; i < l.size(); ++i) {
        const Point2& p = l[i];
        const Point2& q = l[(i + 1) % l.size()];
        const double c = p[0] * q[1] - q[0] * p[1];
        cx += (p[0] + q[0]) * c;
        cy += (p[1] + q[1]) * c;
    }
    return {cx / (6 * a), cy / (6 * a)};
}

ChainTool chainTool(const Tool& t) {
    ChainTool c;
    c.id = t.id;
    c.type = t.type;
    c.material = t.material;
    c.diameter = t.diameter;
    c.cornerRadius = t.cornerRadius;
    c.fluteLength = t.fluteLength;
    c.reach = t.reach;
    c.flutes = t.flutes;
    return c;
}

ToolData toolData(const toolselect::ToolSetting& s) {
    return {s.spindleRpm, s.feedMmMin, s.plungeFeedMmMin, s.ap, s.ae};
}

// Fusing state of one element, in template order.
struct ElementState {
    double floorAllowance = kInf;  // left on the floor by the units so far; inf: untouched
    int roughUnit = -1;            // the last pocket unit (its cutter goes before a rest unit)
    bool holeMachined = false;
    std::map<StepCode, std::string> gaps;  // why an applicable step made no unit
    std::set<StepCode> steps;              // the steps that made a unit
    int units = 0;
};

class Fuser {
public:
    Fuser(const DomainTree& tree, const ToolPlan& plan, const ProcessTemplate& t, const ChainOptions& o,
          ToolSettingOf settingOf)
        : tree_(tree), plan_(plan), tmpl_(t), opt_(o), settingOf_(std::move(settingOf)) {
        if (!settingOf_) {
            settingOf_ = [this](std::size_t tool, const std::string& op) -> std::optional<toolselect::ToolSetting> {
                for (const auto& s : plan_.settings)
                    if (s.tool == static_cast<int>(tool) && s.operation == op) return s;
                return std::nullopt;
            };
        }
        for (const DomainElement& e : tree.elements) byId_[e.id] = &e;
        for (const auto& c : plan.elements) choice_[c.element] = &c;
        for (const auto& h : plan.holes) holeChoice_[h.element] = &h;
        for (const auto& g : plan.groupsAfter)
            for (int e : g.elements) groupTool_[e] = g.tool;
    }

    MachiningChain run();

private:
    const recognition::SetupFrame& frameOf(int setup) const { return frames_.at(setup); }
    const Tool& tool(int i) const { return plan_.tools.at(static_cast<std::size_t>(i)); }
    bool hasSetting(int i, const char* op) const { return settingOf_(static_cast<std::size_t>(i), op).has_value(); }
    bool millingData(int i) const { return hasSetting(i, "roughing") || hasSetting(i, "finishing"); }

    void preorder(int id, std::vector<const DomainElement*>& out) const {
        const auto it = byId_.find(id);
        if (it == byId_.end()) return;
        out.push_back(it->second);
        for (int c : it->second->children) preorder(c, out);
    }

    std::string elementName(const DomainElement& e) const {
        return "element " + std::to_string(e.id) + " (" + featureTypeOf(e) + ")";
    }

    // The parent's floor bounds a child's unit from above: the cavity over it is the parent's.
    double unitTop(const DomainElement& e, double axialAllowance) const {
        if (e.parent >= 0) {
            const auto it = byId_.find(e.parent);
            if (it != byId_.end() && it->second->type != ElementType::Hole)
                return std::min(e.top, it->second->level + axialAllowance);
        }
        return e.top;
    }
    double bottomOf(const DomainElement& e) const {
        return e.type == ElementType::Opening ? e.level - opt_.breakthrough : e.level;
    }

    // Why `t` cannot do `step` on `e` down to `bottom`; empty when it can.
    std::string mismatch(const Tool& t, const DomainElement& e, const TemplateStep& step, Operation op,
                         double bottom) const;

    int plannedRoughingTool(const DomainElement& e) const {
        const auto g = groupTool_.find(e.id);
        if (g != groupTool_.end()) return g->second;
        const auto c = choice_.find(e.id);
        return c == choice_.end() ? -1 : c->second->roughingTool;
    }
    // The planned roughing tool; for a pocket open to the blank, the finishing tool when that is
    // wider: the tool comes in from the open side, so the narrow width that chose a small
    // roughing tool does not bind it.
    int roughingTool(const DomainElement& e) const {
        const int r = plannedRoughingTool(e);
        if (e.type != ElementType::OpenPocket || e.openEdges.empty()) {
            const auto cached = roughWithAllowance_.find(e.id);
            if (cached != roughWithAllowance_.end()) return cached->second;
            const int fitted = roughingToolWithAllowance(e, r, roughingAllowance());
            roughWithAllowance_[e.id] = fitted;
            return fitted;
        }
        const auto c = choice_.find(e.id);
        const int f = c == choice_.end() ? -1 : c->second->finishingTool;
        if (f >= 0 && (r < 0 || tool(f).diameter > tool(r).diameter + 1e-9) && hasSetting(f, "roughing")) return f;
        return r;
    }
    // The planner chose the roughing tool by eta without the step's radial allowance. When the
    // tool grown by the allowance reaches none of the region (a slot-like opening barely wider
    // than the tool), the largest roughing end mill that does; else the planned one.
    int roughingToolWithAllowance(const DomainElement& e, int r, double ar) const {
        if (r < 0 || e.type == ElementType::OpenPocket) return r;
        const auto d = directions_.find(e.setup);
        if (d == directions_.end()) return r;
        const toolselect::PocketGeometry g = toolselect::pocketGeometry(e, d->second);
        auto reaches = [&](const Tool& t) { return toolselect::machinableRatio(g, t.radius() + ar).eta > 0.0; };
        if (reaches(tool(r))) return r;
        int best = -1;
        for (std::size_t i = 0; i < plan_.tools.size(); ++i) {
            const Tool& t = plan_.tools[i];
            if (!t.isEndMill() || t.diameter >= tool(r).diameter || !hasSetting(static_cast<int>(i), "roughing")) continue;
            if (best >= 0 && t.diameter <= tool(best).diameter) continue;
            if (reaches(t)) best = static_cast<int>(i);
        }
        return best >= 0 ? best : r;
    }
    double roughingAllowance() const {
        for (const TemplateStep& st : tmpl_.steps)
            if (st.code == StepCode::Rough) return st.radialAllowance;
        return 0.0;
    }
    mutable std::map<int, int> roughWithAllowance_;  // element -> roughing tool fitted to the allowance
    int finishingTool(const DomainElement& e, std::string& why) const;
    int finisher(const DomainElement& e, std::string& why);
    int floorTool(const DomainElement& e, const TemplateStep& step, std::string& why);
    int widestFloorTool(const DomainElement& e, const TemplateStep& step) const;
    int helixTool(const DomainElement& e, std::string& why) const;
    // The planner's reason for a missing tool; for a pocket, the lines about roughing tools
    // (`roughing`) or the others.
    std::string planError(const DomainElement& e, bool roughing = false) const {
        const auto c = choice_.find(e.id);
        if (c != choice_.end() && !c->second->error.empty()) {
            std::string out, line;
            std::istringstream in(c->second->error);
            while (std::getline(in, line))
                if ((line.find("roughing tool") != std::string::npos) == roughing)
                    out += (out.empty() ? "" : "; ") + line;
            return out;
        }
        const auto h = holeChoice_.find(e.id);
        if (h != holeChoice_.end() && !h->second->error.empty()) return h->second->error;
        return "";
    }

    MachiningUnit& addUnit(const DomainElement& e, const TemplateStep& step, Operation op, int toolIndex, double top,
                           double bottom);
    void makeUnits(const DomainElement& e, const TemplateStep& step);
    void listUnmachined(const DomainElement& e);
    // Lists faces of e the chain leaves, each face once: a chamfer between two elements is
    // named by the first.
    void listFaces(const DomainElement& e, const std::string& reason, const std::vector<int>& faces);

    const DomainTree& tree_;
    const ToolPlan& plan_;
    const ProcessTemplate& tmpl_;
    const ChainOptions& opt_;
    ToolSettingOf settingOf_;
    std::map<int, const DomainElement*> byId_;
    std::map<int, const toolselect::ElementChoice*> choice_;
    std::map<int, const toolselect::HoleChoice*> holeChoice_;
    std::map<int, int> groupTool_;
    std::map<int, recognition::SetupFrame> frames_;
    std::map<int, Vec3> directions_;
    std::map<int, ElementState> state_;
    std::map<int, std::pair<int, std::string>> finishers_;  // element -> tool and why none
    std::set<int> usedTools_;
    std::set<int> facedTops_;  // island-top faces a floor unit faces
    MachiningChain chain_;
};

std::string Fuser::mismatch(const Tool& t, const DomainElement& e, const TemplateStep& step, Operation op,
                            double bottom) const {
    const std::string who = "tool " + t.id + " (D" + fmt(t.diameter) + ")";
    if (op == Operation::Drill) {
        if (t.type != "drill") return who + " is not a drill";
    } else if (!t.isEndMill()) {
        return who + " is not an end mill";
    }
    // Height: from the top constraint down to the unit's bottom.
    const double top = e.hole && op != Operation::Pocket && op != Operation::Profile
                           ? frameOf(e.setup).height(e.hole->location)
                           : e.top;
    const double need = top - bottom;
    if (t.usableLength() + kTol < need)
        return who + " reaches " + fmt(t.usableLength()) + " mm; " + elementName(e) + " needs " + fmt(need) + " mm";
    const double ar = step.radialAllowance;
    if (op == Operation::Profile || op == Operation::Rest) {
        // Side fillet: the tool follows the concave corners.
        if (e.minCornerRadius >= 0 && t.radius() > e.minCornerRadius + kTol)
            return who + " is wider than the " + fmt(e.minCornerRadius) + " mm corner radius of " + elementName(e);
    }
    // Minimum width: a wall or floor pass goes all round a closed region.
    if (op == Operation::Profile || (op == Operation::Pocket && step.code == StepCode::Web)) {
        if (e.type != ElementType::OpenPocket && e.minWidth > 0 &&
            t.diameter > e.minWidth - 2 * ar + kTol)
            return who + " does not pass the " + fmt(e.minWidth) + " mm narrowest width of " + elementName(e) +
                   " with " + fmt(ar) + " mm allowance";
    }
    // Floor fillet: finishing a floor leaves the tool's corner radius at its edge.
    if (step.code == StepCode::Web && t.cornerRadius > std::max(0.0, e.floorFilletRadius) + kTol)
        return who + " has a " + fmt(t.cornerRadius) + " mm corner radius, larger than the " +
               fmt(std::max(0.0, e.floorFilletRadius)) + " mm floor fillet of " + elementName(e);
    return "";
}

int Fuser::finishingTool(const DomainElement& e, std::string& why) const {
    const auto c = choice_.find(e.id);
    const int f = c == choice_.end() ? -1 : c->second->finishingTool;
    if (f < 0) {
        why = planError(e);
        if (why.empty()) why = "no finishing tool was planned for " + elementName(e);
        return -1;
    }
    // A finishing tool wider than the roughing tool would take the diameters back up (validity):
    // the roughing tool finishes when it fits.
    const int r = roughingTool(e);
    if (r >= 0 && tool(f).diameter > tool(r).diameter + 1e-9) {
        const Tool& rt = tool(r);
        const bool fits = (e.minCornerRadius < 0 || rt.radius() <= e.minCornerRadius + kTol) &&
                          rt.cornerRadius <= std::max(0.0, e.floorFilletRadius) + kTol && hasSetting(r, "finishing");
        if (fits) return r;
    }
    return f;
}

// The element's one finishing tool for all its finishing steps (so the diameters do not go back
// up between them): the planned one when it suits every step that applies, else the tool the
// planner's preference picks among those that do (a corner radius equal to the floor fillet
// first, then the largest), no wider than the roughing tool.
int Fuser::finisher(const DomainElement& e, std::string& why) {
    const auto cached = finishers_.find(e.id);
    if (cached != finishers_.end()) {
        why = cached->second.second;
        return cached->second.first;
    }
    const std::string ft = featureTypeOf(e);
    auto suits = [&](const Tool& t) {
        for (const TemplateStep& s : tmpl_.steps) {
            if (s.existence == Existence::MustNot || !s.machines(ft)) continue;
            Operation op;
            if (s.code == StepCode::Web) op = Operation::Pocket;
            else if (s.code == StepCode::Corner) op = Operation::Rest;
            else if (s.role == ToolRole::Finishing && s.code != StepCode::HoleMill) op = Operation::Profile;
            else continue;
            const std::string m = mismatch(t, e, s, op, bottomOf(e));
            if (!m.empty()) return m;
        }
        return std::string();
    };
    int best = finishingTool(e, why);
    if (best >= 0) {
        const std::string m = suits(tool(best));
        if (!m.empty()) {
            why = m;
            best = -1;
        }
    }
    // No wider than the roughing tool nor than the floor's tool: the web step comes before the
    // wall and corner steps, so a wider finisher would take the diameters back up (validity).
    const int r = roughingTool(e);
    double maxD = r >= 0 ? tool(r).diameter : kInf;
    for (const TemplateStep& s : tmpl_.steps) {
        if (s.code != StepCode::Web || s.existence == Existence::MustNot || !s.machines(ft)) continue;
        const int w = widestFloorTool(e, s);
        if (w >= 0) maxD = std::min(maxD, tool(w).diameter);
    }
    if (best >= 0 && tool(best).diameter > maxD + 1e-9) best = -1;
    if (best < 0) {
        const double fillet = std::max(0.0, e.floorFilletRadius);
        bool bestMatches = false;
        for (std::size_t i = 0; i < plan_.tools.size(); ++i) {
            const Tool& t = plan_.tools[i];
            if (!t.isEndMill() || t.diameter > maxD + 1e-9 || !hasSetting(static_cast<int>(i), "finishing")) continue;
            if (!suits(t).empty()) continue;
            const bool matches = fillet > 0 && std::fabs(t.cornerRadius - fillet) <= kTol;
            if (best < 0 || (matches && !bestMatches) ||
                (matches == bestMatches && t.diameter > tool(best).diameter + 1e-9)) {
                best = static_cast<int>(i);
                bestMatches = matches;
            }
        }
    }
    if (best >= 0) why.clear();
    finishers_[e.id] = {best, why};
    return best;
}

int Fuser::floorTool(const DomainElement& e, const TemplateStep& step, std::string& why) {
    // Only when no end mill fits the floor (widestFloorTool) does the element's finishing tool do it.
    const int best = widestFloorTool(e, step);
    if (best >= 0) return best;
    std::string finishWhy;
    const int f = finisher(e, finishWhy);
    if (f >= 0 && mismatch(tool(f), e, step, Operation::Pocket, e.level).empty()) return f;
    why = "no end mill with a corner radius of at most " + fmt(std::max(0.0, e.floorFilletRadius)) +
          " mm reaches the " + fmt(e.depth) + " mm deep floor of " + elementName(e);
    return -1;
}

int Fuser::widestFloorTool(const DomainElement& e, const TemplateStep& step) const {
    // A floor needs no tool as thin as the corners: the largest flat or bull end mill whose corner
    // fits the floor fillet (at one diameter, the one whose corner equals the fillet), no wider
    // than the roughing tool. A ball's scallops would need a step-over a fraction of a millimetre
    // wide; the corner and wall steps take what the wide tool cannot reach.
    const int r = roughingTool(e);
    const double maxD = r >= 0 ? tool(r).diameter : kInf;
    const double fillet = std::max(0.0, e.floorFilletRadius);
    int best = -1;
    bool bestMatches = false;
    for (std::size_t i = 0; i < plan_.tools.size(); ++i) {
        const Tool& t = plan_.tools[i];
        if (!t.isEndMill() || t.type == "ball" || t.diameter > maxD + 1e-9) continue;
        if (!hasSetting(static_cast<int>(i), "finishing")) continue;
        if (!mismatch(t, e, step, Operation::Pocket, e.level).empty()) continue;
        const bool matches = fillet > 0 && std::fabs(t.cornerRadius - fillet) <= kTol;
        if (best < 0 || t.diameter > tool(best).diameter + 1e-9 ||
            (std::fabs(t.diameter - tool(best).diameter) <= 1e-9 && matches && !bestMatches)) {
            best = static_cast<int>(i);
            bestMatches = matches;
        }
    }
    return best;
}

int Fuser::helixTool(const DomainElement& e, std::string& why) const {
    const recognition::HoleInfo& h = *e.hole;
    const double lo = opt_.helixMinRatio * h.diameter, hi = opt_.helixMaxRatio * h.diameter;
    const double need = h.depth + (h.through ? opt_.breakthrough : 0);
    const bool flatBottom = !h.through;
    int best = -1;
    for (std::size_t i = 0; i < plan_.tools.size(); ++i) {
        const Tool& t = plan_.tools[i];
        if (!t.isEndMill() || t.type == "ball") continue;
        if (t.diameter < lo - 1e-9 || t.diameter > hi + 1e-9) continue;
        if (flatBottom && t.cornerRadius > std::max(0.0, e.floorFilletRadius) + kTol) continue;
        if (t.usableLength() + kTol < need || !millingData(static_cast<int>(i))) continue;
        if (best < 0 || t.diameter > tool(best).diameter + 1e-9 ||
            (std::fabs(t.diameter - tool(best).diameter) <= 1e-9 && t.cornerRadius < tool(best).cornerRadius))
            best = static_cast<int>(i);
    }
    if (best < 0)
        why = "no end mill for helical interpolation of " + elementName(e) + " (diameter " + fmt(h.diameter) +
              " mm): it needs one of " + fmt(lo) + " to " + fmt(hi) + " mm reaching " + fmt(need) + " mm" +
              (flatBottom ? " with a flat end" : "");
    return best;
}

MachiningUnit& Fuser::addUnit(const DomainElement& e, const TemplateStep& step, Operation op, int toolIndex,
                              double top, double bottom) {
    const recognition::SetupFrame& frame = frameOf(e.setup);
    const Tool& t = tool(toolIndex);
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
        u.bottom = std::max(bottom - t.cornerRadius, std::min(u.bottom, top - std::min(t.fluteLength, t.reach)));
    const bool floorless = e.type == ElementType::Opening || e.type == ElementType::Hole;
    u.radialAllowance = step.radialAllowance;
    u.axialAllowance = floorless ? 0.0 : step.axialAllowance;
    u.floorFilletRadius = floorless ? 0.0 : std::max(0.0, e.floorFilletRadius);

    const char* op0 = settingOperation(step.code);
    std::optional<toolselect::ToolSetting> s = settingOf_(static_cast<std::size_t>(toolIndex), op0);
    if (!s && op != Operation::Drill)
        s = settingOf_(static_cast<std::size_t>(toolIndex), std::string(op0) == "roughing" ? "finishing" : "roughing");
    if (s) {
        u.setting = {s->spindleRpm, s->feedMmMin, s->plungeFeedMmMin};
        u.stepDown = s->ap;
        u.stepOver = s->ae;
    } else {
        u.note = "no cutting data for tool " + t.id + " in " + opt_.material;
    }

    auto flat = [&](const recognition::Polyline& loop, bool ccw) {
        Loop out;
        out.reserve(loop.size());
        for (const Vec3& p : loop) {
            const recognition::P2 q = frame.project(p);
            out.push_back({q.x, q.y});
        }
        if (out.size() > 1 && std::hypot(out.front()[0] - out.back()[0], out.front()[1] - out.back()[1]) < 1e-9)
            out.pop_back();
        if ((signedArea(out) > 0) != ccw) std::reverse(out.begin(), out.end());
        return out;
    };
    u.contour = flat(e.contour, true);
    for (const auto& isl : e.islands) u.islands.push_back(flat(isl, false));
    // Island tops inside this element's own cavity (above its floor, below its top and the
    // parent's floor): a parent's island reaching down into a child is the parent's to face.
    if (op == Operation::Pocket && e.islandTops.size() == e.islands.size() && !floorless) {
        const double ceiling = unitTop(e, 0.0) - kTol;
        std::vector<double> tops(e.islands.size(), std::numeric_limits<double>::quiet_NaN());
        bool lower = false;
        for (std::size_t i = 0; i < tops.size(); ++i)
            if (e.islandTops[i] < ceiling && e.islandTops[i] > e.level + kTol) tops[i] = e.islandTops[i], lower = true;
        if (lower) u.islandTops = std::move(tops);
    }
    for (const auto& [a, b] : e.openEdges) {
        const recognition::P2 p = frame.project(a), q = frame.project(b);
        u.openEdges.push_back({Point2{p.x, p.y}, Point2{q.x, q.y}});
    }
    u.at = centroid(u.contour);
    if (e.hole) {
        const recognition::P2 c = frame.project(e.hole->location);
        u.at = {c.x, c.y};
        u.holes.push_back({c.x, c.y, e.hole->diameter, top, bottom, e.hole->through,
                           e.hole->through ? 0.0 : std::max(0.0, e.floorFilletRadius)});
    }
    usedTools_.insert(toolIndex);
    chain_.units.push_back(std::move(u));
    ++state_[e.id].units;
    state_[e.id].steps.insert(step.code);
    return chain_.units.back();
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
        const double top = frameOf(e.setup).height(h.location);
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
            const auto hc = holeChoice_.find(e.id);
            const int d = hc == holeChoice_.end() ? -1 : hc->second->drill;
            if (d < 0) {
                gap(planError(e).empty() ? "no drill was planned for hole element " + std::to_string(e.id)
                                         : planError(e));
                return;
            }
            const std::string why = mismatch(tool(d), e, step, Operation::Drill, bottom);
            if (!why.empty()) {
                gap(why);
                return;
            }
            addUnit(e, step, Operation::Drill, d, top, bottom).stepOver = 0;
            st.holeMachined = true;
        } else if (step.code == StepCode::HoleMill) {
            std::string why;
            const int m = helixTool(e, why);
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

    const double top = unitTop(e, e.type == ElementType::Opening ? 0.0 : step.axialAllowance);
    const double bottom = bottomOf(e);
    switch (step.code) {
        case StepCode::Rough:
        case StepCode::CutOff: {
            const int r = roughingTool(e);
            if (r < 0) {
                const std::string why = planError(e, true);
                gap(why.empty() ? "no roughing tool was planned for " + elementName(e) : why);
                return;
            }
            const Operation op = step.code == StepCode::CutOff ? Operation::Profile : Operation::Pocket;
            const std::string why = mismatch(tool(r), e, step, op, bottom);
            if (!why.empty()) {
                gap(why);
                return;
            }
            MachiningUnit& u = addUnit(e, step, op, r, top, bottom);
            const auto c = choice_.find(e.id);
            if (c != choice_.end() && c->second->roughingTool == r) u.eta = c->second->ratio.eta;
            if (r != plannedRoughingTool(e))
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
            const int f = floorTool(e, step, why);
            if (f < 0) {
                gap(why);
                return;
            }
            const double webTop = std::isfinite(st.floorAllowance) ? std::min(top, e.level + st.floorAllowance)
                                                                    : unitTop(e, 0.0);
            MachiningUnit& u = addUnit(e, step, Operation::Pocket, f, webTop, bottom);
            if (!u.islandTops.empty()) {
                u.faceIslandTops = true;
                for (const recognition::AttachedFeature& a : e.attached)
                    if (a.kind == "island_top") facedTops_.insert(a.faces.begin(), a.faces.end());
            }
            // A floor pass clears an area: the roughing width of cut with the finishing speeds.
            if (const auto rs = settingOf_(static_cast<std::size_t>(f), "roughing")) u.stepOver = rs->ae;
            else u.stepOver = 0.5 * u.cutter.diameter;
            // ... but no wider than leaves a scallop within the floor's tolerance.
            u.stepOver = std::min(u.stepOver, floorStepOver(u.cutter.diameter, u.cutter.cornerRadius, opt_.floorScallop));
            st.floorAllowance = u.axialAllowance;
            if (st.roughUnit < 0) st.roughUnit = u.id;
            return;
        }
        case StepCode::Corner: {
            if (st.roughUnit < 0) return;  // nothing went before
            std::string why;
            const int c = finisher(e, why);
            if (c < 0) return;  // the wall steps report it
            const Cutter before = chain_.units[static_cast<std::size_t>(st.roughUnit)].cutter;
            const Tool& ct = tool(c);
            if (ct.diameter >= before.diameter - 1e-9) return;  // the finishing tool reaches no further
            const auto choice = choice_.find(e.id);
            const bool passages = choice != choice_.end() && choice->second->ratio.narrowPassages > 0;
            const bool corners = e.minCornerRadius >= 0 && 0.5 * before.diameter + ar > e.minCornerRadius + kTol;
            if (!corners && !passages) return;
            double rest = 0;
            std::optional<double> eta;
            try {
                const auto dir = directions_.at(e.setup);
                const toolselect::PocketGeometry g = toolselect::pocketGeometry(e, dir);
                const auto wide = toolselect::machinableRatio(g, 0.5 * before.diameter + ar);
                rest = wide.area - wide.machinableArea;
                // The finishing tool fits the corners; only passages narrower than it leave
                // some of that to the wall steps.
                if (passages) {
                    const auto thin = toolselect::machinableRatio(g, ct.radius() + ar);
                    rest -= thin.area - thin.machinableArea;
                    eta = thin.eta;
                }
            } catch (const Error& err) {
                gap(elementName(e) + ": its corners could not be measured (" + err.what() + ")");
                return;
            }
            if (rest <= opt_.restMinArea) return;
            const std::string bad = mismatch(ct, e, step, Operation::Rest, bottom);
            if (!bad.empty()) {
                gap(bad);
                return;
            }
            MachiningUnit& u = addUnit(e, step, Operation::Rest, c, top, bottom);
            u.previousCutter = before;
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
            const int f = finisher(e, why);
            if (f < 0) {
                gap(why);
                return;
            }
            const std::string bad = mismatch(tool(f), e, step, Operation::Profile, bottom);
            if (!bad.empty()) {
                gap(bad);
                return;
            }
            addUnit(e, step, Operation::Profile, f, top, bottom);
            return;
        }
        case StepCode::Drill:
        case StepCode::HoleMill:
            gap("step " + std::string(toString(step.code)) + " machines holes only");
            return;
    }
}

void Fuser::listUnmachined(const DomainElement& e) {
    const std::string ft = featureTypeOf(e);
    ElementState& st = state_[e.id];
    bool anyStep = false;
    std::set<StepCode> listed;
    for (const TemplateStep& s : tmpl_.steps) {
        if (s.existence == Existence::MustNot || !s.machines(ft)) continue;
        anyStep = true;
        if (s.existence != Existence::Must) continue;
        if (st.steps.count(s.code)) continue;
        // A must-step with nothing to do (a floor already finished) is no gap.
        const auto g = st.gaps.find(s.code);
        if (g == st.gaps.end()) continue;
        chain_.unmachined.push_back({e.id, s.code, g->second, {}});
        listed.insert(s.code);
    }
    if (!anyStep) {
        chain_.unmachined.push_back(
            {e.id, std::nullopt, "no step of template '" + tmpl_.name + "' machines feature type " + ft, {}});
        return;
    }
    if (st.units == 0 && listed.empty()) {
        std::string why;
        for (const auto& [code, text] : st.gaps)
            why += (why.empty() ? "" : "; ") + std::string(toString(code)) + ": " + text;
        if (why.empty()) why = "no step made a unit for it";
        chain_.unmachined.push_back({e.id, std::nullopt, why, {}});
    }
    // Attached features no unit cuts.
    if (e.hole && e.hole->countersinkDiameter > 0)
        chain_.unmachined.push_back(
            {e.id, std::nullopt,
             "its " + fmt(e.hole->countersinkAngle) + " degree countersink (diameter " +
                 fmt(e.hole->countersinkDiameter) + " mm) needs a countersink tool; the chain has none", {}});
    const bool countersunk = std::any_of(e.attached.begin(), e.attached.end(),
                                         [](const recognition::AttachedFeature& a) { return a.kind == "countersink"; });
    if (!e.chamferFaces.empty() && !countersunk)
        listFaces(e, std::to_string(e.chamferFaces.size()) + " chamfer face(s) need a chamfer tool; the chain has none",
                  e.chamferFaces);
    // Walls leaning away from the axis: a flat end mill finishing them square to the floor leaves
    // depth x tan(lean) at their top. A drafted wall keeps within the tolerance; a bevel does not.
    // (An element no unit machines is listed whole above.)
    constexpr double kLeftOnLeaningWall = 0.1;  // mm
    if (st.units == 0) return;
    std::vector<int> leaning;
    double most = 0, steepest = 0;
    for (const recognition::AttachedFeature& a : e.attached) {
        if (a.kind != "open_corner" || a.faces.empty()) continue;
        const double left = e.depth * std::tan(a.size * M_PI / 180);
        if (!(left > kLeftOnLeaningWall)) continue;
        leaning.insert(leaning.end(), a.faces.begin(), a.faces.end());
        most = std::max(most, left), steepest = std::max(steepest, a.size);
    }
    if (!leaning.empty()) {
        std::string faces;
        for (int f : leaning) faces += (faces.empty() ? "" : ", ") + std::to_string(f);
        listFaces(e,
                  "face(s) " + faces + " lean up to " + fmt(steepest) +
                      " degrees from the tool axis (bevels with their blends): a flat end mill along this setup's "
                      "axis leaves up to " + fmt(most) + " mm on them; they need a setup along their normal",
                  leaning);
    }
}

void Fuser::listFaces(const DomainElement& e, const std::string& reason, const std::vector<int>& faces) {
    std::set<int> named;
    for (const Unmachined& u : chain_.unmachined) named.insert(u.faces.begin(), u.faces.end());
    std::vector<int> left;
    for (int f : faces)
        if (named.insert(f).second) left.push_back(f);
    if (!left.empty()) chain_.unmachined.push_back({e.id, std::nullopt, reason, left});
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
        frames_.emplace(s.id, f);
        directions_[s.id] = s.direction;
        ChainSetup cs;
        cs.id = s.id;
        cs.name = s.name;
        cs.direction = s.direction;
        cs.u = f.u, cs.v = f.v, cs.w = f.w;
        if (std::isfinite(s.blankTop)) cs.blankTop = s.blankTop;
        chain_.setups.push_back(cs);
    }
    for (const DomainElement& e : tree_.elements) {
        if (!frames_.count(e.setup))
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
        const auto c = choice_.find(e.id);
        if (c != choice_.end() && c->second->roughingTool >= 0) ce.narrowPassages = c->second->ratio.narrowPassages;
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
        for (const DomainElement* e : elements) listUnmachined(*e);
    }
    // Island tops below the pocket's top: no step of the templates faces them, so the material
    // above them stays. Said, with the faces, rather than left unnoticed.
    std::set<int> topsListed = facedTops_;  // a parent pocket names its child's island top too: once is enough
    for (const DomainElement& e : tree_.elements)
        for (const recognition::AttachedFeature& a : e.attached)
            if (a.kind == "island_top" && !a.faces.empty() && e.type != ElementType::Hole &&
                !std::all_of(a.faces.begin(), a.faces.end(), [&](int f) { return topsListed.count(f) > 0; })) {
                topsListed.insert(a.faces.begin(), a.faces.end());
                Unmachined m;
                m.element = e.id;
                m.faces = a.faces;
                m.reason = "the top of an island below the top of " + elementName(e) +
                           " is not finished: no floor unit of the element faces it";
                chain_.unmachined.push_back(m);
            }

    // The tools: those used, then (for editing) those that could be.
    for (std::size_t i = 0; i < plan_.tools.size(); ++i) {
        const Tool& t = plan_.tools[i];
        const bool used = usedTools_.count(static_cast<int>(i)) > 0;
        if (!used && !(opt_.listCandidateTools && (t.isEndMill() || t.type == "drill"))) continue;
        ChainTool ct = chainTool(t);
        for (const char* op : {"roughing", "finishing", "drilling"})
            if (const auto s = settingOf_(i, op)) ct.settings[op] = toolData(*s);
        if (!used && ct.settings.empty()) continue;
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
