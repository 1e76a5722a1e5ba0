#include <aeronc/chain/ConstructionRules.h>
#include <aeronc/chain/Fusing.h>
#include <aeronc/chain/Sequencing.h>
#include <aeronc/chain/StockTops.h>
#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace aeronc::chain {

namespace {

constexpr double kEps = 1e-6;  // allowances and diameters compared exactly, up to rounding
constexpr double kTol = 1e-3;  // tool against recognised geometry

std::string fmt(double x) {
    std::ostringstream s;
    s << std::round(x * 1000) / 1000;
    return s.str();
}

// Names of the nodes a message points at.
class Nodes {
public:
    explicit Nodes(const MachiningChain& c) : chain_(c) {
        for (const ChainSetup& s : c.setups)
            for (const ChainProcess& p : s.processes)
                for (const ChainStep& st : p.steps)
                    for (const ChainProgram& pr : st.programs)
                        for (int u : pr.units) process_[u] = &p;
    }
    std::string setup(int id) const {
        const ChainSetup* s = chain_.setup(id);
        return "setup " + (s ? s->name : std::to_string(id));
    }
    std::string unit(const MachiningUnit& u) const {
        std::string n = setup(u.setup);
        const auto p = process_.find(u.id);
        if (p != process_.end()) n += " / process " + std::to_string(p->second->id) + " (" + p->second->tool + ")";
        return n + " / step " + toString(u.step) + " / unit " + std::to_string(u.id) + " (element " +
               std::to_string(u.element) + ")";
    }
    std::string element(const ChainElement& e) const {
        return setup(e.setup) + " / element " + std::to_string(e.id) + " (" + e.featureType + ")";
    }

private:
    const MachiningChain& chain_;
    std::map<int, const ChainProcess*> process_;
};

std::string describeUnit(const MachiningUnit& u) {
    return "unit " + std::to_string(u.id) + " (step " + toString(u.step) + ", " + u.tool + ")";
}

bool holeOp(Operation o) { return o == Operation::Drill || o == Operation::Helix; }

// Does `before` leave nothing for `after` to remove on the same element?
bool covers(const MachiningUnit& before, const MachiningUnit& after) {
    // A chamfer pass cuts the edge no pocket, profile or hole unit touches.
    if (before.operation == Operation::Chamfer || after.operation == Operation::Chamfer) return false;
    if (holeOp(after.operation) != holeOp(before.operation)) return false;
    if (holeOp(after.operation))
        return before.cutter.diameter >= after.cutter.diameter - kEps && before.bottom <= after.bottom + kEps;
    const bool kinds = before.operation == Operation::Pocket || before.operation == after.operation;
    return kinds && before.top >= after.top - kEps && before.bottom <= after.bottom + kEps &&
           before.cutter.diameter <= after.cutter.diameter + kEps &&
           before.cutter.cornerRadius <= after.cutter.cornerRadius + kEps &&
           before.radialAllowance <= after.radialAllowance + kEps &&
           before.axialAllowance <= after.axialAllowance + kEps;
}

}  // namespace

