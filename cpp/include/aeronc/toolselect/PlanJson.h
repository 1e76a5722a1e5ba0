#pragma once
// A tool plan as JSON text, both ways: what `aeronc select-tools` prints and what Select tools
// stores on a Machining Features group (ToolPlan), read back so the machining chain takes the
// plan as it was made instead of planning the tools again.
#include <aeronc/toolselect/ElementPlanning.h>

#include <string>
#include <vector>

namespace aeronc::toolselect {

// JSON text of a plan (the CLI's select-tools output).
std::string toJson(const ToolPlan& plan, const std::string& material, int indent = 1);

// The plan toJson wrote, for `material`, its tool ids resolved in `tools` (the list the plan
// was made from, e.g. the knowledge base's: the indices are those planTools gave). What the
// text does not hold stays at its default: the depths of elements and holes, and A_m is taken
// as eta·A. Throws inputError naming the field at fault, a plan made for another material, and
// a tool `tools` lacks or whose dimensions changed since the plan was made.
ToolPlan planFromJson(const std::string& text, const std::string& material, const std::vector<Tool>& tools);

}  // namespace aeronc::toolselect
