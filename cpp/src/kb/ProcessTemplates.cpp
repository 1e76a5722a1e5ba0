#include <aeronc/core/Error.h>
#include <aeronc/core/SpindleSpeed.h>
#include <aeronc/kb/LongReach.h>
#include <aeronc/kb/ProcessTemplates.h>
#include <aeronc/kb/ToolPlanning.h>
#include <aeronc/toolselect/PlanJson.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <set>
#include <tuple>

namespace aeronc::kb {

namespace {

// A table read through the editor's interface, cells by column name.
class Rows {
public:
    Rows(const KnowledgeBase& kb, const std::string& name) : table_(kb.table(name)) {}
    std::size_t size() const { return table_.rows.size(); }
    std::string text(std::size_t row, const std::string& column) const { return cell(row, column).value_or(""); }
    double number(std::size_t row, const std::string& column) const {
        const std::string t = text(row, column);
        return t.empty() ? 0.0 : std::strtod(t.c_str(), nullptr);
    }
    bool isNull(std::size_t row, const std::string& column) const { return !cell(row, column).has_value(); }

private:
    const Cell& cell(std::size_t row, const std::string& column) const {
        for (std::size_t c = 0; c < table_.columns.size(); ++c)
            if (table_.columns[c].name == column) return table_.rows[row][c];
        throw inputError("knowledge base: table " + table_.name + " has no column '" + column + "'");
    }
    Table table_;
};

std::string listed(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "'" : ", '") + x + "'";
    return s.empty() ? "none" : s;
}

double thresholdOr(const KnowledgeBase& kb, const std::string& name, double fallback) {
    try {
        return kb.threshold(name);
    } catch (const Error&) {
        return fallback;
    }
}

std::string machineOf(const KnowledgeBase& kb, const std::string& machine) {
    if (!machine.empty()) {
        kb.machine(machine);  // throws for an unknown one, listing the known
        return machine;
    }
    const auto names = kb.machineNames();
    return names.empty() ? std::string() : names.front();
}

}  // namespace

std::vector<std::string> processTemplateNames(const KnowledgeBase& kb) {
    const Rows t(kb, "process_template");
    std::vector<std::pair<std::string, std::string>> v;
    for (std::size_t i = 0; i < t.size(); ++i) v.emplace_back(t.text(i, "family"), t.text(i, "name"));
    std::sort(v.begin(), v.end());
    std::vector<std::string> out;
    for (const auto& [family, name] : v) out.push_back(name);
    return out;
}

chain::ProcessTemplate loadProcessTemplate(const KnowledgeBase& kb, const std::string& templateOrFamily) {
    const Rows templates(kb, "process_template");
    std::size_t row = templates.size();
    for (std::size_t i = 0; i < templates.size() && row == templates.size(); ++i)
        if (templates.text(i, "name") == templateOrFamily) row = i;
    if (row == templates.size()) {
        std::string first;
        for (std::size_t i = 0; i < templates.size(); ++i)
            if (templates.text(i, "family") == templateOrFamily &&
                (row == templates.size() || templates.text(i, "name") < first))
                row = i, first = templates.text(i, "name");
    }
    if (row == templates.size()) {
        const Rows families(kb, "part_family");
        std::vector<std::string> f;
        for (std::size_t i = 0; i < families.size(); ++i) f.push_back(families.text(i, "name"));
        throw inputError("knowledge base: no process template or part family '" + templateOrFamily +
                         "' (templates: " + listed(processTemplateNames(kb)) + "; families: " + listed(f) + ")");
    }

    chain::TemplateRows rows;
    rows.name = templates.text(row, "name");
    rows.family = templates.text(row, "family");
    rows.stepOrderName = templates.text(row, "step_order");
    {
        const Rows families(kb, "part_family");
        for (std::size_t i = 0; i < families.size(); ++i)
            if (families.text(i, "name") == rows.family) rows.requiredSteps = families.text(i, "required_steps");
        const Rows orders(kb, "step_order");
        bool found = false;
        for (std::size_t i = 0; i < orders.size(); ++i)
            if (orders.text(i, "name") == rows.stepOrderName) rows.stepOrder = orders.text(i, "codes"), found = true;
        if (!found)
            throw inputError("knowledge base: process template '" + rows.name + "' names the step order '" +
                             rows.stepOrderName + "', which table step_order does not have");
    }
    const Rows steps(kb, "template_step");
    for (std::size_t i = 0; i < steps.size(); ++i) {
        if (steps.text(i, "template") != rows.name) continue;
        chain::TemplateRows::Step s;
        s.position = static_cast<int>(steps.number(i, "position"));
        s.code = steps.text(i, "code");
        s.existence = steps.text(i, "existence");
        s.features = steps.text(i, "features");
        s.role = steps.text(i, "tool_role");
        s.radialAllowance = steps.number(i, "radial_allowance");
        s.axialAllowance = steps.number(i, "axial_allowance");
        s.description = steps.text(i, "description");
        rows.steps.push_back(s);
    }
    const Rows rules(kb, "sequencing_rule");
    for (std::size_t i = 0; i < rules.size(); ++i) {
        if (rules.text(i, "template") != rows.name) continue;
        rows.rules.push_back({static_cast<int>(rules.number(i, "priority")), rules.text(i, "rule"),
                              rules.text(i, "parameters"), rules.number(i, "enabled") != 0});
    }
    try {
        return chain::parseTemplate(rows);
    } catch (const Error& e) {
        throw inputError(std::string("knowledge base: ") + e.what());
    }
}

