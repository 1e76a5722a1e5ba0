#include <aeronc/optimise/ProblemJson.h>

#include <aeronc/core/Error.h>
#include <aeronc/core/JsonNesting.h>

#include <cmath>
#include <set>

namespace aeronc::optimise {

namespace {

using nlohmann::json;

std::string kindOf(const json& v) {
    if (v.is_string()) {
        const auto& t = v.get_ref<const std::string&>();
        return t.size() <= 40 ? json(t).dump(-1, ' ', true) : "a string";
    }
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    if (v.is_null()) return "null";
    return std::string(v.is_array() ? "an array" : "an object");
}

// One JSON object with its path for messages ("force.C_F").
class Section {
public:
    Section(const json& parent, const std::string& key, const std::string& what, std::set<std::string> keys)
        : path_(key) {
        if (!parent.contains(key)) throw inputError("missing section \"" + key + "\" (" + what + ")");
        j_ = &parent.at(key);
        if (!j_->is_object()) throw inputError("\"" + key + "\" must be an object (" + what + ")");
        keys.insert({"source", "notes"});
        for (const auto& [k, v] : j_->items())
            if (!keys.count(k)) throw inputError("unknown key " + path_ + "." + k);
    }
    Section(const json& object, std::string path) : j_(&object), path_(std::move(path)) {}

    bool has(const std::string& key) const { return j_->contains(key) && !j_->at(key).is_null(); }

