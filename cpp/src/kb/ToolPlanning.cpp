#include <aeronc/kb/ToolPlanning.h>

#include <aeronc/core/Error.h>
#include <aeronc/core/SpindleSpeed.h>
#include <aeronc/kb/LongReach.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <tuple>

namespace aeronc::kb {

using toolselect::ElementChoice;
using toolselect::GroupElements;
using toolselect::HoleChoice;
using toolselect::PlanSettings;
using toolselect::Tool;
using toolselect::ToolPlan;
using toolselect::ToolSetting;

namespace {
constexpr double kDefaultDelta = 0.2;
}  // namespace

ToolPlan planTools(const recognition::DomainTree& tree, const KnowledgeBase& kb, const std::string& material,
                   const std::string& machine) {
    const auto known = kb.workpieceMaterials();
    if (std::find(known.begin(), known.end(), material) == known.end()) {
        std::string list;
        for (const auto& m : known) list += (list.empty() ? "" : ", ") + ("'" + m + "'");
        throw inputError("unknown workpiece material '" + material + "' (known: " + list + ")");
    }
    double maxRpm = 0;
    if (!machine.empty()) {
        maxRpm = kb.machine(machine).maxSpindleRpm;
    } else {
        const auto names = kb.machineNames();
        if (!names.empty()) maxRpm = kb.machine(names.front()).maxSpindleRpm;
    }
    PlanSettings s;
    s.etaMin = kb.threshold("eta_min");
    s.muMerge = kb.threshold("mu_merge");
    const double delta = kb.findThreshold("layer_delta_mm").value_or(kDefaultDelta);

    // Cutting data per (tool material, operation, diameter); absent: the tool does not suit the part.
    std::map<std::tuple<std::string, std::string, double>, std::optional<CuttingCondition>> cache;
    auto condition = [&kb, &cache, material](const Tool& tool,
                                             const std::string& op) -> const std::optional<CuttingCondition>& {
        auto key = std::make_tuple(tool.material, op, tool.diameter);
        auto it = cache.find(key);
        if (it == cache.end()) {
            // No row: the tool does not suit; a bad row or file is an error, not a silent skip.
            it = cache.emplace(key, kb.findCuttingCondition(material, tool.material, op, tool.diameter)).first;
        }
        return it->second;
    };
    const LongReach longReach = LongReach::of(kb);
    auto reduced = [&](const Tool& t, const CuttingCondition& c) { return longReach.applied(t, c); };
    const std::vector<Tool> tools = kb.tools();
    s.mayFinish = [&](const Tool& t) { return t.isEndMill() && condition(t, "finishing").has_value(); };
    s.mayRough = [&](const Tool& t) { return t.isEndMill() && condition(t, "roughing").has_value(); };
    s.mayDrill = [&](const Tool& t) { return t.type == "drill" && condition(t, "drilling").has_value(); };
    s.roughingData = [&](std::size_t i) {
        const Tool& t = tools.at(i);
        const auto& found = condition(t, "roughing");
        if (!found)
            throw inputError("tool " + t.id + ": no roughing cutting data for '" + material + "' with '" +
                             t.material + "'");
        const CuttingCondition c = reduced(t, *found);
        return toolselect::roughingCuttingData(t, c.vc, c.fz, c.ap, c.aeRatio, delta, maxRpm);
    };
    ToolPlan plan = toolselect::planTools(tree, tools, s);

    const double plungeRatio = kb.findThreshold("plunge_feed_ratio").value_or(0.3);
    std::set<std::pair<int, std::string>> used;
    for (const ElementChoice& c : plan.elements) {
        if (c.finishingTool >= 0) used.insert({c.finishingTool, "finishing"});
        if (c.roughingTool >= 0) used.insert({c.roughingTool, "roughing"});
    }
    for (const GroupElements& g : plan.groupsAfter) used.insert({g.tool, "roughing"});
    for (const HoleChoice& h : plan.holes)
        if (h.drill >= 0) used.insert({h.drill, "drilling"});
    for (const auto& [index, op] : used) {
        const Tool& t = tools.at(static_cast<std::size_t>(index));
        const auto& found = condition(t, op);
        if (!found) continue;  // the filters above only let tools with data through
        const std::optional<CuttingCondition> c = reduced(t, *found);
        ToolSetting ts;
        ts.tool = index;
        ts.operation = op;
        ts.spindleRpm = spindleSpeed(c->vc, t.diameter);
        if (maxRpm > 0) ts.spindleRpm = std::min(ts.spindleRpm, maxRpm);
        ts.feedMmMin = c->fz * t.flutes * ts.spindleRpm;
        ts.plungeFeedMmMin = op == "drilling" ? ts.feedMmMin : ts.feedMmMin * plungeRatio;
        ts.vc = c->vc;
        ts.fz = c->fz;
        ts.ap = c->ap;
        ts.ae = c->aeRatio * t.diameter;
        plan.settings.push_back(ts);
    }
    return plan;
}

}  // namespace aeronc::kb