chain::ToolSettingOf toolSettings(const KnowledgeBase& kb, const std::vector<toolselect::Tool>& tools,
                                  const std::string& material, const std::string& machine) {
    const std::string m = machineOf(kb, machine);
    const double maxRpm = m.empty() ? 0 : kb.machine(m).maxSpindleRpm;
    const double plungeRatio = thresholdOr(kb, "plunge_feed_ratio", 0.3);
    const LongReach longReach = LongReach::of(kb);
    // Shared so copies of the function share what they have looked up.
    using Key = std::tuple<std::string, std::string, double>;
    auto cache = std::make_shared<std::map<Key, std::optional<CuttingCondition>>>();
    return [&kb, tools, material, maxRpm, plungeRatio, longReach, cache](
               std::size_t i, const std::string& op) -> std::optional<toolselect::ToolSetting> {
        if (i >= tools.size()) return std::nullopt;
        const toolselect::Tool& t = tools[i];
        if (op == "drilling" ? t.type != "drill" : !t.isEndMill()) return std::nullopt;
        const Key key{t.material, op, t.diameter};
        auto it = cache->find(key);
        if (it == cache->end()) {
            std::optional<CuttingCondition> c;
            try {
                c = kb.cuttingCondition(material, t.material, op, t.diameter);
            } catch (const Error&) {
            }
            it = cache->emplace(key, c).first;
        }
        if (!it->second) return std::nullopt;
        const CuttingCondition c = longReach.applied(t, *it->second);
        toolselect::ToolSetting s;
        s.tool = static_cast<int>(i);
        s.operation = op;
        s.spindleRpm = spindleSpeed(c.vc, t.diameter);
        if (maxRpm > 0) s.spindleRpm = std::min(s.spindleRpm, maxRpm);
        s.feedMmMin = c.fz * t.flutes * s.spindleRpm;
        s.plungeFeedMmMin = op == "drilling" ? s.feedMmMin : s.feedMmMin * plungeRatio;
        s.vc = c.vc;
        s.fz = c.fz;
        s.ap = c.ap;
        s.ae = c.aeRatio * t.diameter;
        return s;
    };
}

chain::ChainOptions chainOptions(const KnowledgeBase& kb, const std::string& material, const std::string& machine) {
    chain::ChainOptions o;
    o.material = material;
    o.machine = machineOf(kb, machine);
    o.breakthrough = thresholdOr(kb, "breakthrough_mm", o.breakthrough);
    o.restMinArea = thresholdOr(kb, "rest_min_area_mm2", o.restMinArea);
    o.allowanceRatio = thresholdOr(kb, "allowance_max_ratio", o.allowanceRatio);
    // The chamfer mills, each at the finishing data of an end mill of its largest diameter (the
    // cone cuts at smaller diameters, so v_c there is lower: on the safe side).
    const double maxRpm = o.machine.empty() ? 0 : kb.machine(o.machine).maxSpindleRpm;
    const double plungeRatio = thresholdOr(kb, "plunge_feed_ratio", 0.3);
    for (toolselect::EdgeTool t : kb.edgeTools()) {
        if (t.kind != "chamfer") continue;
        std::optional<CuttingCondition> c;
        try {
            c = kb.findCuttingCondition(material, t.material, "finishing", t.diameter);
        } catch (const Error&) {
        }
        if (c) {
            t.spindleRpm = spindleSpeed(c->vc, t.diameter);
            if (maxRpm > 0) t.spindleRpm = std::min(t.spindleRpm, maxRpm);
            t.feedMmMin = c->fz * t.flutes * t.spindleRpm;
            t.plungeFeedMmMin = t.feedMmMin * plungeRatio;
        }
        o.edgeTools.push_back(t);
    }
    return o;
}

namespace {

// The chain of `tree` with the plan `planOf` gives for the machine.
template <class PlanOf>
chain::MachiningChain chainWith(const recognition::DomainTree& tree, const KnowledgeBase& kb,
                                const std::string& material, const std::string& machine,
                                const std::string& templateOrFamily, PlanOf planOf) {
    const chain::ProcessTemplate t = loadProcessTemplate(kb, templateOrFamily);
    const chain::ChainOptions o = chainOptions(kb, material, machine);
    if (tree.elements.empty())
        throw inputError("the part has no domain element: recognition found no pocket, opening or hole to machine");
    const toolselect::ToolPlan& plan = planOf(o.machine);
    return chain::buildChain(tree, plan, t, o, toolSettings(kb, plan.tools, material, o.machine));
}

}  // namespace

chain::MachiningChain planChain(const recognition::DomainTree& tree, const KnowledgeBase& kb,
                                const std::string& material, const std::string& machine,
                                const std::string& templateOrFamily) {
    toolselect::ToolPlan plan;
    return chainWith(tree, kb, material, machine, templateOrFamily, [&](const std::string& m) -> const toolselect::ToolPlan& {
        plan = planTools(tree, kb, material, m);
        return plan;
    });
}

chain::MachiningChain planChain(const recognition::DomainTree& tree, const KnowledgeBase& kb,
                                const toolselect::ToolPlan& toolPlan, const std::string& material,
                                const std::string& machine, const std::string& templateOrFamily) {
    std::set<int> elements;
    for (const auto& e : tree.elements) elements.insert(e.id);
    auto check = [&](int id) {
        if (!elements.count(id))
            throw inputError("the tool plan names element " + std::to_string(id) +
                             ", which the recognised tree does not have; select tools again");
    };
    for (const auto& c : toolPlan.elements) check(c.element);
    for (const auto& h : toolPlan.holes) check(h.element);
    return chainWith(tree, kb, material, machine, templateOrFamily,
                     [&](const std::string&) -> const toolselect::ToolPlan& { return toolPlan; });
}

toolselect::ToolPlan storedToolPlan(const KnowledgeBase& kb, const std::string& toolPlanJson,
                                    const std::string& material) {
    return toolselect::planFromJson(toolPlanJson, material, kb.tools());
}

}  // namespace aeronc::kb
