// Machine files: reviewable JSON, one per machine, named like the machines of the knowledge base.
#include <aeronc/core/JsonNesting.h>
#include <aeronc/kinematics/MachineModel.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace aeronc::kinematics {

namespace {

using nlohmann::json;

struct Reader {
    const std::string& source;

    [[noreturn]] void fail(const std::string& what) const {
        throw inputError(source + ": " + what);
    }
    const json& need(const json& j, const char* key, const std::string& where) const {
        if (!j.is_object() || !j.contains(key)) fail("missing \"" + std::string(key) + "\"" + where);
        return j.at(key);
    }
    double number(const json& j, const std::string& what) const {
        if (!j.is_number()) fail(what + " must be a number");
        const double v = j.get<double>();
        if (!std::isfinite(v)) fail(what + " must be finite");
        return v;
    }
    Vec3 vec(const json& j, const std::string& what) const {
        if (!j.is_array() || j.size() != 3) fail(what + " must be [x, y, z]");
        return {number(j[0], what), number(j[1], what), number(j[2], what)};
    }
    double positive(const json& j, const std::string& what) const {
        const double v = number(j, what);
        if (v <= 0) fail(what + " must be positive");
        return v;
    }
    std::string text(const json& j, const std::string& what) const {
        if (!j.is_string()) fail(what + " must be a string");
        return j.get<std::string>();
    }
    Vec3 unit(const json& j, const std::string& what) const {
        const Vec3 v = vec(j, what);
        if (std::abs(v.norm() - 1.0) > 1e-9) fail(what + " must be a unit vector");
        return v.normalized();
    }
};

}  // namespace

int MachineModel::axisIndex(const std::string& n) const {
    for (size_t i = 0; i < rotary.size(); ++i)
        if (rotary[i].name == n) return static_cast<int>(i);
    return -1;
}

std::string MachineModel::kinematicsName() const {
    const bool t0 = rotary.at(0).carrier == Carrier::Table, t1 = rotary.at(1).carrier == Carrier::Table;
    if (t0 && t1) return "table-table";
    if (!t0 && !t1) return "head-head";
    return "head-table";
}

