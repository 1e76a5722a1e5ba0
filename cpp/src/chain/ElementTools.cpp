// The tool of a template step on a domain element (see ElementTools.h).
#include "ElementTools.h"

#include <aeronc/core/Error.h>
#include <aeronc/toolselect/Selection.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace aeronc::chain::detail {

using recognition::DomainElement;
using recognition::ElementType;
using toolselect::Tool;

std::string fmt(double x) {
    std::ostringstream s;
    s << std::round(x * 1000) / 1000;
    return s.str();
}

ElementTools::ElementTools(const recognition::DomainTree& tree, const toolselect::ToolPlan& plan,
                           const ProcessTemplate& t, const ChainOptions& o, ToolSettingOf settingOf)
    : plan_(plan), tmpl_(t), opt_(o), settingOf_(std::move(settingOf)) {
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

void ElementTools::addSetup(int id, const recognition::SetupFrame& frame, const Vec3& direction) {
    frames_.emplace(id, frame);
    directions_[id] = direction;
}

const DomainElement* ElementTools::element(int id) const {
    const auto it = byId_.find(id);
    return it == byId_.end() ? nullptr : it->second;
}

const toolselect::ElementChoice* ElementTools::choice(int element) const {
    const auto it = choice_.find(element);
    return it == choice_.end() ? nullptr : it->second;
}

const toolselect::HoleChoice* ElementTools::holeChoice(int element) const {
    const auto it = holeChoice_.find(element);
    return it == holeChoice_.end() ? nullptr : it->second;
}

std::string elementName(const DomainElement& e) {
    return "element " + std::to_string(e.id) + " (" + featureTypeOf(e) + ")";
}

double ElementTools::unitTop(const DomainElement& e, double axialAllowance) const {
    if (e.parent >= 0) {
        const auto it = byId_.find(e.parent);
        if (it != byId_.end() && it->second->type != ElementType::Hole)
            return std::min(e.top, it->second->level + axialAllowance);
    }
    return e.top;
}

double ElementTools::bottomOf(const DomainElement& e) const {
    return e.type == ElementType::Opening ? e.level - opt_.breakthrough : e.level;
}

int ElementTools::plannedRoughingTool(const DomainElement& e) const {
    const auto g = groupTool_.find(e.id);
    if (g != groupTool_.end()) return g->second;
    const auto c = choice_.find(e.id);
    return c == choice_.end() ? -1 : c->second->roughingTool;
}

int ElementTools::roughingTool(const DomainElement& e) const {
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

double ElementTools::allowanceOf(const TemplateStep& step, const Tool& t, const DomainElement* e) const {
    double most = 0, mostFinishing = 0;
    for (const TemplateStep& s : tmpl_.steps) {
        most = std::max(most, s.radialAllowance);
        if (s.role == ToolRole::Finishing) mostFinishing = std::max(mostFinishing, s.radialAllowance);
    }
    const double cap = opt_.allowanceRatio * t.diameter;
    const double scale = most > cap ? cap / most : 1.0;
    double a = step.radialAllowance * scale;
    if (e && step.role == ToolRole::Finishing && e->type != ElementType::OpenPocket && e->minWidth > 0) {
        const double leaves = mostFinishing * scale, room = 0.25 * (e->minWidth - t.diameter - 2 * kTol);
        const bool fits = t.diameter + 2 * leaves <= e->minWidth - kTol;
        if (!fits && room > 0) a *= room / leaves;
    }
    return a;
}

// The offset the toolpath gives a pocket's boundary for tool `t` leaving `ar` (capped as
// allowanceOf caps it), with toolpath::floorFilletOffset's growth where the floor fillet is
// larger than the tool's corner plus the allowance; whether any centre is left inside it.
bool ElementTools::reachesWith(const toolselect::PocketGeometry& g, const DomainElement& e, const Tool& t,
                               double ar) const {
    const double a = std::min(ar, opt_.allowanceRatio * t.diameter);
    const double rf = std::max(0.0, e.floorFilletRadius);
    const double fillet = rf > 0 ? std::max(0.0, rf - (t.cornerRadius + a)) : 0.0;
    return toolselect::machinableRatio(g, t.radius() + a + fillet).eta > 0.0;
}

bool ElementTools::roughingReaches(const DomainElement& e, int r) const {
    if (r < 0) return false;
    if (e.type == ElementType::OpenPocket) return true;
    const auto d = directions_.find(e.setup);
    if (d == directions_.end()) return true;
    try {
        return reachesWith(toolselect::pocketGeometry(e, d->second), e, tool(r), roughingAllowance());
    } catch (const Error&) {
        return true;  // not measured: the toolpath judges
    }
}

// The planner chose the roughing tool by eta without the step's radial allowance. When the
// tool grown by the allowance reaches none of the region (a slot-like opening barely wider
// than the tool), the largest roughing end mill that does; else the planned one.
int ElementTools::roughingToolWithAllowance(const DomainElement& e, int r, double ar) const {
    if (r < 0 || e.type == ElementType::OpenPocket) return r;
    const auto d = directions_.find(e.setup);
    if (d == directions_.end()) return r;
    const toolselect::PocketGeometry g = toolselect::pocketGeometry(e, d->second);
    auto reaches = [&](const Tool& t) { return reachesWith(g, e, t, ar); };
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

double ElementTools::roughingAllowance() const {
    for (const TemplateStep& st : tmpl_.steps)
        if (st.code == StepCode::Rough) return st.radialAllowance;
    return 0.0;
}

std::string ElementTools::planError(const DomainElement& e, bool roughing) const {
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

std::string ElementTools::mismatch(const Tool& t, const DomainElement& e, const TemplateStep& step, Operation op,
                                   double bottom, Leaves leave) const {
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
    const double ar = allowanceOf(step, t, &e);
    if ((op == Operation::Profile || op == Operation::Rest) && !leave.corners) {
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
    if (step.code == StepCode::Web && !leave.fillet && t.cornerRadius > std::max(0.0, e.floorFilletRadius) + kTol)
        return who + " has a " + fmt(t.cornerRadius) + " mm corner radius, larger than the " +
               fmt(std::max(0.0, e.floorFilletRadius)) + " mm floor fillet of " + elementName(e);
    // A floor pass clears the region the toolpath offsets by R + allowance: the narrowest width
    // above is measured on the outline, the offset on the whole region, and only the latter
    // tells whether the toolpath finds room for the tool's centre.
    if (op == Operation::Pocket && step.code == StepCode::Web && e.type != ElementType::OpenPocket) {
        const auto d = directions_.find(e.setup);
        if (d != directions_.end()) {
            bool reaches = true;
            try {
                reaches = reachesWith(toolselect::pocketGeometry(e, d->second), e, t, ar);
            } catch (const Error&) {
                // not measured: the toolpath judges
            }
            if (!reaches)
                return who + " with " + fmt(ar) + " mm allowance leaves no room for its centre in " + elementName(e);
        }
    }
    return "";
}

int ElementTools::finishingTool(const DomainElement& e, std::string& why) const {
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
int ElementTools::finisher(const DomainElement& e, std::string& why) {
    const auto cached = finishers_.find(e.id);
    if (cached != finishers_.end()) {
        why = cached->second.second;
        return cached->second.first;
    }
    const std::string ft = featureTypeOf(e);
    auto suits = [&](const Tool& t, Leaves leave = {}) {
        for (const TemplateStep& s : tmpl_.steps) {
            if (s.existence == Existence::MustNot || !s.machines(ft)) continue;
            Operation op;
            if (s.code == StepCode::Web) op = Operation::Pocket;
            else if (s.code == StepCode::Corner) op = Operation::Rest;
            else if (s.role == ToolRole::Finishing && s.code != StepCode::HoleMill) op = Operation::Profile;
            else continue;
            const std::string m = mismatch(t, e, s, op, bottomOf(e), leave);
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
    // No tool fits everything: the best that fits the rest finishes what it reaches, and the
    // chain lists what it leaves. For corners sharper than every tool, the smallest radius
    // that reaches (it leaves the least); for a floor fillet smaller than the corner of every
    // tool that reaches the floor, the smallest corner radius, then the widest.
    if (best < 0) {
        const double fillet = std::max(0.0, e.floorFilletRadius);
        for (const Leaves leave : {Leaves{true, false}, Leaves{false, true}, Leaves{true, true}}) {
            for (std::size_t i = 0; i < plan_.tools.size(); ++i) {
                const Tool& t = plan_.tools[i];
                if (!t.isEndMill() || t.type == "ball" || t.diameter > maxD + 1e-9 ||
                    !hasSetting(static_cast<int>(i), "finishing"))
                    continue;
                if (!suits(t, leave).empty()) continue;
                if (best < 0) {
                    best = static_cast<int>(i);
                    continue;
                }
                const Tool& b = tool(best);
                const double dr = leave.fillet ? std::max(0.0, t.cornerRadius - fillet) - std::max(0.0, b.cornerRadius - fillet) : 0.0;
                const bool better = leave.corners
                                        ? (std::fabs(dr) > 1e-9 ? dr < 0 : t.diameter < b.diameter - 1e-9)
                                        : (std::fabs(dr) > 1e-9 ? dr < 0 : t.diameter > b.diameter + 1e-9);
                if (better) best = static_cast<int>(i);
            }
            if (best >= 0) {
                // Only what the chosen tool really leaves.
                Leaves really;
                really.corners = leave.corners && e.minCornerRadius >= 0 && tool(best).radius() > e.minCornerRadius + kTol;
                really.fillet = leave.fillet && tool(best).cornerRadius > fillet + kTol;
                leaves_[e.id] = really;
                break;
            }
        }
    }
    if (best >= 0) why.clear();
    finishers_[e.id] = {best, why};
    return best;
}

int ElementTools::floorTool(const DomainElement& e, const TemplateStep& step, std::string& why) {
    // Only when no end mill fits the floor (widestFloorTool) does the element's finishing tool do it.
    const int best = widestFloorTool(e, step);
    if (best >= 0) return best;
    std::string finishWhy;
    const int f = finisher(e, finishWhy);
    if (f >= 0 && mismatch(tool(f), e, step, Operation::Pocket, e.level).empty()) return f;
    // No end mill whose corner fits the fillet reaches the floor: the one with the smallest
    // corner radius that does (then the widest) finishes it and leaves the fillet's foot.
    std::string nearest;
    {
        const int r = roughingTool(e);
        // Between the walls' tool and the roughing tool: the diameters never grow along the steps.
        const double maxD = r >= 0 ? tool(r).diameter : kInf, minD = f >= 0 ? tool(f).diameter : 0.0;
        int best = -1;
        double nearestD = kInf;
        for (std::size_t i = 0; i < plan_.tools.size(); ++i) {
            const Tool& t = plan_.tools[i];
            if (!t.isEndMill() || t.type == "ball" || t.diameter > maxD + 1e-9 || t.diameter < minD - 1e-9) continue;
            if (!hasSetting(static_cast<int>(i), "finishing")) continue;
            if (const std::string m = mismatch(t, e, step, Operation::Pocket, e.level, {false, true}); !m.empty()) {
                // The smallest tool's reason says what the floor lacks (reach, width, corner).
                if (t.diameter < nearestD - 1e-9) nearestD = t.diameter, nearest = m;
                continue;
            }
            if (best < 0 || t.cornerRadius < tool(best).cornerRadius - 1e-9 ||
                (std::fabs(t.cornerRadius - tool(best).cornerRadius) <= 1e-9 && t.diameter > tool(best).diameter + 1e-9))
                best = static_cast<int>(i);
        }
        if (best >= 0) {
            leaves_[e.id].fillet = true;
            return best;
        }
    }
    why = "no end mill with a corner radius of at most " + fmt(std::max(0.0, e.floorFilletRadius)) +
          " mm reaches the " + fmt(e.depth) + " mm deep floor of " + elementName(e);
    if (!nearest.empty()) why += " (the smallest that might: " + nearest + ")";
    return -1;
}

int ElementTools::widestFloorTool(const DomainElement& e, const TemplateStep& step) const {
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

int ElementTools::helixTool(const DomainElement& e, std::string& why) const {
    const recognition::HoleInfo& h = *e.hole;
    const double lo = opt_.helixMinRatio * h.diameter, hi = opt_.helixMaxRatio * h.diameter;
    const double need = h.depth + (h.through ? opt_.breakthrough : 0);
    const bool flatBottom = !h.through;
    // The largest end mill from lo to hi goes down one helix; failing that, the largest below lo
    // clears the hole in rings (toolpath::helicalHole), as a shop mills a hole wider than its cutters.
    auto largest = [&](double from, double to) {
        int best = -1;
        for (std::size_t i = 0; i < plan_.tools.size(); ++i) {
            const Tool& t = plan_.tools[i];
            if (!t.isEndMill() || t.type == "ball") continue;
            if (t.diameter < from - 1e-9 || t.diameter > to + 1e-9) continue;
            if (flatBottom && t.cornerRadius > std::max(0.0, e.floorFilletRadius) + kTol) continue;
            if (t.usableLength() + kTol < need || !millingData(static_cast<int>(i))) continue;
            if (best < 0 || t.diameter > tool(best).diameter + 1e-9 ||
                (std::fabs(t.diameter - tool(best).diameter) <= 1e-9 && t.cornerRadius < tool(best).cornerRadius))
                best = static_cast<int>(i);
        }
        return best;
    };
    int best = largest(lo, hi);
    if (best < 0) best = largest(0, lo - 2e-9);
    if (best < 0)
        why = "no end mill for helical interpolation of " + elementName(e) + " (diameter " + fmt(h.diameter) +
              " mm): it needs one below " + fmt(hi) + " mm reaching " + fmt(need) + " mm" +
              (flatBottom ? " with a flat end" : "");
    return best;
}

}  // namespace aeronc::chain::detail
