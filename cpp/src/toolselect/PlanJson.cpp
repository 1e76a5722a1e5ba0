// A tool plan as JSON text, both ways (see the header).
#include <aeronc/toolselect/PlanJson.h>

#include <aeronc/core/Error.h>
#include <aeronc/core/JsonNesting.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace aeronc::toolselect {

using nlohmann::json;

namespace {

// A JSON value with the path that names it in messages.
class In {
public:
    In(const json& j, std::string path) : j_(j), path_(std::move(path)) {}
    [[noreturn]] void bad(const std::string& what) const {
        throw inputError("tool plan JSON " + (path_.empty() ? std::string("(root)") : path_) + ": " + what);
    }
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
    bool isNull() const { return j_.is_null(); }
    bool has(const char* key) const { return j_.is_object() && j_.contains(key) && !j_.at(key).is_null(); }
    // A number; null (written for a value that is not finite) reads as NaN.
    double number() const {
        if (j_.is_null()) return std::numeric_limits<double>::quiet_NaN();
        if (!j_.is_number()) bad("is not a number");
        return j_.get<double>();
    }
    int integer() const {
        if (!j_.is_number_integer()) bad("is not a whole number");
        return j_.get<int>();
    }
    std::string text() const {
        if (!j_.is_string()) bad("is not text");
        return j_.get<std::string>();
    }
    std::string textOrEmpty() const { return j_.is_null() ? std::string() : text(); }
    const json& raw() const { return j_; }

private:
    const json& j_;
    std::string path_;
};

recognition::ElementType elementType(const In& in) {
    const std::string s = in.text();
    using recognition::ElementType;
    for (ElementType t : {ElementType::ClosedPocket, ElementType::OpenPocket, ElementType::Opening, ElementType::Hole})
        if (s == toString(t)) return t;
    in.bad("unknown element type '" + s + "'");
}

std::string fmt(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

}  // namespace

std::string toJson(const ToolPlan& plan, const std::string& material, int indent) {
    auto toolId = [&](int i) { return i < 0 ? json(nullptr) : json(plan.tools[static_cast<std::size_t>(i)].id); };
    auto num = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
    json j;
    j["material"] = material;
    j["elements"] = json::array();
    for (const ElementChoice& c : plan.elements) {
        const bool rough = c.roughingTool >= 0;
        j["elements"].push_back({{"id", c.element},
                                 {"type", recognition::toString(c.type)},
                                 {"finishingTool", toolId(c.finishingTool)},
                                 {"roughingTool", toolId(c.roughingTool)},
                                 {"eta", rough ? num(c.ratio.eta) : json(nullptr)},
                                 {"area", rough ? num(c.ratio.area) : json(nullptr)},
                                 {"narrowPassages", rough ? json(c.ratio.narrowPassages) : json(nullptr)},
                                 {"error", c.error.empty() ? json(nullptr) : json(c.error)}});
        if (c.partialRoughingTool >= 0) {
            j["elements"].back()["partialRoughingTool"] = toolId(c.partialRoughingTool);
            j["elements"].back()["partialDepth"] = num(c.partialDepth);
        }
    }
    j["holes"] = json::array();
    for (const HoleChoice& h : plan.holes)
        j["holes"].push_back({{"id", h.element},
                              {"diameter", num(h.diameter)},
                              {"drill", toolId(h.drill)},
                              {"error", h.error.empty() ? json(nullptr) : json(h.error)}});
    auto groups = [&](const std::vector<GroupElements>& gs) {
        json a = json::array();
        for (const GroupElements& g : gs) a.push_back({{"tool", toolId(g.tool)}, {"elements", g.elements}});
        return a;
    };
    j["groups"] = {{"before", groups(plan.groupsBefore)}, {"after", groups(plan.groupsAfter)}};
    j["toolChanges"] = {{"before", plan.merge.toolChangesBefore}, {"after", plan.merge.toolChangesAfter}};
    j["timeMin"] = {{"before", num(plan.merge.timeBefore)}, {"after", num(plan.merge.timeAfter)}};
    j["toolSettings"] = json::array();
    for (const ToolSetting& t : plan.settings)
        j["toolSettings"].push_back({{"tool", toolId(t.tool)},
                                     {"operation", t.operation},
                                     {"spindleRpm", num(t.spindleRpm)},
                                     {"feedMmMin", num(t.feedMmMin)},
                                     {"plungeFeedMmMin", num(t.plungeFeedMmMin)},
                                     {"vc", num(t.vc)},
                                     {"fz", num(t.fz)},
                                     {"ap", num(t.ap)},
                                     {"ae", num(t.ae)}});
    j["tools"] = json::object();
    std::set<int> listed;
    for (const ElementChoice& c : plan.elements) listed.insert(c.finishingTool), listed.insert(c.roughingTool);
    for (const HoleChoice& h : plan.holes) listed.insert(h.drill);
    for (const ToolSetting& t : plan.settings) listed.insert(t.tool);
    for (int i : listed) {
        if (i < 0) continue;
        const Tool& t = plan.tools[static_cast<std::size_t>(i)];
        j["tools"][t.id] = {{"type", t.type},         {"material", t.material},  {"diameter", t.diameter},
                            {"cornerRadius", t.cornerRadius}, {"fluteLength", t.fluteLength}, {"reach", t.reach},
                            {"flutes", t.flutes}, {"neckDiameter", t.neckDiameter}};
    }
    j["merges"] = json::array();
    for (const MergeReport::Step& s : plan.merge.merges)
        j["merges"].push_back({{"kept", toolId(static_cast<int>(s.keptTool))},
                               {"dropped", toolId(static_cast<int>(s.droppedTool))},
                               {"mu", num(s.mu)}});
    return j.dump(indent);
}

ToolPlan planFromJson(const std::string& text, const std::string& material, const std::vector<Tool>& tools) {
    checkJsonNesting(text, "tool plan JSON");
    json j;
    try {
        j = json::parse(text);
    } catch (const json::exception& e) {
        throw inputError(std::string("tool plan JSON: not valid JSON (") + e.what() + ")");
    }
    const In root(j, "");
    const std::string planned = root["material"].text();
    if (planned != material)
        throw inputError("the tool plan was made for '" + planned + "', not '" + material + "'; select tools again");

    std::map<std::string, int> index;
    for (std::size_t i = 0; i < tools.size(); ++i) index.emplace(tools[i].id, static_cast<int>(i));
    // The tools the plan names still have the dimensions it chose them by.
    const In listed = root["tools"];
    if (!listed.raw().is_object()) listed.bad("is not an object");
    for (const auto& [id, given] : listed.raw().items()) {
        const In t(given, "tools." + id);
        const auto it = index.find(id);
        if (it == index.end())
            throw inputError("the tool plan names tool " + id + ", which the knowledge base no longer has; select tools again");
        const Tool& have = tools[static_cast<std::size_t>(it->second)];
        const bool same = t["type"].text() == have.type && t["diameter"].number() == have.diameter &&
                          t["cornerRadius"].number() == have.cornerRadius &&
                          t["fluteLength"].number() == have.fluteLength && t["reach"].number() == have.reach &&
                          t["flutes"].integer() == have.flutes &&
                          (given.contains("neckDiameter") ? t["neckDiameter"].number() : 0.0) == have.neckDiameter;
        if (!same)
            throw inputError("tool " + id + " changed since the tool plan was made (now " + have.type + " D" +
                             fmt(have.diameter) + "); select tools again");
    }
    auto tool = [&](const In& in) -> int {
        if (in.isNull()) return -1;
        const std::string id = in.text();
        const auto it = index.find(id);
        if (it == index.end())
            throw inputError("the tool plan names tool " + id + ", which the knowledge base no longer has; select tools again");
        return it->second;
    };

    ToolPlan plan;
    plan.tools = tools;
    const In elements = root["elements"];
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const In e = elements[i];
        ElementChoice c;
        c.element = e["id"].integer();
        c.type = elementType(e["type"]);
        c.finishingTool = tool(e["finishingTool"]);
        c.roughingTool = tool(e["roughingTool"]);
        if (c.roughingTool >= 0) {
            c.ratio.eta = e["eta"].number();
            c.ratio.area = e["area"].number();
            c.ratio.machinableArea = c.ratio.eta * c.ratio.area;
            c.ratio.narrowPassages = e["narrowPassages"].integer();
        }
        c.error = e["error"].textOrEmpty();
        if (e.has("partialRoughingTool")) {  // plans since roughing as deep as the crib reaches
            c.partialRoughingTool = tool(e["partialRoughingTool"]);
            c.partialDepth = e["partialDepth"].number();
        }
        plan.elements.push_back(c);
    }
    const In holes = root["holes"];
    for (std::size_t i = 0; i < holes.size(); ++i) {
        const In h = holes[i];
        HoleChoice c;
        c.element = h["id"].integer();
        c.diameter = h["diameter"].number();
        c.drill = tool(h["drill"]);
        c.error = h["error"].textOrEmpty();
        plan.holes.push_back(c);
    }
    auto groups = [&](const In& in) {
        std::vector<GroupElements> out;
        for (std::size_t i = 0; i < in.size(); ++i) {
            GroupElements g;
            g.tool = tool(in[i]["tool"]);
            const In members = in[i]["elements"];
            for (std::size_t k = 0; k < members.size(); ++k) g.elements.push_back(members[k].integer());
            out.push_back(g);
        }
        return out;
    };
    plan.groupsBefore = groups(root["groups"]["before"]);
    plan.groupsAfter = groups(root["groups"]["after"]);
    plan.merge.toolChangesBefore = root["toolChanges"]["before"].integer();
    plan.merge.toolChangesAfter = root["toolChanges"]["after"].integer();
    plan.merge.timeBefore = root["timeMin"]["before"].number();
    plan.merge.timeAfter = root["timeMin"]["after"].number();
    const In merges = root["merges"];
    for (std::size_t i = 0; i < merges.size(); ++i) {
        const int kept = tool(merges[i]["kept"]), dropped = tool(merges[i]["dropped"]);
        if (kept < 0 || dropped < 0) merges[i].bad("names no tool");
        plan.merge.merges.push_back({static_cast<std::size_t>(kept), static_cast<std::size_t>(dropped),
                                     merges[i]["mu"].number()});
    }
    const In settings = root["toolSettings"];
    for (std::size_t i = 0; i < settings.size(); ++i) {
        const In s = settings[i];
        ToolSetting t;
        t.tool = tool(s["tool"]);
        t.operation = s["operation"].text();
        t.spindleRpm = s["spindleRpm"].number();
        t.feedMmMin = s["feedMmMin"].number();
        t.plungeFeedMmMin = s["plungeFeedMmMin"].number();
        t.vc = s["vc"].number();
        t.fz = s["fz"].number();
        t.ap = s["ap"].number();
        t.ae = s["ae"].number();
        plan.settings.push_back(t);
    }
    return plan;
}

}  // namespace aeronc::toolselect