std::vector<RuleCheck> checkRules(const MachiningChain& c) {
    const Nodes nodes(c);
    const ProcessTemplate& t = c.processTemplate;
    std::map<std::string, std::vector<RuleCheck>> fails;
    auto fail = [&](const char* rule, const std::string& node, const std::string& message) {
        fails[rule].push_back({rule, node, false, message});
    };
    std::map<int, const ChainElement*> elements;
    for (const ChainElement& e : c.elements) elements[e.id] = &e;

    // The enabled units in chain order.
    std::vector<const MachiningUnit*> ordered;
    std::set<int> seen;
    for (int id : c.order)
        if (id >= 0 && static_cast<std::size_t>(id) < c.units.size() && seen.insert(id).second &&
            c.units[static_cast<std::size_t>(id)].enabled)
            ordered.push_back(&c.units[static_cast<std::size_t>(id)]);
    int enabled = 0;
    for (const MachiningUnit& u : c.units) enabled += u.enabled;

    // Priority.
    std::map<int, const MachiningUnit*> latest;  // setup -> unit with the highest rank so far
    for (const MachiningUnit* u : ordered) {
        const int r = t.rank(u->step);
        if (r < 0) {
            fail("priority", nodes.unit(*u),
                 std::string("step ") + toString(u->step) + " is not in the step order of template '" + t.name +
                     "' (" + joinCodes(t.stepOrder) + ")");
            continue;
        }
        const auto it = latest.find(u->setup);
        if (it != latest.end() && t.rank(it->second->step) > r)
            fail("priority", nodes.unit(*u),
                 describeUnit(*u) + " comes after " + describeUnit(*it->second) + "; template '" + t.name +
                     "' orders the steps " + joinCodes(t.stepOrder));
        else
            latest[u->setup] = u;
    }

    // Existence.
    std::map<std::pair<int, StepCode>, int> unitsOf;
    for (const MachiningUnit* u : ordered) {
        ++unitsOf[{u->element, u->step}];
        const TemplateStep* s = t.step(u->step);
        if (!s && u->step == StepCode::Edge) continue;  // the edge step needs no template row (StepCode.h)
        if (!s)
            fail("existence", nodes.unit(*u),
                 std::string("template '") + t.name + "' has no step " + toString(u->step));
        else if (s->existence == Existence::MustNot)
            fail("existence", nodes.unit(*u),
                 std::string("step ") + toString(u->step) + " (" + describe(u->step) + ") must not exist in template '" +
                     t.name + "'");
    }
    std::set<std::pair<int, StepCode>> excused;
    for (const Unmachined& m : c.unmachined)
        if (m.step) excused.insert({m.element, *m.step});
    for (const ChainElement& e : c.elements)
        for (const TemplateStep& s : t.steps) {
            if (s.existence != Existence::Must || !s.machines(e.featureType)) continue;
            if (unitsOf.count({e.id, s.code}) || excused.count({e.id, s.code})) continue;
            // A must-step with nothing left to do: a floor an earlier unit already finished.
            if (s.code == StepCode::Web) {
                bool done = e.featureType == "opening";
                for (const MachiningUnit* u : ordered)
                    if (u->element == e.id && u->operation == Operation::Pocket &&
                        u->axialAllowance <= s.axialAllowance + kEps)
                        done = true;
                if (done) continue;
            }
            // A roughing must-step no roughing tool fits (Fusing plans none): the floor unit,
            // planned from the top (or above the roughing's floor allowance), clears its volume.
            if (s.code == StepCode::Rough) {
                bool cleared = false;
                for (const MachiningUnit* u : ordered)
                    if (u->element == e.id && u->operation == Operation::Pocket && u->step == StepCode::Web &&
                        (u->top >= e.top - kEps || u->top > e.level + s.axialAllowance + kEps))
                        cleared = true;
                if (cleared) continue;
            }
            fail("existence", nodes.element(e),
                 std::string("no enabled unit of the must-step ") + toString(s.code) + " (" + describe(s.code) +
                     ") machines element " + std::to_string(e.id));
        }

    // Validity and removal, element by element along the order.
    std::map<int, std::vector<const MachiningUnit*>> byElement;
    for (const MachiningUnit* u : ordered) byElement[u->element].push_back(u);
    for (const auto& entry : byElement) {
        const int id = entry.first;  // a plain name: lambdas cannot capture structured bindings before C++20
        const auto& list = entry.second;
        const MachiningUnit* prev = nullptr;
        for (const MachiningUnit* u : list) {
            // Holes and chamfer mills follow the element's own sizes, not the pocket's tools.
            if (holeOp(u->operation) || u->operation == Operation::Chamfer) continue;
            if (prev) {
                auto grows = [&](const char* what, double a, double b) {
                    fail("validity", nodes.unit(*u),
                         describeUnit(*u) + " has a larger " + what + " (" + fmt(b) + " mm) than " + describeUnit(*prev) +
                             " before it on element " + std::to_string(id) + " (" + fmt(a) + " mm)");
                };
                if (u->cutter.diameter > prev->cutter.diameter + kEps)
                    grows("tool diameter", prev->cutter.diameter, u->cutter.diameter);
                if (u->radialAllowance > prev->radialAllowance + kEps)
                    grows("radial allowance", prev->radialAllowance, u->radialAllowance);
                if (u->axialAllowance > prev->axialAllowance + kEps)
                    grows("axial allowance", prev->axialAllowance, u->axialAllowance);
            }
            prev = u;
        }
        for (std::size_t k = 0; k < list.size(); ++k) {
            const MachiningUnit* u = list[k];
            bool flagged = false;
            for (std::size_t j = 0; j < k && !flagged; ++j)
                if (covers(*list[j], *u)) {
                    fail("removal", nodes.unit(*u),
                         describeUnit(*u) + " removes no material: " + describeUnit(*list[j]) + " already cut element " +
                             std::to_string(id) + " to " + fmt(list[j]->radialAllowance) + " mm radial / " +
                             fmt(list[j]->axialAllowance) + " mm axial with a tool reaching as far");
                    flagged = true;
                }
            if (flagged || u->operation != Operation::Rest) continue;
            const ChainElement* e = elements.count(id) ? elements[id] : nullptr;
            if (!u->previousCutter) {
                fail("removal", nodes.unit(*u), describeUnit(*u) + " is rest machining after no other unit");
            } else if (u->cutter.diameter >= u->previousCutter->diameter - kEps) {
                fail("removal", nodes.unit(*u),
                     describeUnit(*u) + " removes no material: its " + fmt(u->cutter.diameter) +
                         " mm tool is no smaller than the " + fmt(u->previousCutter->diameter) +
                         " mm tool before it, so it reaches nothing that one left");
            } else if (e && e->minCornerRadius >= 0 && e->narrowPassages == 0 &&
                       0.5 * u->previousCutter->diameter + u->radialAllowance <= e->minCornerRadius + kTol) {
                fail("removal", nodes.unit(*u),
                     describeUnit(*u) + " removes no material: the " + fmt(u->previousCutter->diameter) +
                         " mm tool before it already fits the " + fmt(e->minCornerRadius) + " mm corners");
            }
        }
    }

    // What the chain says a tool leaves on an element (Remainder): the largest radius (corner
    // radius) it accepts for the element's walls (floor), where no tool of the crib fits.
    std::map<int, double> leftCorners, leftFillet;
    for (const Remainder& r : c.remainders) {
        auto& m = r.kind == "corners" ? leftCorners : leftFillet;
        m[r.element] = std::max(m.count(r.element) ? m[r.element] : 0.0, r.toolRadius);
    }
    auto accepted = [](const std::map<int, double>& m, int element, double radius) {
        const auto it = m.find(element);
        return it != m.end() && radius <= it->second + kTol;
    };

    // Fit of each tool to its element.
    for (const MachiningUnit* u : ordered) {
        const ChainTool* tool = c.tool(u->tool);
        const std::string node = nodes.unit(*u);
        if (!tool) {
            fail("fit", node, "tool '" + u->tool + "' is not in the chain's tool list");
            continue;
        }
        const std::string who = "tool " + tool->id + " (D" + fmt(tool->diameter) + ")";
        const bool endMill = tool->type == "flat" || tool->type == "bull" || tool->type == "ball";
        if (u->operation == Operation::Chamfer) {
            // A chamfer mill: its angle and cover were checked when it was chosen (EdgeTools.h).
            if (tool->type != "chamfer") fail("fit", node, who + " is a " + tool->type + ", not a chamfer mill");
            else if (!tool->settings.count("finishing"))
                fail("fit", node, who + " has no cutting data for finishing in " + c.material);
            continue;
        }
        if (u->operation == Operation::Drill ? tool->type != "drill" : !endMill) {
            fail("fit", node, who + " is a " + tool->type + (u->operation == Operation::Drill ? ", not a drill" : ", not an end mill"));
            continue;
        }
        const ChainElement* e = elements.count(u->element) ? elements[u->element] : nullptr;
        if (!e) continue;
        const double top = holeOp(u->operation) ? u->top : e->top;
        if (tool->usableLength() + kTol < top - u->bottom)
            fail("fit", node,
                 who + " reaches " + fmt(tool->usableLength()) + " mm; the unit goes " + fmt(top - u->bottom) + " mm deep");
        if ((u->operation == Operation::Profile || u->operation == Operation::Rest) && e->minCornerRadius >= 0 &&
            0.5 * tool->diameter > e->minCornerRadius + kTol && !accepted(leftCorners, e->id, 0.5 * tool->diameter))
            fail("fit", node, who + " is wider than the " + fmt(e->minCornerRadius) + " mm corners of element " +
                                  std::to_string(e->id));
        if ((u->operation == Operation::Profile || u->step == StepCode::Web) && e->featureType != "open_pocket" &&
            e->featureType != "flange" && e->minWidth > 0 && tool->diameter > e->minWidth - 2 * u->radialAllowance + kTol)
            fail("fit", node, who + " does not pass the " + fmt(e->minWidth) + " mm narrowest width of element " +
                                  std::to_string(e->id) + " with " + fmt(u->radialAllowance) + " mm allowance");
        if (u->step == StepCode::Web && tool->cornerRadius > std::max(0.0, e->floorFilletRadius) + kTol &&
            !accepted(leftFillet, e->id, tool->cornerRadius))
            fail("fit", node, who + " has a larger corner radius than the " + fmt(std::max(0.0, e->floorFilletRadius)) +
                                  " mm floor fillet of element " + std::to_string(e->id));
        if (e->holeDiameter) {
            if (u->operation == Operation::Drill && std::fabs(tool->diameter - *e->holeDiameter) > 0.01)
                fail("fit", node, who + " does not drill the " + fmt(*e->holeDiameter) + " mm hole");
            if (u->operation == Operation::Helix && tool->diameter >= *e->holeDiameter - kTol)
                fail("fit", node, who + " does not fit inside the " + fmt(*e->holeDiameter) + " mm hole");
        }
        if (!tool->settings.count(settingOperation(u->step)) &&
            !(u->operation != Operation::Drill && (tool->settings.count("roughing") || tool->settings.count("finishing"))))
            fail("fit", node, who + " has no cutting data for " + settingOperation(u->step) + " in " + c.material);
    }

    const std::pair<const char*, std::string> rules[] = {
        {"priority", "every setup follows the step order " + joinCodes(t.stepOrder)},
        {"existence", "every must-step exists where it applies and no must_not step does"},
        {"validity", "tool diameters and allowances never grow along the units of an element"},
        {"removal", "every unit removes material"},
        {"fit", "every tool suits its element"},
    };
    std::vector<RuleCheck> out;
    for (const auto& [rule, holds] : rules) {
        auto it = fails.find(rule);
        if (it == fails.end())
            out.push_back({rule, "chain", true, holds + " (" + std::to_string(enabled) + " enabled units)"});
        else
            out.insert(out.end(), it->second.begin(), it->second.end());
    }
    return out;
}

