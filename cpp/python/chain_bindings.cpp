// aeronc._core: the NC machining chain for FreeCAD's Python side. The chain is built from the
// machining-domain tree a recognition stored (its JSON text), and checked again after the
// Machining chain panel's edits (order, tool, enabled); both take and give JSON text.
#include <aeronc/chain/ChainJson.h>
#include <aeronc/chain/ConstructionRules.h>
#include <aeronc/kb/ProcessTemplates.h>
#include <aeronc/recognition/DomainTreeJson.h>

#include <pybind11/pybind11.h>

#include "Guarded.h"

namespace py = pybind11;
using aeronc::python::guarded;

void bindChain(py::module_& m) {
    using namespace aeronc;
    m.def(
        "build_chain",
        [](const std::string& treeJson, const std::string& kbPath, const std::string& material,
           const std::string& sqlFolder, const std::string& machine, const std::string& family,
           const std::string& toolPlanJson) {
            return guarded([&] {
                py::gil_scoped_release nogil;
                const auto tree = recognition::fromJson(treeJson);
                const auto kb = kb::KnowledgeBase::openWithSqlFolder(kbPath, [&] { return sqlFolder; });
                if (toolPlanJson.empty()) return chain::toJson(kb::planChain(tree, kb, material, machine, family), -1);
                const auto plan = kb::storedToolPlan(kb, toolPlanJson, material);
                return chain::toJson(kb::planChain(tree, kb, plan, material, machine, family), -1);
            });
        },
        py::arg("tree_json"), py::arg("kb_path"), py::arg("material"), py::arg("sql_folder"),
        py::arg("machine") = std::string(), py::arg("family") = std::string("integral_panel"),
        py::arg("tool_plan_json") = std::string(),
        "The NC machining chain of a recognised machining-domain tree (the JSON text recognise_* "
        "returned): tools from the knowledge base at kb_path (built from sql_folder when missing), "
        "the process template of `family` (or the template of that name), units, order, travel and "
        "rule checks; returns JSON text (docs/machining-chain.md). tool_plan_json: the tool plan "
        "select_tools_tree made for this tree and material (a Machining Features group's ToolPlan), "
        "taken as it is; empty: the tools are planned here.");
    m.def(
        "check_chain",
        [](const std::string& chainJson) {
            return guarded([&] {
                py::gil_scoped_release nogil;
                return chain::toJson(chain::checkChain(chain::fromJson(chainJson)), -1);
            });
        },
        py::arg("chain_json"),
        "Re-check an edited chain (its order, tools and enabled flags): cutters and cutting data "
        "from its tool list, the seven-level tree, the travel and the construction rules again; "
        "returns the chain's JSON text.");
}
