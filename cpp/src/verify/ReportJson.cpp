#include <aeronc/core/Error.h>
#include <aeronc/verify/ReportJson.h>

#include <algorithm>
#include <cmath>

namespace aeronc::verify {

namespace {

using nlohmann::json;

// Figures to the micrometre: the report is read by people and pictures, not fed back.
double mm(double v) { return std::round(v * 1000) / 1000; }

json eventJson(const MoveEvent& e) {
    return {{"depth", mm(e.depth)},
            {"kind", e.wall ? "wall" : "floor"},
            {"op", e.label},
            {"opIndex", e.operation},
            {"move", e.move},
            {"face", e.face},
            {"position", {mm(e.position[0]), mm(e.position[1]), mm(e.position[2])}},
            {"tip", {mm(e.tip[0]), mm(e.tip[1]), mm(e.tip[2])}}};
}

json checkJson(const CheckResult& r) {
    json list = json::array();
    for (const auto& e : r.listed) list.push_back(eventJson(e));
    return {{"tolerance", r.tolerance},
            {"count", r.moves},
            {"cells", r.cells},
            {"worst", r.worst ? eventJson(*r.worst) : json(nullptr)},
            {"list", list}};
}

json gridJson(const Grid& g) { return {{"nx", g.nx}, {"ny", g.ny}, {"x0", g.x0}, {"y0", g.y0}, {"cell", g.cell}}; }

json valuesJson(const std::vector<float>& v) {
    json a = json::array();
    a.get_ref<json::array_t&>().reserve(v.size());
    for (float x : v) {
        const double r = mm(x);
        if (r == 0) a.push_back(0);
        else a.push_back(r);
    }
    return a;
}

double positive(const json& j, const char* key, double fallback, bool allowZero) {
    if (!j.contains(key)) return fallback;
    if (!j[key].is_number()) throw inputError(std::string("option ") + key + " must be a number");
    const double v = j[key].get<double>();
    if (!std::isfinite(v) || v < 0 || (!allowZero && v == 0))
        throw inputError(std::string("option ") + key + (allowZero ? " must not be negative" : " must be positive"));
    return v;
}

}  // namespace

json toJson(const SimulationReport& r) {
    json ops = json::array();
    for (const auto& o : r.operations) {
        json op = {{"label", o.label},
                   {"moves", o.moves},
                   {"segments", o.segments},
                   {"removedVolume", mm(o.removedVolume)},
                   {"gouges", o.gougingMoves},
                   {"collisions", o.collidingMoves},
                   {"worstGouge", mm(o.worstGouge)},
                   {"worstCollision", mm(o.worstCollision)}};
        if (o.worstGougeAt) op["worstGougeAt"] = eventJson(*o.worstGougeAt);
        if (o.worstCollisionAt) op["worstCollisionAt"] = eventJson(*o.worstCollisionAt);
        ops.push_back(std::move(op));
    }
    json faces = json::array();
    for (const auto& f : r.coverage.faces)
        faces.push_back({{"face", f.face},
                         {"measured", f.measured()},
                         {"floorArea", mm(f.floorArea)},
                         {"wallArea", mm(f.wallArea)},
                         {"uncoveredArea", mm(f.uncoveredArea)},
                         {"maxLeftover", mm(f.maxLeftover)}});
    json elements = json::array();
    for (const auto& e : r.coverage.elements)
        elements.push_back({{"id", e.id},
                            {"faces", e.faces},
                            {"area", mm(e.area)},
                            {"uncoveredArea", mm(e.uncoveredArea)},
                            {"maxLeftover", mm(e.maxLeftover)}});
    json out = {{"grid", gridJson(r.grid)},
                {"part",
                 {{"volume", mm(r.partVolume)},
                  {"triangles", r.triangles},
                  {"inconsistentColumns", r.inconsistentColumns}}},
                {"stock", {{"blankVolume", mm(r.blankVolume)}, {"finalVolume", mm(r.finalStockVolume)}}},
                {"ops", ops},
                {"gouges", checkJson(r.gouges)},
                {"collisions", checkJson(r.collisions)},
                {"coverage",
                 {{"floorTolerance", r.coverage.options.floorTolerance},
                  {"wallTolerance", r.coverage.options.wallTolerance},
                  {"faces", faces},
                  {"elements", elements}}},
                {"timings",
                 {{"rasterise", r.rasteriseSeconds}, {"simulate", r.simulateSeconds}, {"coverage", r.coverageSeconds}}}};
    if (!r.leftover.top.empty()) {
        json m = gridJson(r.leftover.grid);
        m["top"] = valuesJson(r.leftover.top);
        m["bottom"] = valuesJson(r.leftover.bottom);
        out["leftover"] = std::move(m);
    } else {
        out["leftover"] = nullptr;
    }
    return out;
}

SimulationOptions simulationOptionsFromJson(const json& j) {
    SimulationOptions o;
    if (j.is_null()) return o;
    if (!j.is_object()) throw inputError("the simulation options must be a JSON object");
    static const char* known[] = {"gougeTolerance", "collisionTolerance", "floorTolerance", "wallTolerance",
                                  "wallSearch",     "wallBand",           "leftoverMap",    "maxListed",
                                  "deflection",     "angularDeflection"};
    for (auto it = j.begin(); it != j.end(); ++it)
        if (std::none_of(std::begin(known), std::end(known), [&](const char* k) { return it.key() == k; }))
            throw inputError("unknown simulation option '" + it.key() + "'");
    o.gougeTolerance = positive(j, "gougeTolerance", o.gougeTolerance, true);
    o.collisionTolerance = positive(j, "collisionTolerance", o.collisionTolerance, true);
    o.coverage.floorTolerance = positive(j, "floorTolerance", o.coverage.floorTolerance, true);
    o.coverage.wallTolerance = positive(j, "wallTolerance", o.coverage.wallTolerance, true);
    o.coverage.wallSearch = positive(j, "wallSearch", o.coverage.wallSearch, false);
    o.coverage.wallBand = positive(j, "wallBand", o.coverage.wallBand, true);
    if (j.contains("leftoverMap")) {
        if (!j["leftoverMap"].is_boolean()) throw inputError("option leftoverMap must be true or false");
        o.leftoverMap = j["leftoverMap"].get<bool>();
    }
    if (j.contains("maxListed")) {
        if (!j["maxListed"].is_number_integer() || j["maxListed"].get<long long>() < 0)
            throw inputError("option maxListed must be a whole number, 0 or more");
        o.maxListed = int(std::min<long long>(j["maxListed"].get<long long>(), 1'000'000));
    }
    return o;
}

}  // namespace aeronc::verify
