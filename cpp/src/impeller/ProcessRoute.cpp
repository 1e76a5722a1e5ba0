#include <aeronc/impeller/ProcessRoute.h>

#include <aeronc/core/Error.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace aeronc::impeller {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string mm(double v) {
    std::ostringstream s;
    s.precision(4);
    s << v << " mm";
    return s.str();
}

std::vector<int> allOf(const ImpellerFeatures& f, std::vector<int> Blade::*member) {
    std::vector<int> out;
    for (const auto& b : f.blades) out.insert(out.end(), (b.*member).begin(), (b.*member).end());
    return out;
}

// The first of `tools` (already in preference order) that `fits`, or an error naming the limits.
CuttingTool pick(std::vector<const CuttingTool*> tools, const std::function<bool(const CuttingTool&)>& fits,
                 const RouteRule& rule, const std::string& kind, const std::string& limits) {
    for (const auto* t : tools)
        if (fits(*t)) return *t;
    throw inputError("impeller route step " + std::to_string(rule.position) + " (" + rule.operation + "): no " + kind +
                     " in the knowledge base fits: " + limits + "; add one to the tool tables");
}

std::vector<const CuttingTool*> ofType(const std::vector<CuttingTool>& tools, const std::string& type) {
    std::vector<const CuttingTool*> out;
    for (const auto& t : tools)
        if (t.type == type) out.push_back(&t);
    // Largest first; for tapered balls the largest tip, then the largest taper (the stiffest).
    std::sort(out.begin(), out.end(), [](const CuttingTool* a, const CuttingTool* b) {
        if (a->diameter != b->diameter) return a->diameter > b->diameter;
        if (a->taperDeg != b->taperDeg) return a->taperDeg > b->taperDeg;
        return a->id < b->id;
    });
    return out;
}

}  // namespace

double CuttingTool::diameterAt(double h) const {
    return type == "tapered_ball" ? diameter + 2 * std::max(h, 0.0) * std::tan(taperDeg * kPi / 180) : diameter;
}

