#include <aeronc/core/Error.h>
#include <aeronc/verify/Program.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace aeronc::verify {

namespace {

using nlohmann::json;

double number(const json& v, const std::string& where) {
    if (!v.is_number()) throw inputError(where + " must be a number");
    const double x = v.get<double>();
    if (!std::isfinite(x)) throw inputError(where + " must be finite");
    return x;
}

double numberOr(const json& j, const char* key, double fallback, const std::string& where) {
    return j.contains(key) ? number(j.at(key), where + "." + key) : fallback;
}

int faceNumber(const json& v, const std::string& where) {
    if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 100'000'000)
        throw inputError(where + " must be a face number (1, 2, ...)");
    return v.get<int>();
}

std::vector<int> faceList(const json& v, const std::string& where) {
    if (!v.is_array()) throw inputError(where + " must be a list of face numbers");
    std::vector<int> out;
    for (std::size_t k = 0; k < v.size(); ++k) out.push_back(faceNumber(v[k], where + "[" + std::to_string(k) + "]"));
    return out;
}

Move moveFrom(const json& m, const std::string& where) {
    if (!m.is_array() || m.size() < 4)
        throw inputError(where + " must be [kind, x, y, z] (or [3, x, y, bottom, r, peck, dwell] for a drill cycle)");
    if (!m[0].is_number_integer() || m[0].get<long long>() < 0 || m[0].get<long long>() > 3)
        throw inputError(where + ": kind must be 0 (rapid), 1 (feed), 2 (plunge) or 3 (drill cycle)");
    Move mv;
    mv.kind = MoveKind(m[0].get<int>());
    mv.x = number(m[1], where + " x"), mv.y = number(m[2], where + " y"), mv.z = number(m[3], where + " z");
    if (mv.kind == MoveKind::DrillCycle) {
        if (m.size() < 5) throw inputError(where + ": a drill cycle needs [3, x, y, bottom, r, peck, dwell]");
        mv.retract = number(m[4], where + " r");
        if (m.size() > 5) mv.peck = number(m[5], where + " peck");
        if (m.size() > 6) mv.dwell = number(m[6], where + " dwell");
    } else if (m.size() > 4) {
        throw inputError(where + " has " + std::to_string(m.size()) + " numbers; a move is [kind, x, y, z]");
    }
    return mv;
}

Operation operationFrom(const json& o, const std::string& where) {
    if (!o.is_object()) throw inputError(where + " must be an object");
    Operation op;
    op.label = o.contains("label") && o["label"].is_string() ? o["label"].get<std::string>() : where;
    const std::string name = "operation '" + op.label + "'";
    if (o.contains("axis")) {
        const auto& a = o["axis"];
        if (!a.is_array() || a.size() != 3) throw inputError(name + ": axis must be [0, 0, 1] or [0, 0, -1]");
        const double ax = number(a[0], name + " axis"), ay = number(a[1], name + " axis"),
                     az = number(a[2], name + " axis");
        if (std::abs(ax) > 1e-6 || std::abs(ay) > 1e-6 || std::abs(std::abs(az) - 1) > 1e-6)
            throw inputError(name + ": the tool axis must be +Z or -Z ([0, 0, 1] or [0, 0, -1]); the dexel model "
                                    "verifies 3-axis machining only");
        op.axis = az > 0 ? 1 : -1;
    }
    if (!o.contains("cutter") || !o["cutter"].is_object())
        throw inputError(name + " needs a cutter {\"diameter\", \"cornerRadius\"}");
    const auto& c = o["cutter"];
    if (!c.contains("diameter")) throw inputError(name + ": the cutter needs a diameter");
    try {
        // A chamfer mill gives its included angle and tip diameter: the dexels see its cone.
        op.cutter = c.contains("includedAngle")
                        ? Cutter::cone(number(c["diameter"], name + " cutter diameter"),
                                       numberOr(c, "tipDiameter", 0.0, name + " cutter"),
                                       number(c["includedAngle"], name + " cutter included angle"))
                        : Cutter::fromDiameter(number(c["diameter"], name + " cutter diameter"),
                                               numberOr(c, "cornerRadius", 0.0, name + " cutter"));
    } catch (const Error& e) {
        throw inputError(name + ": " + e.what());
    }
    op.radialAllowance = numberOr(o, "radialAllowance", 0.0, name);
    op.axialAllowance = numberOr(o, "axialAllowance", 0.0, name);
    if (op.radialAllowance <= -op.cutter.radius)
        throw inputError(name + ": a radial allowance of " + std::to_string(op.radialAllowance) +
                         " leaves no cutter");
    if (!o.contains("moves") || !o["moves"].is_array()) throw inputError(name + " needs a list of moves");
    const auto& moves = o["moves"];
    op.moves.reserve(moves.size());
    for (std::size_t k = 0; k < moves.size(); ++k)
        op.moves.push_back(moveFrom(moves[k], name + " move " + std::to_string(k)));
    return op;
}

}  // namespace

Program programFromJson(const json& j) {
    if (!j.is_object()) throw inputError("the program must be a JSON object with \"ops\"");
    Program p;
    p.cellSize = numberOr(j, "cellSize", p.cellSize, "program");
    if (!(p.cellSize > 0)) throw inputError("cellSize must be a positive number of mm");
    if (j.contains("blank") && !j["blank"].is_null()) {
        const auto& b = j["blank"];
        if (!b.is_array() || b.size() != 6) throw inputError("blank must be [xmin, ymin, zmin, xmax, ymax, zmax]");
        for (int k = 0; k < 6; ++k) p.blank[k] = number(b[k], "blank[" + std::to_string(k) + "]");
        if (!(p.blank[3] > p.blank[0] && p.blank[4] > p.blank[1] && p.blank[5] > p.blank[2]))
            throw inputError("blank [xmin, ymin, zmin, xmax, ymax, zmax] has a maximum not above its minimum");
        p.hasBlank = true;
    }
    if (!j.contains("ops") || !j["ops"].is_array()) throw inputError("the program needs \"ops\", a list of operations");
    for (std::size_t k = 0; k < j["ops"].size(); ++k)
        p.operations.push_back(operationFrom(j["ops"][k], "ops[" + std::to_string(k) + "]"));
    if (j.contains("finishedFaces")) p.finishedFaces = faceList(j["finishedFaces"], "finishedFaces");
    if (j.contains("elements")) {
        const auto& e = j["elements"];
        if (!e.is_object()) throw inputError("elements must be an object {\"element id\": [faces]}");
        for (auto it = e.begin(); it != e.end(); ++it)
            p.elements.emplace_back(it.key(), faceList(it.value(), "elements." + it.key()));
    }
    return p;
}

}  // namespace aeronc::verify
