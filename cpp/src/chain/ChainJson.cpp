#include <aeronc/chain/ChainJson.h>
#include <aeronc/core/Error.h>

#include <nlohmann/json.hpp>

#include <cmath>

namespace aeronc::chain {

using nlohmann::json;

namespace {

json num(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }
json vec(const Vec3& v) { return json::array({v[0], v[1], v[2]}); }
json pt(const Point2& p) { return json::array({p[0], p[1]}); }
json loop(const Loop& l) {
    json a = json::array();
    for (const Point2& p : l) a.push_back(pt(p));
    return a;
}
json cutter(const Cutter& c) {
    json j = {{"diameter", c.diameter}, {"cornerRadius", c.cornerRadius}, {"type", c.type}};
    if (c.includedAngle > 0) j["tipDiameter"] = c.tipDiameter, j["includedAngle"] = c.includedAngle;  // a chamfer mill
    return j;
}
json codes(const std::vector<StepCode>& v) {
    json a = json::array();
    for (StepCode c : v) a.push_back(toString(c));
    return a;
}

json templateJson(const ProcessTemplate& t) {
    json steps = json::array();
    for (const TemplateStep& s : t.steps)
        steps.push_back({{"code", toString(s.code)},
                         {"existence", toString(s.existence)},
                         {"features", s.features},
                         {"role", toString(s.role)},
                         {"radialAllowance", s.radialAllowance},
                         {"axialAllowance", s.axialAllowance},
                         {"description", s.description}});
    json rules = json::array();
    for (const SequencingRule& r : t.rules)
        rules.push_back({{"priority", r.priority}, {"rule", toString(r.kind)}, {"parameters", r.parameters}});
    return {{"name", t.name},         {"family", t.family}, {"requiredSteps", codes(t.requiredSteps)},
            {"stepOrderName", t.stepOrderName}, {"stepOrder", codes(t.stepOrder)}, {"steps", steps},
            {"rules", rules}};
}

json unitJson(const MachiningUnit& u) {
    json islands = json::array();
    for (const Loop& l : u.islands) islands.push_back(loop(l));
    json open = json::array();
    for (const auto& e : u.openEdges) open.push_back(json::array({pt(e[0]), pt(e[1])}));
    json holes = json::array();
    for (const HoleTarget& h : u.holes) {
        json one{{"u", h.u}, {"v", h.v}, {"diameter", h.diameter}, {"top", h.top}, {"bottom", h.bottom},
                 {"through", h.through}};
        if (h.floorFilletRadius > 0) one["floorFilletRadius"] = h.floorFilletRadius;
        holes.push_back(std::move(one));
    }
    json tops = json::array();
    for (double t : u.islandTops) tops.push_back(num(t));
    json j = {{"id", u.id},
            {"setup", u.setup},
            {"element", u.element},
            {"step", toString(u.step)},
            {"operation", toString(u.operation)},
            {"featureType", u.featureType},
            {"tool", u.tool},
            {"toolNumber", u.toolNumber},
            {"cutter", cutter(u.cutter)},
            {"previousCutter", u.previousCutter ? cutter(*u.previousCutter) : json(nullptr)},
            {"previousAllowance", u.previousAllowance ? json(*u.previousAllowance) : json(nullptr)},
            {"setting",
             {{"spindleRpm", num(u.setting.spindleRpm)},
              {"feedMmMin", num(u.setting.feedMmMin)},
              {"plungeFeedMmMin", num(u.setting.plungeFeedMmMin)}}},
            {"top", u.top},
            {"stockTop", u.stockTop ? json(*u.stockTop) : json(nullptr)},
            {"bottom", u.bottom},
            {"contour", loop(u.contour)},
            {"islands", islands},
            {"openEdges", open},
            {"holes", holes},
            {"radialAllowance", u.radialAllowance},
            {"axialAllowance", u.axialAllowance},
            {"floorFilletRadius", u.floorFilletRadius},
            {"stepDown", num(u.stepDown)},
            {"stepOver", num(u.stepOver)},
            {"at", pt(u.at)},
            {"eta", u.eta ? num(*u.eta) : json(nullptr)},
            {"note", u.note},
            {"enabled", u.enabled},
            {"order", u.order}};
    if (!u.islandTops.empty()) j["islandTops"] = tops;
    if (u.faceIslandTops) j["faceIslandTops"] = true;
    if (u.operation == Operation::Chamfer) j["edgeOffset"] = u.edgeOffset;
    if (u.shortOfFloor) j["shortOfFloor"] = true;
    return j;
}

// A JSON value with the path that names it in messages.
class In {
public:
    In(const json& j, std::string path) : j_(j), path_(std::move(path)) {}
    [[noreturn]] void bad(const std::string& what) const {
        throw inputError("chain JSON " + (path_.empty() ? std::string("(root)") : path_) + ": " + what);
    }
    bool has(const char* key) const { return j_.is_object() && j_.contains(key) && !j_.at(key).is_null(); }
    In operator[](const char* key) const {
        if (!j_.is_object()) bad("is not an object");
        const auto it = j_.find(key);
        if (it == j_.end()) bad(std::string("missing field '") + key + "'");
        return {*it, path_.empty() ? key : path_ + "." + key};
    }
    In operator[](std::size_t i) const {
        if (!j_.is_array() || i >= j_.size()) bad("has no item " + std::to_string(i));
        return {j_[i], path_ + "[" + std::to_string(i) + "]"};
    }
    std::size_t size() const {
        if (!j_.is_array()) bad("is not an array");
        return j_.size();
    }
    double number() const {
        if (!j_.is_number()) bad("is not a number");
        return j_.get<double>();
    }
    // A number, or null for "none" (written for infinities).
    double numberOr(double none) const { return j_.is_null() ? none : number(); }
    int integer() const {
        if (!j_.is_number_integer()) bad("is not a whole number");
        return j_.get<int>();
    }
    std::string text() const {
        if (!j_.is_string()) bad("is not text");
        return j_.get<std::string>();
    }
    bool boolean() const {
        if (!j_.is_boolean()) bad("is not true or false");
        return j_.get<bool>();
    }
    const std::string& path() const { return path_; }
    const json& raw() const { return j_; }

private:
    const json& j_;
    std::string path_;
};

Point2 point(const In& in) {
    if (in.size() != 2) in.bad("is not a point [u, v]");
    return {in[std::size_t{0}].number(), in[std::size_t{1}].number()};
}
Vec3 vector3(const In& in) {
    if (in.size() != 3) in.bad("is not a vector [x, y, z]");
    return {in[std::size_t{0}].number(), in[std::size_t{1}].number(), in[std::size_t{2}].number()};
}
Loop readLoop(const In& in) {
    Loop l;
    for (std::size_t i = 0; i < in.size(); ++i) l.push_back(point(in[i]));
    return l;
}
Cutter readCutter(const In& in) {
    Cutter c{in["diameter"].number(), in["cornerRadius"].number(), in["type"].text()};
    if (in.has("includedAngle")) c.includedAngle = in["includedAngle"].number(), c.tipDiameter = in["tipDiameter"].number();
    return c;
}
std::vector<StepCode> readCodes(const In& in) {
    std::vector<StepCode> out;
    for (std::size_t i = 0; i < in.size(); ++i) out.push_back(parseStepCode(in[i].text(), "chain JSON " + in[i].path()));
    return out;
}

ProcessTemplate readTemplate(const In& in) {
    ProcessTemplate t;
    t.name = in["name"].text();
    t.family = in["family"].text();
    t.requiredSteps = readCodes(in["requiredSteps"]);
    t.stepOrderName = in["stepOrderName"].text();
    t.stepOrder = readCodes(in["stepOrder"]);
    const In steps = in["steps"];
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const In s = steps[i];
        const std::string where = "chain JSON " + s.path();
        TemplateStep ts;
        ts.code = parseStepCode(s["code"].text(), where);
        ts.existence = parseExistence(s["existence"].text(), where);
        const In f = s["features"];
        for (std::size_t k = 0; k < f.size(); ++k) ts.features.push_back(f[k].text());
        ts.role = parseToolRole(s["role"].text(), where);
        ts.radialAllowance = s["radialAllowance"].number();
        ts.axialAllowance = s["axialAllowance"].number();
        ts.description = s["description"].text();
        t.steps.push_back(ts);
    }
    const In rules = in["rules"];
    for (std::size_t i = 0; i < rules.size(); ++i) {
        const In r = rules[i];
        t.rules.push_back(parseRule(r["priority"].integer(), r["rule"].text(), r["parameters"].text(),
                                    "chain JSON " + r.path()));
    }
    validateTemplate(t);
    return t;
}

MachiningUnit readUnit(const In& in) {
    const std::string where = "chain JSON " + in.path();
    MachiningUnit u;
    u.id = in["id"].integer();
    u.setup = in["setup"].integer();
    u.element = in["element"].integer();
    u.step = parseStepCode(in["step"].text(), where);
    u.operation = parseOperation(in["operation"].text(), where);
    u.featureType = in["featureType"].text();
    u.tool = in["tool"].text();
    u.toolNumber = in["toolNumber"].integer();
    u.cutter = readCutter(in["cutter"]);
    if (in.has("previousCutter")) u.previousCutter = readCutter(in["previousCutter"]);
    if (in.has("previousAllowance")) u.previousAllowance = in["previousAllowance"].number();
    const In s = in["setting"];
    u.setting = {s["spindleRpm"].numberOr(NAN), s["feedMmMin"].numberOr(NAN), s["plungeFeedMmMin"].numberOr(NAN)};
    u.top = in["top"].number();
    u.bottom = in["bottom"].number();
    if (in.has("stockTop")) u.stockTop = in["stockTop"].number();
    u.contour = readLoop(in["contour"]);
    const In islands = in["islands"];
    for (std::size_t i = 0; i < islands.size(); ++i) u.islands.push_back(readLoop(islands[i]));
    if (in.has("islandTops")) {  // added later: older chains have none
        const In tops = in["islandTops"];
        if (tops.size() != u.islands.size()) tops.bad("needs one height (or null) per island");
        for (std::size_t i = 0; i < tops.size(); ++i) u.islandTops.push_back(tops[i].numberOr(NAN));
    }
    if (in.has("faceIslandTops")) u.faceIslandTops = in["faceIslandTops"].boolean();
    const In open = in["openEdges"];
    for (std::size_t i = 0; i < open.size(); ++i) {
        if (open[i].size() != 2) open[i].bad("is not an edge [[u, v], [u, v]]");
        u.openEdges.push_back({point(open[i][std::size_t{0}]), point(open[i][std::size_t{1}])});
    }
    const In holes = in["holes"];
    for (std::size_t i = 0; i < holes.size(); ++i) {
        const In h = holes[i];
        u.holes.push_back({h["u"].number(), h["v"].number(), h["diameter"].number(), h["top"].number(),
                           h["bottom"].number(), h["through"].boolean(),
                           h.has("floorFilletRadius") ? h["floorFilletRadius"].number() : 0.0});  // older chains: none
    }
    u.radialAllowance = in["radialAllowance"].number();
    u.axialAllowance = in["axialAllowance"].number();
    if (in.has("floorFilletRadius")) u.floorFilletRadius = in["floorFilletRadius"].number();  // older chains: none
    if (in.has("edgeOffset")) u.edgeOffset = in["edgeOffset"].number();
    u.stepDown = in["stepDown"].numberOr(NAN);
    u.stepOver = in["stepOver"].numberOr(NAN);
    u.at = point(in["at"]);
    if (in.has("eta")) u.eta = in["eta"].number();
    u.note = in["note"].text();
    if (in.has("shortOfFloor")) u.shortOfFloor = in["shortOfFloor"].boolean();
    u.enabled = in["enabled"].boolean();
    u.order = in["order"].integer();
    return u;
}

}  // namespace