    double number(const std::string& key, const std::string& what) const {
        if (!has(key)) throw inputError("missing " + path_ + "." + key + " (" + what + ")");
        return numberAt(key);
    }
    double number(const std::string& key, double fallback) const { return has(key) ? numberAt(key) : fallback; }
    std::optional<double> maybe(const std::string& key) const {
        return has(key) ? std::optional<double>(numberAt(key)) : std::nullopt;
    }
    std::string text(const std::string& key, const std::string& fallback) const {
        if (!has(key)) return fallback;
        if (!j_->at(key).is_string()) throw inputError(path_ + "." + key + " must be a string");
        return j_->at(key).get<std::string>();
    }
    int whole(const std::string& key, const std::string& what) const {
        const double v = number(key, what);
        if (v != std::floor(v) || std::abs(v) > 1e6)
            throw inputError(path_ + "." + key + " (" + what + ") must be a whole number");
        return int(v);
    }
    std::vector<double> numbers(const std::string& key) const {
        std::vector<double> out;
        if (!has(key)) return out;
        const json& a = j_->at(key);
        if (!a.is_array()) throw inputError(path_ + "." + key + " must be an array of numbers");
        for (const auto& v : a) {
            if (!v.is_number()) throw inputError(path_ + "." + key + " must be an array of numbers");
            out.push_back(v.get<double>());
        }
        return out;
    }

private:
    double numberAt(const std::string& key) const {
        const json& v = j_->at(key);
        // The value's kind, not the value: it may be any size or depth.
        if (!v.is_number()) throw inputError(path_ + "." + key + " must be a number, got " + kindOf(v));
        return v.get<double>();
    }
    const json* j_;
    std::string path_;
};

}  // namespace

json parameterJson(const std::string& text) {
    checkJsonNesting(text, "the parameter file");
    try {
        return json::parse(text);
    } catch (const json::exception& e) {
        throw inputError(std::string("the parameter file is not valid JSON (") + e.what() + ")");
    }
}

Parameters parseParameters(const json& j) {
    if (!j.is_object()) throw inputError("the parameter file must hold a JSON object");
    static const std::set<std::string> top{"name",      "source", "notes",    "kb",     "cutter",   "cut",
                                           "machine",   "force",  "tool_life", "quality", "economics", "search",
                                           "baseline", "references"};
    for (const auto& [k, v] : j.items())
        if (!top.count(k)) throw inputError("unknown key \"" + k + "\" at the top of the parameter file");

    Parameters out;
    Problem& p = out.problem;
    p.name = j.contains("name") && j["name"].is_string() ? j["name"].get<std::string>() : "";

    const Section cutter(j, "cutter", "the milling cutter: diameter_mm, teeth, corner_radius_mm",
                         {"id", "diameter_mm", "teeth", "corner_radius_mm", "max_chip_load_mm"});
    p.cutter.diameter = cutter.number("diameter_mm", "cutter diameter d_0");
    p.cutter.teeth = cutter.whole("teeth", "number of teeth Z");
    p.cutter.cornerRadius = cutter.number("corner_radius_mm", "corner (nose) radius r");
    p.cutter.maxChipLoad = cutter.number("max_chip_load_mm", 0.0);

    const Section cut(j, "cut", "the operation: length_mm, a_p_mm, a_e_mm", {"length_mm", "a_p_mm", "a_e_mm"});
    p.cut.length = cut.number("length_mm", "cut length L");
    p.cut.depth = cut.number("a_p_mm", "depth of cut a_p");
    p.cut.width = cut.number("a_e_mm", "width of cut a_e");

    const Section m(j, "machine", "the machine's limits",
                    {"name", "min_spindle_rpm", "max_spindle_rpm", "spindle_steps_rpm", "power_kw", "max_feed_mm_min",
                     "max_force_n", "efficiency"});
    p.machine.name = m.text("name", "");
    p.machine.minSpindle = m.number("min_spindle_rpm", p.machine.minSpindle);
    p.machine.maxSpindle = m.number("max_spindle_rpm", "spindle speed limit n_max");
    p.machine.spindleSteps = m.numbers("spindle_steps_rpm");
    p.machine.power = m.number("power_kw", "power limit P_max");
    p.machine.maxFeed = m.number("max_feed_mm_min", "feed limit v_f,max");
    p.machine.maxForce = m.number("max_force_n", "force limit [F]");
    p.machine.efficiency = m.number("efficiency", "drive efficiency eta");

    const Section f(j, "force", "cutting-force coefficients C_F, x_F, y_F, u_F, q_F, w_F, K_Fc",
                    {"C_F", "x_F", "y_F", "u_F", "q_F", "w_F", "K_Fc"});
    p.force.cF = f.number("C_F", "cutting-force coefficient");
    p.force.xF = f.number("x_F", "cutting-force exponent of a_p");
    p.force.yF = f.number("y_F", "cutting-force exponent of f_z");
    p.force.uF = f.number("u_F", "cutting-force exponent of a_e");
    p.force.qF = f.number("q_F", "cutting-force exponent of d_0");
    p.force.wF = f.number("w_F", "cutting-force exponent of n");
    p.force.kFc = f.number("K_Fc", p.force.kFc);

    const Section t(j, "tool_life", "tool-life coefficients C_v and m (and q_v, x_v, y_v, u_v, p_v, K_v)",
                    {"C_v", "m", "q_v", "x_v", "y_v", "u_v", "p_v", "K_v"});
    p.toolLife.cV = t.number("C_v", "tool-life coefficient");
    p.toolLife.m = t.number("m", "tool-life exponent");
    p.toolLife.qV = t.number("q_v", 0.0);
    p.toolLife.xV = t.number("x_v", 0.0);
    p.toolLife.yV = t.number("y_v", 0.0);
    p.toolLife.uV = t.number("u_v", 0.0);
    p.toolLife.pV = t.number("p_v", 0.0);
    p.toolLife.kV = t.number("K_v", 1.0);

    const Section q(j, "quality", "the roughness limit ra_max_um", {"ra_max_um", "ra_coefficient"});
    p.quality.raMax = q.number("ra_max_um", "roughness limit R_a,max");
    p.quality.raCoefficient = q.number("ra_coefficient", p.quality.raCoefficient);

    const Section e(j, "economics", "t_0_min, t_c_min, c_0_per_min, c_t_per_tool_life",
                    {"t_0_min", "t_c_min", "c_0_per_min", "c_t_per_tool_life", "w_time", "w_cost"});
    p.economics.auxiliaryTime = e.number("t_0_min", "auxiliary time per part t_0");
    p.economics.toolChangeTime = e.number("t_c_min", "time per tool change t_c");
    p.economics.machineRate = e.number("c_0_per_min", "machine and operator cost per minute c_0");
    p.economics.toolCost = e.number("c_t_per_tool_life", "tool cost per tool life c_t");
    p.economics.weightTime = e.number("w_time", p.economics.weightTime);
    p.economics.weightCost = e.number("w_cost", p.economics.weightCost);

    if (j.contains("search")) {
        const Section s(j, "search", "the f_z search range", {"f_z_min_mm", "f_z_max_mm"});
        p.feedPerTooth.min = s.number("f_z_min_mm", p.feedPerTooth.min);
        p.feedPerTooth.max = s.number("f_z_max_mm", p.feedPerTooth.max);
    }

    if (j.contains("baseline")) {
        const Section b(j, "baseline", "the handbook cutting data to compare with",
                        {"label", "f_z_mm", "n_rpm", "v_c_m_min", "tool_life_min"});
        BaselineSpec spec;
        spec.label = b.text("label", "baseline");
        spec.fz = b.number("f_z_mm", "baseline feed per tooth");
        spec.n = b.maybe("n_rpm");
        spec.cuttingSpeed = b.maybe("v_c_m_min");
        spec.toolLife = b.maybe("tool_life_min");
        if (int(spec.n.has_value()) + int(spec.cuttingSpeed.has_value()) + int(spec.toolLife.has_value()) != 1)
            throw inputError("baseline needs exactly one of n_rpm, v_c_m_min, tool_life_min");
        for (auto v : {spec.n, spec.cuttingSpeed, spec.toolLife, std::optional<double>(spec.fz)})
            if (v && !(*v > 0 && std::isfinite(*v))) throw inputError("baseline values must be positive");
        out.baseline = spec;
    }

    if (j.contains("references")) {
        if (!j["references"].is_array()) throw inputError("\"references\" must be an array");
        int i = 0;
        for (const auto& r : j["references"]) {
            const std::string path = "references[" + std::to_string(i++) + "]";
            if (!r.is_object()) throw inputError(path + " must be an object");
            for (const auto& [k, v] : r.items())
                if (k != "label" && k != "n_rpm" && k != "f_z_mm" && k != "fitness" && k != "source" && k != "notes")
                    throw inputError("unknown key " + path + "." + k);
            const Section s(r, path);
            ReferencePoint ref;
            ref.label = s.text("label", path);
            ref.n = s.number("n_rpm", "spindle speed");
            ref.fz = s.number("f_z_mm", "feed per tooth");
            ref.fitness = s.maybe("fitness");
            if (!(ref.n > 0 && ref.fz > 0)) throw inputError(path + ": n_rpm and f_z_mm must be positive");
            out.references.push_back(ref);
        }
    }
    validate(p);
    return out;
}

}  // namespace aeronc::optimise
