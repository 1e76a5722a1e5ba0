// One impeller program from its route: cutters, toolpaths, cutting data (see the header).
#include <aeronc/kb/ImpellerProgram.h>

#include <aeronc/core/Error.h>
#include <aeronc/core/SpindleSpeed.h>
#include <aeronc/impeller/Blank.h>
#include <aeronc/kb/OptimiseParameters.h>
#include <aeronc/optimise/ProblemJson.h>
#include <aeronc/optimise/Report.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <tuple>

namespace aeronc::kb {

using impeller::CuttingTool;
using impeller::RouteStep;
using impellerpath::CutterShape;

namespace {

constexpr const char* kFiveAxisSteps[] = {"rough_channels", "finish_blades", "finish_hub", "finish_fillets"};
// The optimiser's settings for these tools, as the Optimise cutting command's.
constexpr double kRoughingRaMaxUm = 12.5;
constexpr double kChipLoadFactor = 1.5;  // chip load at most this times the knowledge base's f_z

bool fiveAxis(const std::string& operation) {
    return std::find(std::begin(kFiveAxisSteps), std::end(kFiveAxisSteps), operation) != std::end(kFiveAxisSteps);
}

// The last step of the operation (a route has one of each), or none.
const RouteStep* stepOf(const std::vector<RouteStep>& steps, const std::string& operation) {
    const RouteStep* found = nullptr;
    for (const RouteStep& s : steps)
        if (s.operation == operation) found = &s;
    return found;
}

// A ball or tapered ball of the route; its speeds come later, from its cutting data.
CutterShape ballCutter(const RouteStep& s, int number, const std::string& role) {
    const CuttingTool& t = *s.tool;
    if (t.type != "ball" && t.type != "tapered_ball")
        throw inputError("impeller toolpaths: " + role + ": tool " + t.id + " is a " + t.type +
                         " tool; the channels need a ball or tapered ball");
    CutterShape c;
    c.id = t.id;
    c.number = number;
    c.tipRadius = t.diameter / 2, c.taperDeg = t.taperDeg, c.fluteLength = t.fluteLength, c.reach = t.reach;
    c.shankRadius = t.shankDiameter / 2;
    c.rpm = 1, c.feed = 1;
    return c;
}

CutterShape flatCutterOf(const RouteStep& s, int number, const std::string& role) {
    const CuttingTool& t = *s.tool;
    if (t.type == "ball" || t.type == "tapered_ball")
        throw inputError("impeller toolpaths: axial: " + role + ": tool " + t.id + " is a " + t.type +
                         " tool; this step needs a flat-bottomed tool");
    return impellerpath::flatCutter(t.id, number, t.diameter, t.fluteLength, t.reach, 1, 1);
}

// The length of the segment from p to q rounded once: the square root of the exact sum of the
// squared differences, corrected by one Newton step in double-double arithmetic. A plain
// sqrt(dx² + dy² + dz²) rounds three more times; the cut lengths would then differ in the last
// bits from those a script sums over the same moves (Python's math.dist rounds once).
double segmentLength(const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
    double hi = 0, lo = 0;
    for (int k = 0; k < 3; ++k) {
        const double d = p[k] - q[k];
        const double square = d * d, squareError = std::fma(d, d, -square);
        const double sum = hi + square, back = sum - hi;
        lo += ((hi - (sum - back)) + (square - back)) + squareError;
        hi = sum;
    }
    const double r = std::sqrt(hi + lo);
    if (!(r > 0)) return r;
    const double rr = r * r, rrError = std::fma(r, r, -rr);
    return r + (((hi - rr) - rrError) + lo) / (2 * r);
}

// Length of the cutting moves of an operation, measured at the tool tip.
double cutLength(const impellerpath::Operation& op) {
    double length = 0;
    Eigen::Vector3d previous;
    bool first = true;
    for (const auto& m : op.moves) {
        const Eigen::Vector3d tip = m.centre - op.cutter.tipRadius * m.axis;
        if (!first && !m.rapid) length += segmentLength(previous, tip);
        previous = tip, first = false;
    }
    return length;
}

std::string toolMaterial(const CuttingTool& t) { return t.material.empty() ? "carbide" : t.material; }

// Speeds of a facing, drilling or boring tool: the knowledge base's cutting condition, capped
// at the machine's spindle speed and feed.
ToolCutting conditionCutting(const KnowledgeBase& kb, const std::string& material, const Machine& machine,
                             const RouteStep& step, double length) {
    const CuttingTool& t = *step.tool;
    ToolCutting c;
    c.tool = t.id;
    c.operation = step.operation == "face" ? "roughing" : step.operation == "drill" ? "drilling" : "finishing";
    const CuttingCondition cc = kb.cuttingCondition(material, toolMaterial(t), c.operation, t.diameter);
    const double ratio = kb.threshold("plunge_feed_ratio");
    c.rpm = std::min(spindleSpeed(cc.vc, t.diameter), machine.maxSpindleRpm);
    const int teeth = std::max(t.flutes, 1);
    c.feed = std::min(cc.fz * teeth * c.rpm, machine.maxFeedMmMin);
    c.plungeFeed = c.feed * ratio;
    c.fz = c.feed / (teeth * c.rpm);
    c.ap = 0, c.ae = t.diameter, c.length = length;
    c.active = {"knowledge base"};
    c.kbFz = cc.fz, c.kbVc = cc.vc;
    c.steps = {step.position};
    return c;
}

// Speeds of a 5-axis tool from the cutting-parameter optimiser (the same model and limits as
// Optimise cutting) for its deepest and widest engagement over the steps it cuts.
ToolCutting optimisedCutting(const KnowledgeBase& kb, const std::string& material, const std::string& machine,
                             const RouteStep& step, const CuttingTool& t, double ap, double ae, double length) {
    ToolCutting c;
    c.tool = t.id;
    c.operation = step.operation == "rough_channels" ? "roughing" : "finishing";
    const double d = t.diameter;
    if (t.flutes < 1) throw inputError("tool " + t.id + ": no number of flutes in the knowledge base");
    const CuttingCondition cc = kb.cuttingCondition(material, toolMaterial(t), c.operation, d);
    nlohmann::json params = {
        {"name", step.operation + " " + t.id},
        {"kb", {{"workpiece_material", material}, {"tool_material", toolMaterial(t)}, {"operation", c.operation},
                {"machine", machine}}},
        {"cutter", {{"diameter_mm", d}, {"teeth", t.flutes}, {"corner_radius_mm", d / 2},
                    {"max_chip_load_mm", kChipLoadFactor * cc.fz},
                    {"source", "knowledge base tool " + t.id + " (ball radius; chip load 1.5 x the knowledge base's f_z)"}}},
        {"cut", {{"length_mm", std::max(length, 1.0)}, {"a_p_mm", ap}, {"a_e_mm", std::min(ae, d)},
                 {"source", "impeller toolpaths of step " + std::to_string(step.position)}}},
        {"economics", {{"t_0_min", 1.0}, {"c_0_per_min", 1.0}, {"c_t_per_tool_life", 40.0}, {"w_time", 0.5},
                       {"w_cost", 0.5}}}};
    if (c.operation == "roughing") params["quality"] = {{"ra_max_um", kRoughingRaMaxUm}};
    optimise::GeneticOptions ga;
    ga.seed = 1;
    const optimise::Comparison solved = optimise::compare(
        optimise::parseParameters(withKnowledgeBase(kb, params)), optimise::Method::Deterministic, ga);
    const optimise::Optimum& best = solved.deterministic->combined;
    c.rpm = best.at.n;
    c.feed = best.at.feedRate;
    c.plungeFeed = c.feed * kb.threshold("plunge_feed_ratio");
    c.fz = best.at.fz;
    c.ap = ap, c.ae = std::min(ae, d), c.length = length;
    c.active = best.activeConstraints();
    c.kbFz = cc.fz, c.kbVc = cc.vc;
    return c;
}

void setSpeeds(std::vector<impellerpath::Operation>& operations, const std::vector<ToolCutting>& cutting) {
    for (auto& op : operations)
        for (const ToolCutting& c : cutting)
            if (c.tool == op.cutter.id) op.cutter.rpm = c.rpm, op.cutter.feed = c.feed;
}

}  // namespace

std::map<int, int> impellerToolNumbers(const std::vector<RouteStep>& steps) {
    std::map<int, int> numbers;
    std::map<std::string, int> byTool;
    for (const RouteStep& s : steps) {
        if (!s.tool) continue;
        const auto it = byTool.emplace(s.tool->id, static_cast<int>(byTool.size()) + 1).first;
        numbers[s.position] = it->second;
    }
    return numbers;
}

namespace {

// The route's cutters (their speeds come from the cutting data), with what the checks refuse.
struct RouteTools {
    const RouteStep* rough = nullptr;
    const RouteStep* blades = nullptr;
    impellerpath::RouteCutters cutters;
    impellerpath::AxialCutters axial;
    impellerpath::AxialOptions axialOptions;
    impellerpath::PathOptions paths;
};

RouteTools routeTools(const std::vector<RouteStep>& steps, const std::map<int, int>& numbers,
                      const KnowledgeBase& kb, const ImpellerProgramOptions& o) {
    const auto materials = kb.workpieceMaterials();
    if (std::find(materials.begin(), materials.end(), o.material) == materials.end()) {
        std::string known;
        for (const auto& m : materials) known += (known.empty() ? "" : ", ") + m;
        throw inputError("unknown workpiece material '" + o.material + "'; the knowledge base has " + known);
    }
    kb.machine(o.machine);  // an unknown one names the known
    if (!(o.paths.stations >= 2 && o.paths.stations <= 200)) throw inputError("impeller program: stations wants 2 to 200");
    if (!(o.paths.channels >= 0)) throw inputError("impeller program: channels wants 0 (all) or more");
    RouteTools r;
    r.rough = stepOf(steps, "rough_channels");
    r.blades = stepOf(steps, "finish_blades");
    if (!r.rough || !r.blades || !r.rough->tool || !r.blades->tool)
        throw inputError("the impeller route has no channel roughing or no blade finishing step with a tool");
    const auto number = [&](const RouteStep& s) { return numbers.at(s.position); };
    r.cutters = {ballCutter(*r.rough, number(*r.rough), "rougher"), ballCutter(*r.blades, number(*r.blades), "finisher"),
                 std::nullopt};
    if (const RouteStep* fillets = stepOf(steps, "finish_fillets"); fillets && fillets->tool)
        r.cutters.filletBall = ballCutter(*fillets, number(*fillets), "filletBall");
    for (auto [operation, role, slot] : {std::tuple{"face", "faceMill", &r.axial.faceMill},
                                         {"drill", "drill", &r.axial.drill}, {"bore", "boringMill", &r.axial.boringMill}})
        if (const RouteStep* s = stepOf(steps, operation); s && s->tool) *slot = flatCutterOf(*s, number(*s), role);
    if (const RouteStep* drill = stepOf(steps, "drill")) r.axialOptions.drillAllowance = drill->allowance;
    if (!(r.axialOptions.drillAllowance >= 0))
        throw inputError("impeller toolpaths: axial: drillAllowance must be >= 0 (the drilling step's allowance)");
    if (!(r.rough->allowance >= 0)) throw inputError("impeller toolpaths: the channel roughing's allowance must be >= 0");
    r.paths = o.paths;
    r.paths.roughAllowance = r.rough->allowance;
    return r;
}

}  // namespace

void checkImpellerProgram(const std::vector<RouteStep>& steps, const KnowledgeBase& kb,
                          const ImpellerProgramOptions& options) {
    routeTools(steps, impellerToolNumbers(steps), kb, options);
}

ImpellerProgramming programImpeller(const TopoDS_Shape& part, const impeller::ImpellerFeatures& f,
                                    const impeller::ImpellerDimensions& d, const std::vector<RouteStep>& steps,
                                    const KnowledgeBase& kb, const ImpellerProgramOptions& o) {
    ImpellerProgramming out;
    out.toolNumbers = impellerToolNumbers(steps);
    const RouteTools tools = routeTools(steps, out.toolNumbers, kb, o);
    const Machine machine = kb.machine(o.machine);
    const RouteStep* rough = tools.rough;
    const RouteStep* blades = tools.blades;
    const impellerpath::PathOptions& paths = tools.paths;

    using Clock = std::chrono::steady_clock;
    const auto seconds = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    auto t0 = Clock::now();
    out.fiveAxis = impellerpath::impellerToolpaths(part, f, d, tools.cutters, paths);
    std::vector<std::pair<CutterShape, std::vector<impellerpath::Move>>> byOperation;
    for (const auto& op : out.fiveAxis.operations) byOperation.push_back({op.cutter, op.moves});
    out.rapids = impellerpath::checkRapids(impeller::outerProfile(part, f, paths.blankAllowance), f, byOperation,
                                           paths.rapidClearance - 1e-6);
    out.axial = impellerpath::axialToolpaths(part, f, d, tools.axial, tools.axialOptions);
    out.toolpathSeconds = seconds(t0);
    t0 = Clock::now();

    std::map<std::string, const impellerpath::Operation*> ops;
    for (const auto& op : out.fiveAxis.operations) ops[op.name] = &op;
    for (const auto& op : out.axial.operations) ops[op.name] = &op;
    auto add = [&](ToolCutting c, bool replace) {
        for (ToolCutting& have : out.cutting)
            if (have.tool == c.tool) {
                if (replace) have = std::move(c);
                return;
            }
        out.cutting.push_back(std::move(c));
    };
    // One ToolController per tool: one set of speeds serves every step it cuts, so the deepest
    // and the widest engagement of its steps meet the limits.
    struct Cut {
        const RouteStep* step;
        CuttingTool tool;
        double ap = 0, ae = 0, length = 0;
        std::vector<int> steps;
    };
    std::vector<Cut> cuts;
    for (const RouteStep& s : steps) {
        const auto op = ops.find(s.operation);
        if (op == ops.end()) continue;
        if ((s.operation == "face" || s.operation == "drill" || s.operation == "bore") && s.tool) {
            add(conditionCutting(kb, o.material, machine, s, cutLength(*op->second)), false);
            continue;
        }
        if (!fiveAxis(s.operation)) continue;
        // The core finishes the blades and the hub with one cutter: the blade finishing tool.
        const CuttingTool& tool = s.operation == "finish_hub" ? *blades->tool : *s.tool;
        double ap, ae;
        if (s.operation == "rough_channels") ap = paths.stepDown, ae = paths.stepOver * tool.diameter;
        else if (s.operation == "finish_blades") ap = d.bladeHeight, ae = rough->allowance;  // the flank's height
        else if (s.operation == "finish_fillets") ap = d.filletRadius, ae = rough->allowance;  // the fillet's arc
        else ap = rough->allowance, ae = paths.finishStep;  // the hub: the roughing's stock, between lanes
        auto cut = std::find_if(cuts.begin(), cuts.end(), [&](const Cut& c) { return c.tool.id == tool.id; });
        if (cut == cuts.end()) cut = cuts.insert(cuts.end(), Cut{&s, tool, 0, 0, 0, {}});
        cut->ap = std::max(cut->ap, ap), cut->ae = std::max(cut->ae, ae);
        cut->length += cutLength(*op->second);
        cut->steps.push_back(s.position);
    }
    for (const Cut& cut : cuts) {
        ToolCutting c = optimisedCutting(kb, o.material, o.machine, *cut.step, cut.tool, std::max(cut.ap, 0.05),
                                         std::max(cut.ae, 0.05), cut.length);
        c.steps = cut.steps;
        add(std::move(c), true);
    }
    setSpeeds(out.fiveAxis.operations, out.cutting);
    setSpeeds(out.axial.operations, out.cutting);
    out.cuttingSeconds = seconds(t0);
    return out;
}

}  // namespace aeronc::kb