std::string toJson(const MachiningChain& c, int indent) {
    json j;
    j["family"] = c.family;
    j["material"] = c.material;
    j["machine"] = c.machine;
    j["template"] = templateJson(c.processTemplate);
    j["setups"] = json::array();
    for (const ChainSetup& s : c.setups) {
        json processes = json::array();
        for (const ChainProcess& p : s.processes) {
            json steps = json::array();
            for (const ChainStep& st : p.steps) {
                json programs = json::array();
                for (const ChainProgram& pr : st.programs) programs.push_back({{"tool", pr.tool}, {"units", pr.units}});
                steps.push_back({{"code", toString(st.code)}, {"programs", programs}});
            }
            processes.push_back({{"id", p.id}, {"machine", p.machine}, {"tool", p.tool}, {"steps", steps}});
        }
        j["setups"].push_back({{"id", s.id},
                               {"name", s.name},
                               {"direction", vec(s.direction)},
                               {"frame", {{"u", vec(s.u)}, {"v", vec(s.v)}, {"w", vec(s.w)}}},
                               {"processes", processes}});
        if (s.blankTop) j["setups"].back()["blankTop"] = *s.blankTop;
    }
    j["elements"] = json::array();
    for (const ChainElement& e : c.elements)
        j["elements"].push_back({{"id", e.id},
                                 {"setup", e.setup},
                                 {"parent", e.parent},
                                 {"featureType", e.featureType},
                                 {"level", e.level},
                                 {"top", e.top},
                                 {"depth", e.depth},
                                 {"minWidth", e.minWidth},
                                 {"minCornerRadius", e.minCornerRadius < 0 ? json(nullptr) : num(e.minCornerRadius)},
                                 {"floorFilletRadius", e.floorFilletRadius},
                                 {"narrowPassages", e.narrowPassages},
                                 {"holeDiameter", e.holeDiameter ? num(*e.holeDiameter) : json(nullptr)}});
    j["units"] = json::array();
    for (const MachiningUnit& u : c.units) j["units"].push_back(unitJson(u));
    j["order"] = c.order;
    j["travel"] = {{"rulesOnly", c.travel.rulesOnly},
                   {"optimised", c.travel.optimised},
                   {"savedPercent", c.travel.savedPercent}};
    j["checks"] = json::array();
    for (const RuleCheck& r : c.checks)
        j["checks"].push_back({{"rule", r.rule}, {"node", r.node}, {"ok", r.ok}, {"message", r.message}});
    j["unmachined"] = json::array();
    for (const Unmachined& m : c.unmachined)
        j["unmachined"].push_back({{"element", m.element},
                                   {"step", m.step ? json(toString(*m.step)) : json(nullptr)},
                                   {"reason", m.reason},
                                   {"faces", m.faces}});
    j["remainders"] = json::array();
    for (const Remainder& r : c.remainders)
        j["remainders"].push_back({{"element", r.element}, {"step", toString(r.step)}, {"kind", r.kind},
                                   {"tool", r.tool}, {"toolRadius", num(r.toolRadius)}, {"area", num(r.area)},
                                   {"depth", num(r.depth)}, {"needs", r.needs}});
    j["tools"] = json::object();
    for (const ChainTool& t : c.tools) {
        json settings = json::object();
        for (const auto& [op, d] : t.settings)
            settings[op] = {{"spindleRpm", num(d.spindleRpm)}, {"feedMmMin", num(d.feedMmMin)},
                            {"plungeFeedMmMin", num(d.plungeFeedMmMin)}, {"ap", num(d.ap)}, {"ae", num(d.ae)}};
        j["tools"][t.id] = {{"number", t.number},         {"type", t.type},         {"material", t.material},
                            {"diameter", t.diameter},     {"cornerRadius", t.cornerRadius},
                            {"fluteLength", t.fluteLength}, {"reach", t.reach}, {"flutes", t.flutes},
                            {"neckDiameter", t.neckDiameter}, {"settings", settings}};
        if (t.includedAngle > 0)
            j["tools"][t.id]["tipDiameter"] = t.tipDiameter, j["tools"][t.id]["includedAngle"] = t.includedAngle;
    }
    return j.dump(indent);
}

