#pragma once
// The knowledge base as a source for tool selection: the planner of toolselect/ElementPlanning.h
// fed with the base's tools, thresholds and cutting data, and the spindle speeds and feeds
// of the tools it chose. The selection algorithms themselves know nothing of the database.
#include <aeronc/kb/KnowledgeBase.h>
#include <aeronc/recognition/DomainTree.h>
#include <aeronc/toolselect/ElementPlanning.h>

#include <string>

namespace aeronc::kb {

// Plans every element of `tree` with everything from the knowledge base: its tools, the
// thresholds eta_min and mu_merge, layer_delta_mm as delta (0.2 mm when absent), and the
// roughing cutting data of (material, tool material): a_e = ae_ratio·D, feed = f_z·Z·n,
// n = 1000·v_c/(π·D), a_p. A tool suits the workpiece when the knowledge base has cutting
// data for its material and the operation (finishing, roughing or drilling). Throws
// aeronc::inputError for an unknown workpiece material. The spindle speed is capped at the
// machine's maximum (the named machine, or the knowledge base's first one when `machine` is
// empty): without the cap a layer takes the same time with any diameter and every pair of
// groups would merge. Fills ToolPlan::settings for every (tool, operation) used.
toolselect::ToolPlan planTools(const recognition::DomainTree& tree, const KnowledgeBase& kb,
                               const std::string& material, const std::string& machine = "");

}  // namespace aeronc::kb
