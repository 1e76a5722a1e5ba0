#include <aeronc/toolpath/ToolpathJson.h>

#include <aeronc/core/Error.h>
#include <aeronc/toolpath/Drilling.h>
#include <aeronc/toolpath/HelicalHole.h>
#include <aeronc/toolpath/PocketClearing.h>
#include <aeronc/toolpath/Profile.h>
#include <aeronc/toolpath/RestCorners.h>

#include "Validate.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <set>

namespace aeronc::toolpath {

namespace {
using json = nlohmann::json;

// The keys each operation takes (the milling ones are accepted, and unused, by drilling too);
// anything else is a mistake worth naming.
const std::set<std::string> kCommon{"operation", "name", "cutter", "top", "bottom", "safeHeight", "stockTop", "clearance",
                                    "stepDown", "stepOver", "radialAllowance", "axialAllowance", "rampAngle",
                                    "chordTolerance", "climb"};

std::set<std::string> keysOf(const std::string& op) {
    std::set<std::string> k = kCommon;
    auto add = [&](std::initializer_list<const char*> more) { k.insert(more.begin(), more.end()); };
    if (op == "pocket" || op == "rest") add({"contour", "islands", "islandTops", "faceIslandTops", "openEdges", "floorFilletRadius", "finishingPass",
                                             "finishingAllowance"});
    if (op == "rest") add({"previousCutter", "previousAllowance"});
    if (op == "profile")
        add({"contour", "closed", "side", "lead", "leadRadius", "startLimit", "endLimit", "floorFilletRadius", "clearOf"});
    if (op == "helix") add({"holes", "finishingAllowance", "breakThrough"});
    if (op == "drill") add({"holes", "retractHeight", "peck", "dwell", "pointAngle", "breakThrough"});
    return k;
}

Point point(const json& j) {
    if (!j.is_array() || j.size() != 2) throw inputError("a point must be [u, v]");
    return {j[0].get<double>(), j[1].get<double>()};
}

Loop loop(const json& j) {
    if (!j.is_array()) throw inputError("a loop must be a list of [u, v] points");
    Loop l;
    for (const auto& p : j) l.push_back(point(p));
    return l;
}

Cutter cutter(const json& j) {
    if (!j.is_object() || !j.contains("diameter")) throw inputError("a cutter needs {\"diameter\": ...}");
    return {j.at("diameter").get<double>(), j.value("cornerRadius", 0.0)};
}

template <class T>
void get(const json& j, const char* key, T& v) {
    if (j.contains(key)) v = j.at(key).get<T>();
}

void getOptional(const json& j, const char* key, std::optional<double>& v) {
    if (j.contains(key) && !j.at(key).is_null()) v = j.at(key).get<double>();
}

void milling(const json& j, CutParameters& p) {
    getOptional(j, "safeHeight", p.safeHeight);
    getOptional(j, "stockTop", p.stockTop);
    getOptional(j, "stepOver", p.stepOver);
    get(j, "clearance", p.clearance);
    get(j, "stepDown", p.stepDown);
    get(j, "radialAllowance", p.radialAllowance);
    get(j, "axialAllowance", p.axialAllowance);
    get(j, "rampAngle", p.rampAngleDeg);
    get(j, "chordTolerance", p.chordTolerance);
    get(j, "climb", p.climb);
}

double required(const json& j, const char* key) {
    if (!j.contains(key)) throw inputError(std::string("missing \"") + key + "\"");
    return j.at(key).get<double>();
}

PocketUnit pocketUnit(const json& j) {
    PocketUnit u;
    if (!j.contains("contour")) throw inputError("missing \"contour\"");
    u.contour = loop(j.at("contour"));
    if (j.contains("islands"))
        for (const auto& i : j.at("islands")) u.islands.push_back(loop(i));
    if (j.contains("openEdges"))
        for (const auto& e : j.at("openEdges")) {
            if (!e.is_array() || e.size() != 2) throw inputError("an open edge must be [[u, v], [u, v]]");
            u.openEdges.push_back({point(e[0]), point(e[1])});
        }
    if (j.contains("islandTops") && !j.at("islandTops").is_null()) {
        const json& t = j.at("islandTops");
        if (!t.is_array() || t.size() != u.islands.size())
            throw inputError("\"islandTops\" needs one height (or null) per island");
        for (const auto& h : t) u.islandTops.push_back(h.is_null() ? std::nan("") : h.get<double>());
    }
    get(j, "faceIslandTops", u.faceIslandTops);
    u.top = required(j, "top");
    u.bottom = required(j, "bottom");
    get(j, "floorFilletRadius", u.floorFilletRadius);
    return u;
}

std::vector<Hole> holes(const json& j) {
    if (!j.contains("holes") || !j.at("holes").is_array()) throw inputError("missing \"holes\"");
    std::vector<Hole> out;
    for (const auto& h : j.at("holes")) {
        Hole x;
        x.centre = {required(h, "u"), required(h, "v")};
        x.diameter = h.value("diameter", 0.0);
        x.top = required(h, "top");
        x.bottom = required(h, "bottom");
        x.through = h.value("through", false);
        x.floorFilletRadius = h.value("floorFilletRadius", 0.0);
        out.push_back(x);
    }
    return out;
}

Toolpath compute(const json& j) {
    if (!j.is_object()) throw inputError("a unit must be a JSON object");
    if (!j.contains("operation")) throw inputError("missing \"operation\"");
    const std::string op = j.at("operation").get<std::string>();
    if (op != "pocket" && op != "profile" && op != "helix" && op != "drill" && op != "rest")
        throw inputError("unknown operation '" + op + "' (pocket, profile, helix, drill, rest)");
    const auto keys = keysOf(op);
    for (auto it = j.begin(); it != j.end(); ++it)
        if (!keys.count(it.key())) throw inputError("unknown key \"" + it.key() + "\" for operation " + op);
    if (!j.contains("cutter")) throw inputError("missing \"cutter\"");
    const Cutter c = cutter(j.at("cutter"));

    if (op == "pocket" || op == "rest") {
        PocketParameters p;
        milling(j, p);
        get(j, "finishingPass", p.finishingPass);
        get(j, "finishingAllowance", p.finishingAllowance);
        const PocketUnit u = pocketUnit(j);
        if (op == "pocket") return pocketClearing(u, c, p);
        if (!j.contains("previousCutter")) throw inputError("missing \"previousCutter\"");
        std::optional<double> before;
        if (j.contains("previousAllowance") && !j.at("previousAllowance").is_null()) {
            if (!j.at("previousAllowance").is_number()) throw inputError("\"previousAllowance\" must be a number");
            before = j.at("previousAllowance").get<double>();
        }
        return restCorners(u, cutter(j.at("previousCutter")), c, p, before);
    }
    if (op == "profile") {
        ProfileParameters p;
        milling(j, p);
        ProfileUnit u;
        if (!j.contains("contour")) throw inputError("missing \"contour\"");
        u.drive = loop(j.at("contour"));
        get(j, "closed", u.closed);
        u.top = required(j, "top");
        u.bottom = required(j, "bottom");
        get(j, "floorFilletRadius", u.floorFilletRadius);
        if (u.floorFilletRadius < 0) throw inputError("floorFilletRadius must be at least 0");
        if (j.contains("clearOf")) {
            if (!j.at("clearOf").is_array()) throw inputError("\"clearOf\" must be a list of polylines");
            for (const auto& w : j.at("clearOf")) {
                Loop l = loop(w);
                if (l.size() < 2) throw inputError("a polyline of \"clearOf\" needs two points at least");
                for (const Point& q : l) {
                    requireFinite(q[0], "a point of clearOf");
                    requireFinite(q[1], "a point of clearOf");
                }
                u.clearOf.push_back(std::move(l));
            }
        }
        if (j.contains("startLimit")) u.startLimit = point(j.at("startLimit"));
        if (j.contains("endLimit")) u.endLimit = point(j.at("endLimit"));
        p.side = u.closed ? ToolSide::Outside : ToolSide::Left;
        if (j.contains("side")) {
            const auto s = j.at("side").get<std::string>();
            if (s == "outside") p.side = ToolSide::Outside;
            else if (s == "inside") p.side = ToolSide::Inside;
            else if (s == "left") p.side = ToolSide::Left;
            else if (s == "right") p.side = ToolSide::Right;
            else throw inputError("unknown side '" + s + "' (outside, inside, left, right)");
        }
        if (j.contains("lead")) {
            const auto l = j.at("lead").get<std::string>();
            if (l == "arc") p.lead = Lead::Arc;
            else if (l == "line") p.lead = Lead::Line;
            else if (l == "none") p.lead = Lead::None;
            else throw inputError("unknown lead '" + l + "' (arc, line, none)");
        }
        getOptional(j, "leadRadius", p.leadRadius);
        return profile(u, c, p);
    }
    if (op == "helix") {
        HelicalHoleParameters p;
        milling(j, p);
        get(j, "finishingAllowance", p.finishingAllowance);
        get(j, "breakThrough", p.breakThrough);
        return helicalHole(holes(j), c, p);
    }
    DrillParameters p;
    getOptional(j, "safeHeight", p.safeHeight);
    getOptional(j, "stockTop", p.stockTop);
    getOptional(j, "retractHeight", p.retractHeight);
    get(j, "clearance", p.clearance);
    get(j, "peck", p.peck);
    get(j, "dwell", p.dwell);
    get(j, "pointAngle", p.pointAngleDeg);
    get(j, "breakThrough", p.breakThrough);
    return drilling(holes(j), c, p);
}

}  // namespace

namespace {

// Fixed point to 1e-6 mm with trailing zeros dropped: exact enough for any post, and a
// fraction of the size and time of shortest-round-trip doubles.
void number(std::string& out, double v) {
    if (!std::isfinite(v)) throw Error(Error::Kind::Internal, "a toolpath value is not finite");
    long long n = std::llround(v * 1e6);
    if (n < 0) out += '-', n = -n;
    char b[24];
    int len = 0;
    long long whole = n / 1000000, frac = n % 1000000;
    do b[len++] = char('0' + whole % 10), whole /= 10;
    while (whole);
    while (len) out += b[--len];
    if (frac) {
        int digits = 6;
        while (frac % 10 == 0) frac /= 10, --digits;
        out += '.';
        for (int k = digits - 1; k >= 0; --k) b[k] = char('0' + frac % 10), frac /= 10;
        out.append(b, std::size_t(digits));
    }
}

}  // namespace

std::string toJson(const Toolpath& t) {
    std::string out;
    out.reserve(t.moves.size() * 36 + 64);
    out += "{\"moves\":[";
    for (std::size_t i = 0; i < t.moves.size(); ++i) {
        const Move& m = t.moves[i];
        out += i ? ",[" : "[";
        out += char('0' + int(m.kind));
        for (double v : {m.u, m.v, m.h}) out += ',', number(out, v);
        if (m.kind == Move::Kind::Drill)
            for (double v : {m.r, m.q, m.dwell}) out += ',', number(out, v);
        out += ']';
    }
    out += "],\"cutLength\":";
    number(out, t.cutLength);
    out += ",\"rapidLength\":";
    number(out, t.rapidLength);
    out += '}';
    return out;
}

std::string toolpathJson(const std::string& unitJson) { return toJson(toolpathOfJson(unitJson)); }

Toolpath toolpathOfJson(const std::string& unitJson) {
    json j;
    try {
        j = json::parse(unitJson);
    } catch (const json::exception& e) {
        throw inputError(std::string("the unit is not valid JSON: ") + e.what());
    }
    const std::string name = j.is_object() && j.contains("name") && j["name"].is_string() ? j["name"].get<std::string>() : "";
    try {
        return compute(j);
    } catch (const Error& e) {
        if (name.empty()) throw;
        throw Error(e.kind(), "unit '" + name + "': " + e.what());
    } catch (const json::exception& e) {
        throw inputError((name.empty() ? "" : "unit '" + name + "': ") + "a value has the wrong type (" + e.what() + ")");
    }
}

}  // namespace aeronc::toolpath