MachiningChain fromJson(const std::string& text) {
    json j;
    try {
        j = json::parse(text);
    } catch (const json::exception& e) {
        throw inputError(std::string("chain JSON: not valid JSON (") + e.what() + ")");
    }
    const In root(j, "");
    MachiningChain c;
    c.family = root["family"].text();
    c.material = root["material"].text();
    c.machine = root["machine"].text();
    c.processTemplate = readTemplate(root["template"]);

    const In setups = root["setups"];
    for (std::size_t i = 0; i < setups.size(); ++i) {
        const In s = setups[i];
        ChainSetup cs;
        cs.id = s["id"].integer();
        cs.name = s["name"].text();
        cs.direction = vector3(s["direction"]);
        cs.u = vector3(s["frame"]["u"]);
        cs.v = vector3(s["frame"]["v"]);
        cs.w = vector3(s["frame"]["w"]);
        if (s.has("blankTop")) cs.blankTop = s["blankTop"].number();  // added later
        const In processes = s["processes"];
        for (std::size_t k = 0; k < processes.size(); ++k) {
            const In p = processes[k];
            ChainProcess cp;
            cp.id = p["id"].integer();
            cp.machine = p["machine"].text();
            cp.tool = p["tool"].text();
            const In steps = p["steps"];
            for (std::size_t m = 0; m < steps.size(); ++m) {
                ChainStep st;
                st.code = parseStepCode(steps[m]["code"].text(), "chain JSON " + steps[m].path());
                const In programs = steps[m]["programs"];
                for (std::size_t q = 0; q < programs.size(); ++q) {
                    ChainProgram pr;
                    pr.tool = programs[q]["tool"].text();
                    const In units = programs[q]["units"];
                    for (std::size_t r = 0; r < units.size(); ++r) pr.units.push_back(units[r].integer());
                    st.programs.push_back(pr);
                }
                cp.steps.push_back(st);
            }
            cs.processes.push_back(cp);
        }
        c.setups.push_back(cs);
    }

    const In elements = root["elements"];
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const In e = elements[i];
        ChainElement ce;
        ce.id = e["id"].integer();
        ce.setup = e["setup"].integer();
        ce.parent = e["parent"].integer();
        ce.featureType = e["featureType"].text();
        ce.level = e["level"].number();
        ce.top = e["top"].number();
        ce.depth = e["depth"].number();
        ce.minWidth = e["minWidth"].number();
        ce.minCornerRadius = e["minCornerRadius"].numberOr(-1);
        ce.floorFilletRadius = e["floorFilletRadius"].number();
        ce.narrowPassages = e["narrowPassages"].integer();
        if (e.has("holeDiameter")) ce.holeDiameter = e["holeDiameter"].number();
        c.elements.push_back(ce);
    }

    const In units = root["units"];
    for (std::size_t i = 0; i < units.size(); ++i) {
        c.units.push_back(readUnit(units[i]));
        if (c.units.back().id != static_cast<int>(i))
            units[i]["id"].bad("is " + std::to_string(c.units.back().id) + "; units are numbered from 0 in order");
        if (!c.setup(c.units.back().setup)) units[i]["setup"].bad("names no setup of the chain");
    }
    const In order = root["order"];
    for (std::size_t i = 0; i < order.size(); ++i) c.order.push_back(order[i].integer());

    const In travel = root["travel"];
    c.travel = {travel["rulesOnly"].number(), travel["optimised"].number(), travel["savedPercent"].number()};
    const In checks = root["checks"];
    for (std::size_t i = 0; i < checks.size(); ++i)
        c.checks.push_back({checks[i]["rule"].text(), checks[i]["node"].text(), checks[i]["ok"].boolean(),
                            checks[i]["message"].text()});
    const In unmachined = root["unmachined"];
    for (std::size_t i = 0; i < unmachined.size(); ++i) {
        const In m = unmachined[i];
        Unmachined u;
        u.element = m["element"].integer();
        if (m.has("step")) u.step = parseStepCode(m["step"].text(), "chain JSON " + m.path());
        u.reason = m["reason"].text();
        if (m.has("faces")) {
            const In faces = m["faces"];
            for (std::size_t k = 0; k < faces.size(); ++k) u.faces.push_back(faces[k].integer());
        }
        c.unmachined.push_back(u);
    }
    if (root.has("remainders")) {  // absent in older chains
        const In remainders = root["remainders"];
        for (std::size_t i = 0; i < remainders.size(); ++i) {
            const In m = remainders[i];
            Remainder r;
            r.element = m["element"].integer();
            r.step = parseStepCode(m["step"].text(), "chain JSON " + m.path());
            r.kind = m["kind"].text();
            if (r.kind != "corners" && r.kind != "floor_fillet" && r.kind != "depth")
                m["kind"].bad("is none of corners, floor_fillet, depth");
            r.tool = m["tool"].text();
            r.toolRadius = m["toolRadius"].number();
            r.area = m["area"].number();
            r.depth = m["depth"].number();
            r.needs = m["needs"].text();
            c.remainders.push_back(r);
        }
    }
    const In tools = root["tools"];
    if (!tools.raw().is_object()) tools.bad("is not an object keyed by tool id");
    for (const auto& [id, value] : tools.raw().items()) {
        const In t(value, tools.path() + "." + id);
        ChainTool ct;
        ct.id = id;
        ct.number = t["number"].integer();
        ct.type = t["type"].text();
        ct.material = t["material"].text();
        ct.diameter = t["diameter"].number();
        ct.cornerRadius = t["cornerRadius"].number();
        ct.fluteLength = t["fluteLength"].number();
        ct.reach = t["reach"].number();
        if (t.has("neckDiameter")) ct.neckDiameter = t["neckDiameter"].number();  // absent in older chains
        if (t.has("includedAngle")) ct.includedAngle = t["includedAngle"].number(), ct.tipDiameter = t["tipDiameter"].number();
        ct.flutes = t["flutes"].integer();
        const In settings = t["settings"];
        if (!settings.raw().is_object()) settings.bad("is not an object keyed by operation");
        for (const auto& [op, v] : settings.raw().items()) {
            const In d(v, settings.path() + "." + op);
            ct.settings[op] = {d["spindleRpm"].numberOr(NAN), d["feedMmMin"].numberOr(NAN),
                               d["plungeFeedMmMin"].numberOr(NAN), d["ap"].numberOr(NAN), d["ae"].numberOr(NAN)};
        }
        c.tools.push_back(ct);
    }
    return c;
}

}  // namespace aeronc::chain