MachineModel machineFromJson(const std::string& text, const std::string& source) {
    checkJsonNesting(text, source);
    json j;
    try {
        j = json::parse(text);
    } catch (const json::exception& e) {
        throw inputError(source + ": not valid JSON (" + e.what() + ")");
    }
    const Reader r{source};
    if (!j.is_object()) r.fail("a machine file holds one JSON object");
    MachineModel m;
    const auto& name = r.need(j, "name", "");
    if (!name.is_string() || name.get<std::string>().empty()) r.fail("\"name\" must be a non-empty string");
    m.name = name.get<std::string>();
    if (j.contains("description")) m.description = r.text(j["description"], "\"description\"");
    if (j.contains("controller")) m.controller = r.text(j["controller"], "\"controller\"");
    if (j.contains("toolDirection")) m.toolDirection = r.unit(j["toolDirection"], "\"toolDirection\"");

    const auto& axes = r.need(j, "rotaryAxes", "");
    if (!axes.is_array() || axes.size() != 2) r.fail("\"rotaryAxes\" must list exactly two rotary axes");
    for (size_t i = 0; i < axes.size(); ++i) {
        const std::string where = " in rotaryAxes[" + std::to_string(i) + "]";
        RotaryAxis a;
        if (!axes[i].is_object()) r.fail("rotaryAxes[" + std::to_string(i) + "] must be an object");
        const auto& n = r.need(axes[i], "name", where);
        if (!n.is_string() || n.get<std::string>().size() != 1 || !std::isupper(static_cast<unsigned char>(n.get<std::string>()[0])))
            r.fail("the name" + where + " must be one capital letter (the NC address)");
        a.name = n.get<std::string>();
        const auto& carrier = r.need(axes[i], "carrier", where);
        if (carrier == "table")
            a.carrier = Carrier::Table;
        else if (carrier == "head")
            a.carrier = Carrier::Head;
        else
            r.fail("\"carrier\"" + where + " must be \"table\" or \"head\"");
        a.direction = r.unit(r.need(axes[i], "direction", where), "\"direction\"" + where);
        a.point = r.vec(r.need(axes[i], "point", where), "\"point\"" + where);
        a.min = r.number(r.need(axes[i], "min", where), "\"min\"" + where);
        a.max = r.number(r.need(axes[i], "max", where), "\"max\"" + where);
        if (a.min > a.max) r.fail("\"min\" > \"max\"" + where);
        m.rotary.push_back(a);
    }
    if (m.rotary[0].name == m.rotary[1].name) r.fail("the two rotary axes have the same name");
    if (m.rotary[0].direction.cross(m.rotary[1].direction).norm() < 1e-6)
        r.fail("the two rotary axes are parallel: the tool axis cannot be oriented");
    for (const char* linear : {"X", "Y", "Z"})
        if (m.rotary[0].name == linear || m.rotary[1].name == linear)
            r.fail(std::string("a rotary axis cannot be called ") + linear);

    if (j.contains("partZero")) m.partZero = r.vec(j["partZero"], "\"partZero\"");
    if (j.contains("linearTravel")) {
        if (!j["linearTravel"].is_object()) r.fail("\"linearTravel\" must be an object {\"X\": [min, max], ...}");
        LinearTravel t;
        const char* names[3] = {"X", "Y", "Z"};
        for (int k = 0; k < 3; ++k) {
            const auto& range = r.need(j["linearTravel"], names[k], " in linearTravel");
            if (!range.is_array() || range.size() != 2) r.fail(std::string("linearTravel.") + names[k] + " must be [min, max]");
            t.min[k] = r.number(range[0], std::string("linearTravel.") + names[k]);
            t.max[k] = r.number(range[1], std::string("linearTravel.") + names[k]);
            if (t.min[k] >= t.max[k]) r.fail(std::string("linearTravel.") + names[k] + ": min >= max");
        }
        m.travel = t;
    }
    if (j.contains("retractDistance")) m.retractDistance = r.positive(j["retractDistance"], "\"retractDistance\"");
    if (j.contains("maxRotaryFeed")) m.maxRotaryFeed = r.positive(j["maxRotaryFeed"], "\"maxRotaryFeed\"");
    // Feeds and speeds beyond these are refused by the posts; the NC words take up to 1e9.
    if (j.contains("maxFeed")) {
        m.maxFeed = r.positive(j["maxFeed"], "\"maxFeed\"");
        if (*m.maxFeed >= 1e9) r.fail("\"maxFeed\" must be below 1e9 mm/min");
    }
    if (j.contains("maxSpindleSpeed")) {
        m.maxSpindleSpeed = r.positive(j["maxSpindleSpeed"], "\"maxSpindleSpeed\"");
        if (*m.maxSpindleSpeed > 2147483647.0) r.fail("\"maxSpindleSpeed\" must fit the S word (at most 2147483647)");
    }
    if (j.contains("sinumerik")) {
        const auto& s = j["sinumerik"];
        if (!s.is_object())
            r.fail("\"sinumerik\" must be an object {\"swivelDataRecord\": ..., \"directionReference\": ...}");
        for (const auto& [k, v] : s.items())
            if (k != "swivelDataRecord" && k != "directionReference") r.fail("unknown entry sinumerik." + k);
        if (s.contains("swivelDataRecord")) {
            m.swivelDataRecord = r.text(s["swivelDataRecord"], "sinumerik.swivelDataRecord");
            // Written inside CYCLE800("..."): a quote or a line break there would end the call.
            const std::string& n = m.swivelDataRecord;
            const bool name = !n.empty() && n.size() <= 32 && std::all_of(n.begin(), n.end(), [](char c) {
                return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
            });
            if (!name) r.fail("sinumerik.swivelDataRecord must be a name of 1 to 32 letters, digits or '_'");
        }
        if (s.contains("directionReference")) {
            const auto ref = r.text(s["directionReference"], "sinumerik.directionReference");
            m.directionReference = m.axisIndex(ref);
            if (m.directionReference < 0) r.fail("sinumerik.directionReference \"" + ref + "\" is not a rotary axis");
        }
    }
    return m;
}

MachineModel loadMachineFile(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw inputError("cannot read machine file " + path);
    std::ostringstream s;
    s << in.rdbuf();
    return machineFromJson(s.str(), path);
}

}  // namespace aeronc::kinematics
