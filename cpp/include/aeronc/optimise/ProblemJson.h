#pragma once
// The optimiser's parameter file (JSON). Layout, with units in the key names:
//   cutter     {diameter_mm, teeth, corner_radius_mm, max_chip_load_mm?}
//   cut        {length_mm, a_p_mm, a_e_mm}
//   machine    {name, min_spindle_rpm?, max_spindle_rpm, spindle_steps_rpm?, power_kw,
//               max_feed_mm_min, max_force_n, efficiency}
//   force      {C_F, x_F, y_F, u_F, q_F, w_F, K_Fc?}
//   tool_life  {C_v, m, q_v?, x_v?, y_v?, u_v?, p_v?, K_v?}
//   quality    {ra_max_um, ra_coefficient?}
//   economics  {t_0_min, t_c_min, c_0_per_min, c_t_per_tool_life, w_time?, w_cost?}
//   search     {f_z_min_mm?, f_z_max_mm?}
//   baseline   {label, f_z_mm, and one of n_rpm, v_c_m_min, tool_life_min}        (optional)
//   references [{label, n_rpm, f_z_mm, fitness?}]                                  (optional)
// "name", "source", "notes" and "kb" (names for the knowledge-base adapter) are allowed at the
// top, "source" and "notes" in any section. A key marked ? has the default in Problem.h; any
// other missing value, an unknown key, a wrong type or a non-physical value is an
// aeronc::inputError that names it.
#include <aeronc/optimise/Problem.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace aeronc::optimise {

// A published or known point to print next to ours (e.g. the paper's GA result).
struct ReferencePoint {
    std::string label;
    double n = 0, fz = 0;
    std::optional<double> fitness;  // as printed by its source, on its own scale
};

// The cutting data a handbook (or the knowledge base) recommends, to compare against.
struct BaselineSpec {
    std::string label;
    double fz = 0;
    std::optional<double> n, cuttingSpeed, toolLife;  // exactly one: r/min, m/min, or min
};

struct Parameters {
    Problem problem;
    std::optional<BaselineSpec> baseline;
    std::vector<ReferencePoint> references;
};

Parameters parseParameters(const nlohmann::json& j);

// The parameter file's text as JSON; inputError "not valid JSON (...)" or "nested deeper than
// 64 levels" (aeronc/core/JsonNesting.h) otherwise.
nlohmann::json parameterJson(const std::string& text);

}  // namespace aeronc::optimise
