#include <aeronc/chain/ProcessTemplate.h>
#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace aeronc::chain {

namespace {

constexpr double kEps = 1e-9;

// Whitespace-separated words.
std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

// Comma-separated items, blanks around them dropped.
std::vector<std::string> items(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        const auto b = item.find_first_not_of(" \t");
        if (b == std::string::npos) continue;
        out.push_back(item.substr(b, item.find_last_not_of(" \t") - b + 1));
    }
    return out;
}

std::string known(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

std::string fmt(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

std::vector<std::string> featureList(const std::string& text, const std::string& where) {
    std::vector<std::string> out;
    for (const std::string& f : items(text)) {
        if (!isFeatureType(f))
            throw inputError(where + ": unknown feature type '" + f + "' (known: " + known(featureTypes()) + ")");
        out.push_back(f);
    }
    if (out.empty()) throw inputError(where + ": names no feature type");
    return out;
}

}  // namespace

bool TemplateStep::machines(const std::string& featureType) const {
    return std::find(features.begin(), features.end(), featureType) != features.end();
}

const char* toString(RuleKind k) {
    switch (k) {
        case RuleKind::ProcessOrder: return "process_order";
        case RuleKind::OuterBeforeInner: return "outer_before_inner";
        case RuleKind::HigherZFirst: return "higher_z_first";
        case RuleKind::FeatureTypeOrder: return "feature_type_order";
        case RuleKind::CentreOut: return "centre_out";
    }
    return "?";
}

int ProcessTemplate::rank(StepCode c) const {
    const auto it = std::find(stepOrder.begin(), stepOrder.end(), c);
    // The edges are chamfered after every step that finishes the faces they touch.
    if (it == stepOrder.end() && c == StepCode::Edge) return static_cast<int>(stepOrder.size());
    return it == stepOrder.end() ? -1 : static_cast<int>(it - stepOrder.begin());
}

const TemplateStep* ProcessTemplate::step(StepCode c) const {
    for (const TemplateStep& s : steps)
        if (s.code == c) return &s;
    return nullptr;
}

SequencingRule parseRule(int priority, const std::string& key, const std::string& parameters,
                         const std::string& where) {
    SequencingRule r;
    r.priority = priority;
    r.parameters = parameters;
    std::map<std::string, std::string> params;
    for (const std::string& w : words(parameters)) {
        const auto eq = w.find('=');
        if (eq == std::string::npos || eq == 0)
            throw inputError(where + ": parameter '" + w + "' is not name=value");
        if (!params.emplace(w.substr(0, eq), w.substr(eq + 1)).second)
            throw inputError(where + ": parameter '" + w.substr(0, eq) + "' is given twice");
    }
    std::set<std::string> allowed;
    if (key == "process_order") {
        r.kind = RuleKind::ProcessOrder;
        allowed = {"order"};
        const auto it = params.find("order");
        if (it != params.end()) {
            if (it->second == "larger_tool_first") r.largerToolFirst = true;
            else if (it->second == "smaller_tool_first") r.largerToolFirst = false;
            else
                throw inputError(where + ": order='" + it->second +
                                 "' is neither larger_tool_first nor smaller_tool_first");
        }
    } else if (key == "outer_before_inner") {
        r.kind = RuleKind::OuterBeforeInner;
        allowed = {"outer"};
        if (!params.count("outer")) throw inputError(where + ": needs outer=<feature types> (e.g. outer=open_pocket)");
        r.featureTypes = featureList(params["outer"], where + ", outer");
    } else if (key == "higher_z_first") {
        r.kind = RuleKind::HigherZFirst;
    } else if (key == "feature_type_order") {
        r.kind = RuleKind::FeatureTypeOrder;
        allowed = {"order"};
        if (!params.count("order"))
            throw inputError(where + ": needs order=<feature types> (e.g. order=open_pocket,closed_pocket)");
        r.featureTypes = featureList(params["order"], where + ", order");
        std::set<std::string> seen;
        for (const auto& f : r.featureTypes)
            if (!seen.insert(f).second) throw inputError(where + ": feature type '" + f + "' is listed twice");
    } else if (key == "centre_out") {
        r.kind = RuleKind::CentreOut;
    } else {
        throw inputError(where + ": unknown rule '" + key +
                         "' (known: process_order, outer_before_inner, higher_z_first, feature_type_order, "
                         "centre_out)");
    }
    for (const auto& [name, value] : params)
        if (!allowed.count(name))
            throw inputError(where + ": rule " + key + " takes no parameter '" + name + "'");
    return r;
}

ProcessTemplate parseTemplate(const TemplateRows& rows) {
    const std::string who = "process template '" + rows.name + "'";
    ProcessTemplate t;
    t.name = rows.name;
    t.family = rows.family;
    t.requiredSteps = parseStepCodes(rows.requiredSteps, "part family '" + rows.family + "', required steps");
    t.stepOrderName = rows.stepOrderName;
    t.stepOrder = parseStepCodes(rows.stepOrder, who + ", step order '" + rows.stepOrderName + "'");
    std::vector<TemplateRows::Step> steps = rows.steps;
    std::sort(steps.begin(), steps.end(), [](const auto& a, const auto& b) { return a.position < b.position; });
    for (const auto& s : steps) {
        const std::string where = who + ", step at position " + std::to_string(s.position);
        TemplateStep ts;
        ts.code = parseStepCode(s.code, where);
        ts.existence = parseExistence(s.existence, where);
        ts.role = parseToolRole(s.role, where);
        for (const std::string& f : words(s.features)) {
            if (!isFeatureType(f))
                throw inputError(where + " (" + s.code + "): unknown feature type '" + f + "' (known: " +
                                 known(featureTypes()) + ")");
            ts.features.push_back(f);
        }
        ts.radialAllowance = s.radialAllowance;
        ts.axialAllowance = s.axialAllowance;
        ts.description = s.description;
        t.steps.push_back(ts);
    }
    std::vector<TemplateRows::Rule> rules;
    for (const auto& r : rows.rules)
        if (r.enabled) rules.push_back(r);
    std::sort(rules.begin(), rules.end(), [](const auto& a, const auto& b) { return a.priority < b.priority; });
    for (const auto& r : rules)
        t.rules.push_back(parseRule(r.priority, r.rule, r.parameters,
                                    who + ", sequencing rule " + std::to_string(r.priority) + " (" + r.rule + ")"));
    validateTemplate(t);
    return t;
}

void validateTemplate(const ProcessTemplate& t) {
    const std::string who = "process template '" + t.name + "'";
    if (t.steps.empty()) throw inputError(who + " has no steps");
    std::set<StepCode> seen;
    for (StepCode c : t.stepOrder)
        if (!seen.insert(c).second)
            throw inputError(who + ": step order '" + t.stepOrderName + "' lists '" + toString(c) + "' twice");
    seen.clear();
    for (const TemplateStep& s : t.steps)
        if (!seen.insert(s.code).second)
            throw inputError(who + ": step " + std::string(toString(s.code)) + " appears twice");

    // Existence: the family's must-steps.
    std::vector<std::string> missing;
    for (StepCode c : t.requiredSteps) {
        const TemplateStep* s = t.step(c);
        if (!s || s->existence != Existence::Must)
            missing.push_back(std::string(toString(c)) + " (" + describe(c) + (s ? ", marked " + std::string(toString(s->existence)) : "") + ")");
    }
    if (!missing.empty()) {
        std::string list;
        for (const auto& m : missing) list += (list.empty() ? "" : ", ") + m;
        throw inputError(who + " lacks the must-step" + (missing.size() > 1 ? "s " : " ") + list + " that part family '" +
                         t.family + "' requires");
    }

    // Priority: the steps follow the chosen order.
    int last = -1;
    const TemplateStep* lastStep = nullptr;
    for (const TemplateStep& s : t.steps) {
        const int r = t.rank(s.code);
        if (r < 0)
            throw inputError(who + ": step " + std::string(toString(s.code)) + " is not in its step order '" +
                             t.stepOrderName + "' (" + joinCodes(t.stepOrder) + ")");
        if (r < last)
            throw inputError(who + ": step " + std::string(toString(s.code)) + " comes after step " +
                             toString(lastStep->code) + ", against its step order '" + t.stepOrderName + "' (" +
                             joinCodes(t.stepOrder) + ")");
        last = r;
        lastStep = &s;
    }

    for (const TemplateStep& s : t.steps) {
        const std::string where = who + ", step " + toString(s.code);
        if (!(std::isfinite(s.radialAllowance) && s.radialAllowance >= 0 && std::isfinite(s.axialAllowance) &&
              s.axialAllowance >= 0))
            throw inputError(where + ": allowances must be numbers >= 0");
        if (s.existence == Existence::MustNot) continue;
        if (s.features.empty())
            throw inputError(where + " is '" + toString(s.existence) + "' but names no feature type it machines");
        for (const auto& f : s.features)
            if (!isFeatureType(f))
                throw inputError(where + ": unknown feature type '" + f + "' (known: " + known(featureTypes()) + ")");
        if (s.role == ToolRole::None) throw inputError(where + " names no tool role");
        const bool drill = s.code == StepCode::Drill;
        if (drill != (s.role == ToolRole::Drilling))
            throw inputError(where + ": tool role '" + toString(s.role) + "' " +
                             (drill ? "cannot drill; a d step takes the drilling role"
                                    : "is for the d step only"));
        if ((s.code == StepCode::Corner) != (s.role == ToolRole::Corner))
            throw inputError(where + ": tool role '" + toString(s.role) + "' " +
                             (s.code == StepCode::Corner ? "does not machine corners; a c step takes the corner role"
                                                         : "is for the c step only"));
        const bool holes = s.code == StepCode::Drill || s.code == StepCode::HoleMill;
        for (const auto& f : s.features)
            if ((f == "hole") != holes)
                throw inputError(where + ": " + (holes ? "machines holes only, not " + f
                                                       : std::string("cannot machine holes; the d and h steps do")));
    }

    // Validity on the template: along the steps machining one feature type, the allowances do
    // not grow (a later step that left more would cut air).
    for (const std::string& f : featureTypes()) {
        const TemplateStep* prev = nullptr;
        for (const TemplateStep& s : t.steps) {
            if (s.existence == Existence::MustNot || !s.machines(f)) continue;
            if (prev && (s.radialAllowance > prev->radialAllowance + kEps ||
                         s.axialAllowance > prev->axialAllowance + kEps))
                throw inputError(who + ", step " + toString(s.code) + ": on " + f + " it leaves " +
                                 fmt(s.radialAllowance) + " mm radial / " + fmt(s.axialAllowance) +
                                 " mm axial, more than step " + toString(prev->code) + " before it (" +
                                 fmt(prev->radialAllowance) + " / " + fmt(prev->axialAllowance) +
                                 " mm); allowances must not grow along the steps");
            prev = &s;
        }
    }

    std::set<int> priorities;
    for (const SequencingRule& r : t.rules)
        if (!priorities.insert(r.priority).second)
            throw inputError(who + ": two sequencing rules have priority " + std::to_string(r.priority));
}

}  // namespace aeronc::chain
