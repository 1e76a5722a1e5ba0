#pragma once
// A process template (the patent's process-plan template for a part family): the steps a part
// goes through in a chosen priority order, what each machines with which tool and allowances,
// and the sequencing rules (integral-panel paper §2.4) as data. Plain structs: the knowledge
// base fills them (kb/ProcessTemplates.h), the chain reads them.
#include <aeronc/chain/StepCode.h>

#include <string>
#include <vector>

namespace aeronc::chain {

struct TemplateStep {
    StepCode code = StepCode::Rough;
    Existence existence = Existence::May;
    std::vector<std::string> features;  // feature types it machines
    ToolRole role = ToolRole::None;
    double radialAllowance = 0;  // left on the walls, mm
    double axialAllowance = 0;   // left on the floors, mm
    std::string description;

    bool machines(const std::string& featureType) const;
};

enum class RuleKind { ProcessOrder, OuterBeforeInner, HigherZFirst, FeatureTypeOrder, CentreOut };
const char* toString(RuleKind k);  // the knowledge base's key: "process_order", ...

struct SequencingRule {
    int priority = 0;
    RuleKind kind = RuleKind::CentreOut;
    bool largerToolFirst = true;            // process_order
    std::vector<std::string> featureTypes;  // outer_before_inner: the outer ones; feature_type_order: the order
    std::string parameters;                 // as written, for display
};

struct ProcessTemplate {
    std::string name;
    std::string family;
    std::vector<StepCode> requiredSteps;  // the family's must-steps
    std::string stepOrderName;
    std::vector<StepCode> stepOrder;      // the priority order of steps within a setup
    std::vector<TemplateStep> steps;      // in template order
    std::vector<SequencingRule> rules;    // enabled rules, ascending priority

    int rank(StepCode c) const;  // position in stepOrder; -1 when absent
    const TemplateStep* step(StepCode c) const;
};

// A template's rows as the knowledge base keeps them: text, checked by parseTemplate.
struct TemplateRows {
    std::string name, family, requiredSteps, stepOrderName, stepOrder;
    struct Step {
        int position = 0;
        std::string code, existence, features, role;
        double radialAllowance = 0, axialAllowance = 0;
        std::string description;
    };
    std::vector<Step> steps;  // any order; sorted by position
    struct Rule {
        int priority = 0;
        std::string rule, parameters;
        bool enabled = true;
    };
    std::vector<Rule> rules;
};

// Parses and validates; throws aeronc::inputError naming the template and the row at fault.
ProcessTemplate parseTemplate(const TemplateRows& rows);

// One sequencing rule from its key and 'name=value' parameters; throws naming `where`.
SequencingRule parseRule(int priority, const std::string& key, const std::string& parameters,
                         const std::string& where);

// The checks parseTemplate makes, for a template built in code or read from a chain's JSON:
// known and unrepeated codes; the family's must-steps present as must-steps; steps in the
// template's step order; must/may steps naming known feature types and a tool role that
// suits their code; allowances that do not grow along the steps machining a feature type
// (the validity rule on the template itself); rule priorities unique.
void validateTemplate(const ProcessTemplate& t);

}  // namespace aeronc::chain
