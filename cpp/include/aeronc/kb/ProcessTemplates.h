#pragma once
// Knowledge-base adapter of the machining chain: process templates and sequencing rules read
// from their tables, the cutting data of every tool, and the whole chain of a recognised part
// planned from the knowledge base. The chain core itself (aeronc/chain) takes plain structs.
#include <aeronc/chain/Fusing.h>
#include <aeronc/kb/KnowledgeBase.h>

#include <string>
#include <vector>

namespace aeronc::kb {

// The names of the process templates, by family then name.
std::vector<std::string> processTemplateNames(const KnowledgeBase& kb);

// The template named `templateOrFamily`, or else the default template of the family of that
// name (the template named like the family, else its first by name), with its family's
// required steps, its step order and its enabled sequencing rules; validated
// (chain::parseTemplate). Throws aeronc::inputError naming the template and the row at fault,
// or listing the templates and families there are.
chain::ProcessTemplate loadProcessTemplate(const KnowledgeBase& kb, const std::string& templateOrFamily);

// Spindle speed, feeds, a_p and a_e of `tools` (the list the indices refer to) for the
// workpiece material, as tool planning computes them: n = 1000·v_c/(π·D) capped at the
// machine's maximum, feed f_z·Z·n, plunge feed × plunge_feed_ratio (drilling: the feed).
// The function reads `kb` when called: keep the knowledge base open while it is used.
chain::ToolSettingOf toolSettings(const KnowledgeBase& kb, const std::vector<toolselect::Tool>& tools,
                                  const std::string& material, const std::string& machine);

// Chain options from the thresholds breakthrough_mm and rest_min_area_mm2 (defaults when
// absent); the machine is the named one or the knowledge base's first.
chain::ChainOptions chainOptions(const KnowledgeBase& kb, const std::string& material, const std::string& machine);

// Tool planning (kb::planTools), the template, the cutting data, then
// chain::buildChain. Throws aeronc::inputError for an unknown material, machine, template or
// family, a broken template or rule, and a tree with no domain element.
chain::MachiningChain planChain(const recognition::DomainTree& tree, const KnowledgeBase& kb,
                                const std::string& material, const std::string& machine = "",
                                const std::string& templateOrFamily = "integral_panel");

// The same with the tools planned before (Select tools, `aeronc select-tools`): the plan is
// taken as it is, not made again. Also throws when the plan names an element the tree does
// not have.
chain::MachiningChain planChain(const recognition::DomainTree& tree, const KnowledgeBase& kb,
                                const toolselect::ToolPlan& toolPlan, const std::string& material,
                                const std::string& machine = "",
                                const std::string& templateOrFamily = "integral_panel");

// A tool plan stored as JSON (toolselect::toJson: a Machining Features group's ToolPlan, the
// CLI's select-tools output) read against the knowledge base's tools; throws inputError for a
// plan made for another material or with tools the base no longer has as they were.
toolselect::ToolPlan storedToolPlan(const KnowledgeBase& kb, const std::string& toolPlanJson,
                                    const std::string& material);

}  // namespace aeronc::kb