void arrange(MachiningChain& c) {
    int processId = 0, number = 0;
    std::map<std::string, int> numbers;
    for (ChainSetup& s : c.setups) {
        s.processes.clear();
        for (int id : c.order) {
            MachiningUnit& u = c.units[static_cast<std::size_t>(id)];
            if (u.setup != s.id) continue;
            if (s.processes.empty() || s.processes.back().tool != u.tool)
                s.processes.push_back({++processId, c.machine, u.tool, {}});
            ChainProcess& p = s.processes.back();
            if (p.steps.empty() || p.steps.back().code != u.step) p.steps.push_back({u.step, {{u.tool, {}}}});
            p.steps.back().programs.back().units.push_back(id);
            if (u.enabled && !numbers.count(u.tool)) numbers[u.tool] = ++number;
        }
    }
    for (std::size_t i = 0; i < c.order.size(); ++i) {
        MachiningUnit& u = c.units[static_cast<std::size_t>(c.order[i])];
        u.order = static_cast<int>(i);
        const auto n = numbers.find(u.tool);
        u.toolNumber = n == numbers.end() ? 0 : n->second;
    }
    for (ChainTool& t : c.tools) {
        const auto n = numbers.find(t.id);
        t.number = n == numbers.end() ? 0 : n->second;
    }
    setStockTops(c);
}