ProcessRoute planRoute(const ImpellerFeatures& f, const ImpellerDimensions& d, std::vector<RouteRule> rules,
                       const std::vector<CuttingTool>& tools) {
    std::sort(rules.begin(), rules.end(), [](const RouteRule& a, const RouteRule& b) { return a.position < b.position; });
    ProcessRoute route;
    const double height = std::max(d.bladeHeight, d.splitterHeight);
    for (const auto& rule : rules) {
        RouteStep s;
        s.position = rule.position;
        s.operation = rule.operation;
        s.strategy = rule.strategy;
        s.description = rule.description;
        s.toolRule = rule.toolRule;
        s.allowance = rule.allowance;
        s.clearance = rule.clearance;
        std::string missing;
        if (rule.operation == "face") s.faces = f.planes, missing = f.planes.empty() ? "no planes" : "";
        else if (rule.operation == "turn") s.faces = f.turned, missing = f.turned.empty() ? "no turned faces" : "";
        else if (rule.operation == "drill" || rule.operation == "bore") {
            if (f.bore) s.faces = {f.bore};
            else missing = "no bore";
        } else if (rule.operation == "rough_channels") {
            missing = f.blades.empty() ? "no blades" : "";
        } else if (rule.operation == "finish_blades") {
            s.faces = allOf(f, &Blade::walls);
        } else if (rule.operation == "finish_hub") {
            s.faces = f.hubFaces.empty() ? std::vector<int>{f.hub} : f.hubFaces;
        } else if (rule.operation == "finish_fillets") {
            s.faces = allOf(f, &Blade::fillets);
            if (s.faces.empty() || d.filletRadius <= 0) missing = "no root fillets";
        } else {
            throw inputError("impeller route step " + std::to_string(rule.position) + ": unknown operation '" +
                             rule.operation + "'");
        }
        if (!missing.empty()) {
            route.skipped.push_back(std::to_string(rule.position) + " " + rule.operation + ": " + missing);
            continue;
        }
        const double channel = d.minChannelWidth;
        const double reachNeeded = height + rule.clearance;
        if (rule.toolRule == "none") {
            s.toolReason = "no milling tool: a lathe step";
        } else if (rule.toolRule == "face_mill") {
            s.tool = pick(ofType(tools, "face"), [](const CuttingTool&) { return true; }, rule, "face mill", "any size");
            s.toolReason = "the largest face mill";
        } else if (rule.toolRule == "drill_in_bore" || rule.toolRule == "end_mill_in_bore") {
            // The bore is an axial step (not in the 5-axis program): a bore no tool of the crib
            // fits (a small deep bore wants a drill and a reamer) is listed, not a stop.
            const bool drill = rule.toolRule == "drill_in_bore";
            const double dMax = drill ? d.boreDiameter - 2 * rule.allowance : 0.8 * d.boreDiameter;
            const std::string limits = "diameter at most " + mm(dMax) + ", reach at least " + mm(d.boreDepth);
            try {
                s.tool = pick(ofType(tools, drill ? "drill" : "flat"), [&](const CuttingTool& t) {
                    return t.diameter <= dMax + 1e-9 && t.reach >= d.boreDepth; }, rule, drill ? "drill" : "flat end mill", limits);
            } catch (const Error& e) {
                if (e.kind() != Error::Kind::Input) throw;
                route.skipped.push_back(std::to_string(rule.position) + " " + rule.operation + ": " + e.what());
                continue;
            }
            s.toolReason = limits;
        } else if (rule.toolRule == "ball_in_channel") {
            // A ball is limited by the channel where the channel is at least its radius deep:
            // the gap at a nose where the blades stand a fraction of a millimetre tall is not.
            auto dMax = [&](double dia) { return d.channelWidth(dia / 2) - 2 * rule.allowance - rule.clearance; };
            const std::string limits = "diameter at most the channel's width where it is as deep as the ball's radius, "
                                       "less " + mm(2 * rule.allowance + rule.clearance) + " (narrowest " + mm(channel) +
                                       "), reach at least " + mm(reachNeeded);
            s.tool = pick(ofType(tools, "ball"), [&](const CuttingTool& t) {
                return t.diameter <= dMax(t.diameter) + 1e-9 && t.reach >= reachNeeded; }, rule, "ball end mill", limits);
            s.toolReason = "diameter at most " + mm(dMax(s.tool->diameter)) + " (channel " +
                           mm(d.channelWidth(s.tool->diameter / 2)) + " where it is " + mm(s.tool->diameter / 2) +
                           " deep), reach at least " + mm(reachNeeded);
        } else if (rule.toolRule == "tapered_ball_in_channel") {
            const double dMax = d.channelWidth(reachNeeded) - rule.clearance;
            const std::string limits = "tip radius at most the fillet's " + mm(d.filletRadius) + ", diameter at " +
                                       mm(reachNeeded) + " at most " + mm(dMax) + " (and at each height the channel's "
                                       "width where it is that deep less " + mm(rule.clearance) + "), reach at least " +
                                       mm(reachNeeded);
            // The cone widens upwards, the channel where it is deeper may widen too: every height counts.
            auto fitsChannel = [&](const CuttingTool& t) {
                for (double h = t.diameter / 2; h < reachNeeded; h += 1.0)
                    if (t.diameterAt(h) > d.channelWidth(h) - rule.clearance + 1e-9) return false;
                return t.diameterAt(reachNeeded) <= dMax + 1e-9;
            };
            s.tool = pick(ofType(tools, "tapered_ball"), [&](const CuttingTool& t) {
                return (d.filletRadius <= 0 || t.diameter / 2 <= d.filletRadius + 1e-9) && fitsChannel(t) &&
                       t.reach >= reachNeeded;
            }, rule, "tapered ball end mill", limits);
            s.toolReason = limits;
        } else if (rule.toolRule == "ball_in_fillet") {
            const std::string limits = "radius at most the fillet's " + mm(d.filletRadius) + ", reach at least " +
                                       mm(reachNeeded);
            s.tool = pick(ofType(tools, "ball"), [&](const CuttingTool& t) {
                return t.diameter / 2 <= d.filletRadius + 1e-9 && t.diameter <= d.channelWidth(t.diameter / 2) - rule.clearance &&
                       t.reach >= reachNeeded;
            }, rule, "ball end mill", limits);
            s.toolReason = limits;
        } else {
            throw inputError("impeller route step " + std::to_string(rule.position) + ": unknown tool rule '" +
                             rule.toolRule + "'");
        }
        route.steps.push_back(s);
    }
    return route;
}

std::string routeToJson(const ProcessRoute& r) {
    using nlohmann::json;
    json steps = json::array();
    for (const auto& s : r.steps) {
        json j = {{"position", s.position}, {"operation", s.operation},     {"strategy", s.strategy},
                  {"description", s.description}, {"toolRule", s.toolRule}, {"allowance", s.allowance},
                  {"clearance", s.clearance},      {"faces", s.faces},       {"toolReason", s.toolReason},
                  {"tool", nullptr}};
        if (s.tool)
            j["tool"] = {{"id", s.tool->id},           {"type", s.tool->type},   {"material", s.tool->material},
                         {"diameter", s.tool->diameter}, {"taperDeg", s.tool->taperDeg}, {"reach", s.tool->reach},
                         {"fluteLength", s.tool->fluteLength}, {"flutes", s.tool->flutes}};
        steps.push_back(j);
    }
    return json{{"steps", steps}, {"skipped", r.skipped}}.dump(1);
}

}  // namespace aeronc::impeller
