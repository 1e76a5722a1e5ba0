#pragma once
// The knowledge base as a source for the cutting-parameter optimiser: the sections of its
// parameter file (see aeronc/optimise/ProblemJson.h) filled from one cutting condition
// (workpiece material x tool material x operation), one machine and optionally one tool.
// The optimiser itself knows nothing of the database; this only writes JSON.
#include <aeronc/kb/KnowledgeBase.h>

#include <nlohmann/json.hpp>

#include <optional>

namespace aeronc::kb {

// names: {"workpiece_material", "tool_material", "operation", "machine", "tool"?}; tool_material
// may be left out when a tool is named (its material is used). Unknown names are inputErrors.
// Fills machine, force, tool_life (plain Taylor C and m), quality (threshold ra_max_um),
// economics.t_c_min (the machine's tool-change time), cut.a_p_mm, baseline (the row's v_c
// and f_z) and, with a tool, cutter and cut.a_e_mm (a_e/d ratio x diameter). Cutting data
// given by diameter range is chosen with cutterDiameter, else with the named tool's diameter.
nlohmann::json optimiseParameters(const KnowledgeBase& kb, const nlohmann::json& names,
                                  std::optional<double> cutterDiameter = std::nullopt);

// The parameter file `params` completed from the knowledge base with its "kb" names: the
// file's own values win key by key; its baseline and references, if any, replace the base's.
nlohmann::json withKnowledgeBase(const KnowledgeBase& kb, const nlohmann::json& params);

}  // namespace aeronc::kb