MachiningChain checkChain(MachiningChain c) {
    for (std::size_t i = 0; i < c.units.size(); ++i)
        if (c.units[i].id != static_cast<int>(i))
            throw inputError("units[" + std::to_string(i) + "]: id " + std::to_string(c.units[i].id) +
                             " where " + std::to_string(i) + " belongs (units are numbered from 0 in order)");
    if (c.order.size() != c.units.size())
        throw inputError("order: lists " + std::to_string(c.order.size()) + " units; the chain has " +
                         std::to_string(c.units.size()) + ", each must be listed once");
    std::vector<char> listed(c.units.size(), 0);
    for (std::size_t i = 0; i < c.order.size(); ++i) {
        const int id = c.order[i];
        if (id < 0 || static_cast<std::size_t>(id) >= c.units.size())
            throw inputError("order[" + std::to_string(i) + "]: no unit " + std::to_string(id));
        if (listed[static_cast<std::size_t>(id)]++)
            throw inputError("order[" + std::to_string(i) + "]: unit " + std::to_string(id) + " is listed twice");
    }

    // The tool list says what a tool is and how it cuts.
    for (MachiningUnit& u : c.units) {
        const ChainTool* t = c.tool(u.tool);
        if (!t) continue;
        u.cutter = {t->diameter, t->cornerRadius, t->type, t->tipDiameter, t->includedAngle};
        std::string op = settingOperation(u.step);
        if (!t->settings.count(op) && u.operation != Operation::Drill)
            op = op == "roughing" ? "finishing" : "roughing";
        const auto s = t->settings.find(op);
        if (s == t->settings.end()) continue;
        u.setting = {s->second.spindleRpm, s->second.feedMmMin, s->second.plungeFeedMmMin};
        u.stepDown = std::min(s->second.ap, t->fluteLength);  // as Fusing: a layer no higher than the flutes
        u.stepOver = u.operation == Operation::Drill ? 0 : s->second.ae;
        if (u.operation == Operation::Chamfer) {  // as Fusing: one pass at the chamfer's depth, one across
            u.stepDown = u.top - u.bottom;
            u.stepOver = 2 * u.edgeOffset;
            continue;
        }
        if (u.step == StepCode::Web) {
            const auto r = t->settings.find("roughing");
            u.stepOver = r != t->settings.end() ? r->second.ae : 0.5 * t->diameter;
        }
        // A floor pass, or a rest unit down to the floor's final height, leaves the floor's scallop.
        if (u.step == StepCode::Web || (u.operation == Operation::Rest && u.axialAllowance <= 1e-9))
            u.stepOver = std::min(u.stepOver, floorStepOver(t->diameter, t->cornerRadius, ChainOptions{}.floorScallop));
    }
    // A rest unit follows the last pocket unit that cleared its element's full height (a floor
    // pass leaves the walls as they were).
    std::map<int, std::vector<const MachiningUnit*>> pockets;
    for (int id : c.order) {
        MachiningUnit& u = c.units[static_cast<std::size_t>(id)];
        if (!u.enabled) continue;
        if (u.operation == Operation::Rest) {
            u.previousCutter.reset();
            u.previousAllowance.reset();
            for (const MachiningUnit* p : pockets[u.element])
                if (p->top >= u.top - kEps) u.previousCutter = p->cutter, u.previousAllowance = p->radialAllowance;
        }
        if (u.operation == Operation::Pocket) pockets[u.element].push_back(&u);
    }
    arrange(c);
    c.travel.optimised = travelOf(c, c.order);
    c.travel.savedPercent =
        c.travel.rulesOnly > 0 ? 100.0 * (c.travel.rulesOnly - c.travel.optimised) / c.travel.rulesOnly : 0.0;
    c.checks = checkRules(c);
    return c;
}

}  // namespace aeronc::chain
