#include <aeronc/kb/OptimiseParameters.h>

#include <aeronc/core/Error.h>

#include <algorithm>

namespace aeronc::kb {

namespace {

std::string name(const nlohmann::json& names, const std::string& key, bool required) {
    if (!names.contains(key)) {
        if (required) throw inputError("\"kb\" needs \"" + key + "\" (the knowledge-base name to look up)");
        return "";
    }
    if (!names.at(key).is_string()) throw inputError("kb." + key + " must be a string");
    return names.at(key).get<std::string>();
}

}  // namespace

nlohmann::json optimiseParameters(const KnowledgeBase& kb, const nlohmann::json& names,
                                  std::optional<double> cutterDiameter) {
    if (!names.is_object()) throw inputError("\"kb\" must be an object naming workpiece_material, tool_material, "
                                             "operation and machine");
    for (const auto& [k, v] : names.items())
        if (k != "workpiece_material" && k != "tool_material" && k != "operation" && k != "machine" && k != "tool")
            throw inputError("unknown key kb." + k);

    const std::string toolId = name(names, "tool", false);
    std::optional<toolselect::Tool> tool;
    if (!toolId.empty()) {
        const auto tools = kb.tools();
        const auto it = std::find_if(tools.begin(), tools.end(), [&](const auto& t) { return t.id == toolId; });
        if (it == tools.end()) throw inputError("knowledge base " + kb.path() + ": unknown tool '" + toolId + "'");
        tool = *it;
    }
    std::string toolMaterial = name(names, "tool_material", !tool);
    if (toolMaterial.empty()) toolMaterial = tool->material;
    if (tool && tool->material != toolMaterial)
        throw inputError("kb.tool '" + toolId + "' is " + tool->material + ", not " + toolMaterial);

    const std::string workpiece = name(names, "workpiece_material", true), operation = name(names, "operation", true);
    // Cutting data may be given by tool diameter: the file's cutter, else the named tool.
    if (!cutterDiameter && tool) cutterDiameter = tool->diameter;
    const CuttingCondition cc = kb.cuttingCondition(workpiece, toolMaterial, operation, cutterDiameter);
    const Machine m = kb.machine(name(names, "machine", true));
    const std::string from = "knowledge base: " + workpiece + " / " + toolMaterial + " / " + operation;

    nlohmann::json j;
    j["machine"] = {{"name", m.name},
                    {"max_spindle_rpm", m.maxSpindleRpm},
                    {"power_kw", m.powerKw},
                    {"max_feed_mm_min", m.maxFeedMmMin},
                    {"max_force_n", m.maxForceN},
                    {"efficiency", m.efficiency},
                    {"source", "knowledge base: machine " + m.name}};
    j["force"] = {{"C_F", cc.cF}, {"x_F", cc.xF}, {"y_F", cc.yF}, {"u_F", cc.uF},
                  {"q_F", cc.qF}, {"w_F", cc.wF}, {"K_Fc", cc.kFc}, {"source", from}};
    // The knowledge base holds the plain Taylor law v_c*T^m = C.
    j["tool_life"] = {{"C_v", cc.taylorC}, {"m", cc.taylorM}, {"source", from}};
    j["cut"] = {{"a_p_mm", cc.ap}};
    j["economics"] = {{"t_c_min", m.toolChangeS / 60.0}};
    // An older or edited knowledge base may lack it: the parameter file must say then.
    if (const auto ra = kb.findThreshold("ra_max_um"))
        j["quality"] = {{"ra_max_um", *ra}, {"source", "knowledge base: threshold ra_max_um"}};
    if (tool) {
        j["cutter"] = {{"id", tool->id},
                       {"diameter_mm", tool->diameter},
                       {"teeth", tool->flutes},
                       {"corner_radius_mm", tool->cornerRadius},
                       {"source", "knowledge base: tool " + tool->id}};
        j["cut"]["a_e_mm"] = cc.aeRatio * tool->diameter;
    }
    j["baseline"] = {{"label", "knowledge base (v_c, f_z)"},
                     {"f_z_mm", cc.fz},
                     {"v_c_m_min", cc.vc},
                     {"source", from}};
    return j;
}

nlohmann::json withKnowledgeBase(const KnowledgeBase& kb, const nlohmann::json& params) {
    if (!params.is_object() || !params.contains("kb"))
        throw inputError("--kb needs a \"kb\" section in the parameter file naming workpiece_material, "
                         "tool_material, operation and machine");
    std::optional<double> diameter;
    if (params.contains("cutter") && params["cutter"].is_object() && params["cutter"].contains("diameter_mm") &&
        params["cutter"]["diameter_mm"].is_number())
        diameter = params["cutter"]["diameter_mm"].get<double>();
    nlohmann::json out = optimiseParameters(kb, params.at("kb"), diameter);
    for (const auto& [k, v] : params.items()) {
        if (v.is_object() && out.contains(k) && out[k].is_object() && k != "baseline") {
            for (const auto& [kk, vv] : v.items()) out[k][kk] = vv;
        } else {
            out[k] = v;
        }
    }
    return out;
}

}  // namespace aeronc::kb
