// The impeller's blank, and its process route from the knowledge base's rule library, on
// generated impellers.
#include <aeronc/core/Error.h>
#include <aeronc/impeller/Blank.h>
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/impeller/ProcessRoute.h>
#include <aeronc/kb/ImpellerProgram.h>
#include <aeronc/kb/ImpellerRoute.h>
#include <aeronc/kb/KnowledgeBase.h>
#include <aeronc/testparts/ImpellerGenerator.h>

#include <BRepAdaptor_Curve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <map>

#include "ErrorOf.h"

using namespace aeronc;
using namespace aeronc::impeller;

namespace {

constexpr double kPi = 3.14159265358979323846;

double volume(const TopoDS_Shape& s) {
    GProp_GProps g;
    BRepGProp::VolumeProperties(s, g);
    return g.Mass();
}

struct Recognised {
    testparts::Impeller part;
    ImpellerFeatures features;
    ImpellerDimensions dims;
};

Recognised recognised(const testparts::ImpellerSpec& spec) {
    Recognised r{testparts::makeImpeller(spec), {}, {}};
    r.features = recogniseImpeller(r.part.shape);
    r.dims = measureImpeller(r.part.shape, r.features);
    return r;
}

kb::KnowledgeBase defaultKb(const std::string& name) {
    const auto path = std::filesystem::temp_directory_path() / ("aeronc_impeller_" + name + ".sqlite");
    std::filesystem::remove(path);
    return kb::KnowledgeBase::openWithSqlFolder(path.string(), [] { return std::string(AERONC_RESOURCES) + "/kb"; });
}

}  // namespace

TEST(ImpellerBlank, HoldsThePartWithTheAllowance) {
    testparts::ImpellerSpec spec;
    spec.bladeCount = 5;
    const auto r = recognised(spec);
    const double allowance = 2;
    const auto profile = outerProfile(r.part.shape, r.features, allowance);
    const TopoDS_Shape blank = revolveProfile(profile, r.features);
    ASSERT_TRUE(BRepCheck_Analyzer(blank).IsValid());
    // The part lies inside the blank: every point of its edges, sampled densely, is within the
    // profile's radius at its station along the axis (the axis is Z through the origin).
    int checked = 0;
    for (TopExp_Explorer ex(r.part.shape, TopAbs_EDGE); ex.More(); ex.Next()) {
        BRepAdaptor_Curve c(TopoDS::Edge(ex.Current()));
        for (int i = 0; i <= 200; ++i) {
            const gp_Pnt q = c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * i / 200);
            const double z = q.Z() - r.features.axisPoint[2], rad = std::hypot(q.X(), q.Y());
            ASSERT_GT(z, profile.axial.front());
            ASSERT_LT(z, profile.axial.back());
            const size_t k = std::upper_bound(profile.axial.begin(), profile.axial.end(), z) - profile.axial.begin() - 1;
            EXPECT_LT(rad, profile.radius[k]) << "at z " << z << " r " << rad << " station " << k << " from " << profile.axial[k];
            ++checked;
        }
    }
    EXPECT_GT(checked, 10000);
    // The largest radius is the rim's plus the allowance (and the mesh's deflection); the length
    // the part's plus the allowance at both ends.
    const double rMax = *std::max_element(profile.radius.begin(), profile.radius.end());
    EXPECT_NEAR(rMax, spec.outerRadius + allowance + 0.02, 1e-6);
    EXPECT_NEAR(profile.axial.back() - profile.axial.front(), r.dims.axialLength + 2 * allowance, 1e-2);
    // It follows the outer profile: near the nose it is narrower than the rim, and the blank
    // is far less than the bounding cylinder.
    EXPECT_LT(profile.radius.back(), 0.8 * rMax);
    const double cylinder = kPi * rMax * rMax * (profile.axial.back() - profile.axial.front());
    EXPECT_LT(volume(blank), 0.85 * cylinder);
    EXPECT_GT(volume(blank), volume(r.part.shape));
    EXPECT_NE(test::inputErrorOf([&] { outerProfile(r.part.shape, r.features, -1); }).find("allowance"),
              std::string::npos);
}

// The default route on the 2 x 9 impeller: every step the part calls for, with the tool its
// rule asks for; each chosen tool meets the limits and the next larger one of its kind does not.
TEST(ImpellerRoute, DefaultRouteAndTools) {
    const auto r = recognised(testparts::ImpellerSpec{});
    const auto kb = defaultKb("route");
    const auto route = kb::planImpellerRoute(kb, r.features, r.dims);
    std::vector<std::string> ops;
    for (const auto& s : route.steps) ops.push_back(s.operation);
    EXPECT_EQ(ops, (std::vector<std::string>{"turn", "face", "drill", "bore", "rough_channels", "finish_blades",
                                             "finish_hub", "finish_fillets"}));
    const auto tools = kb::impellerTools(kb);
    const double h = r.dims.bladeHeight;
    std::map<std::string, const RouteStep*> by;
    for (const auto& s : route.steps) by[s.operation] = &s;
    auto largerOfType = [&](const CuttingTool& t) {
        std::vector<CuttingTool> out;
        for (const auto& o : tools)
            if (o.type == t.type && (o.diameter > t.diameter || (o.diameter == t.diameter && o.taperDeg > t.taperDeg)))
                out.push_back(o);
        return out;
    };
    {  // roughing: a ball that fits the channel with the allowances and clearance, and reaches
        const auto& s = *by["rough_channels"];
        ASSERT_TRUE(s.tool);
        EXPECT_EQ(s.tool->type, "ball");
        const double dMax = r.dims.minChannelWidth - 2 * s.allowance - s.clearance;
        EXPECT_LE(s.tool->diameter, dMax);
        EXPECT_GE(s.tool->reach, h + s.clearance);
        for (const auto& o : largerOfType(*s.tool)) EXPECT_TRUE(o.diameter > dMax || o.reach < h + s.clearance) << o.id;
    }
    for (const char* op : {"finish_blades", "finish_hub"}) {
        const auto& s = *by[op];
        ASSERT_TRUE(s.tool);
        EXPECT_EQ(s.tool->type, "tapered_ball");
        EXPECT_LE(s.tool->diameter / 2, r.dims.filletRadius);
        EXPECT_LE(s.tool->diameterAt(h + s.clearance), r.dims.minChannelWidth - s.clearance);
    }
    {
        const auto& s = *by["finish_fillets"];
        ASSERT_TRUE(s.tool);
        EXPECT_EQ(s.tool->type, "ball");
        EXPECT_LE(s.tool->diameter / 2, r.dims.filletRadius);
        EXPECT_EQ(s.faces.size(), 4 * r.features.blades.size());
    }
    EXPECT_EQ(by["finish_blades"]->faces.size(), 4 * r.features.blades.size());
    EXPECT_EQ(by["finish_hub"]->faces, std::vector<int>{r.features.hub});
    EXPECT_EQ(by["drill"]->tool->type, "drill");
    EXPECT_LE(by["drill"]->tool->diameter, r.dims.boreDiameter - 2 * by["drill"]->allowance);
    EXPECT_FALSE(by["turn"]->tool);
    const auto json = nlohmann::json::parse(routeToJson(route));
    EXPECT_EQ(json["steps"].size(), route.steps.size());
}

// A narrower channel and a smaller fillet pick smaller tools; without fillets and splitters the
// fillet step is skipped; a channel no tool fits is refused with the limits.
TEST(ImpellerRoute, FollowsTheDimensions) {
    const auto r = recognised(testparts::ImpellerSpec{});
    const auto kb = defaultKb("dims");
    const auto rules = kb::impellerRouteRules(kb);
    const auto tools = kb::impellerTools(kb);
    auto toolOf = [](const ProcessRoute& route, const std::string& op) {
        for (const auto& s : route.steps)
            if (s.operation == op) return *s.tool;
        ADD_FAILURE() << op;
        return CuttingTool{};
    };
    ImpellerDimensions narrow = r.dims;
    narrow.minChannelWidth = 5.5;
    narrow.filletRadius = 1.2;
    narrow.bladeHeight = narrow.splitterHeight = 8;  // the shipped 2 mm ball reaches 10 mm
    const auto wide = planRoute(r.features, r.dims, rules, tools);
    const auto tight = planRoute(r.features, narrow, rules, tools);
    EXPECT_LT(toolOf(tight, "rough_channels").diameter, toolOf(wide, "rough_channels").diameter);
    EXPECT_LE(toolOf(tight, "finish_fillets").diameter, 2.4);
    EXPECT_LT(toolOf(tight, "finish_fillets").diameter, toolOf(wide, "finish_fillets").diameter);
    EXPECT_LE(toolOf(tight, "finish_blades").diameterAt(narrow.bladeHeight + 0.5), 5.0);

    ImpellerDimensions none = r.dims;
    none.filletRadius = 0;
    const auto noFillet = planRoute(r.features, none, rules, tools);
    ASSERT_EQ(noFillet.skipped.size(), 1u);
    EXPECT_NE(noFillet.skipped[0].find("finish_fillets"), std::string::npos);

    ImpellerDimensions closed = r.dims;
    closed.minChannelWidth = 1.5;
    const std::string msg = test::inputErrorOf([&] { planRoute(r.features, closed, rules, tools); });
    EXPECT_NE(msg.find("rough_channels"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no ball end mill"), std::string::npos) << msg;
    auto bad = rules;
    bad[0].toolRule = "guess";
    EXPECT_NE(test::inputErrorOf([&] { planRoute(r.features, r.dims, bad, tools); }).find("unknown tool rule"),
              std::string::npos);
}

// The one impeller program (kb::programImpeller, what the command line, the Python module and
// Program impeller all use): tool numbers in route order, one per tool; the 5-axis tools cut at
// the cutting-parameter optimiser's speeds for their own toolpaths' engagement, the facing,
// drilling and boring tools at the knowledge base's; the operations carry those speeds.
TEST(ImpellerProgram, OneProgramWithTheOptimisersCuttingData) {
    testparts::ImpellerSpec spec;
    spec.bladeCount = 4;
    spec.splitters = false;
    const auto r = recognised(spec);
    const auto kb = defaultKb("program");
    const auto route = kb::planImpellerRoute(kb, r.features, r.dims);
    kb::ImpellerProgramOptions o;
    o.paths.stations = 3, o.paths.channels = 1;
    const auto prog = kb::programImpeller(r.part.shape, r.features, r.dims, route.steps, kb, o);

    // Numbers: one per distinct tool, in route order; the hub shares the blades' tool.
    std::map<std::string, int> numberOf;
    int last = 0;
    for (const auto& s : route.steps) {
        if (!s.tool) continue;
        const int n = prog.toolNumbers.at(s.position);
        if (numberOf.emplace(s.tool->id, n).second) EXPECT_EQ(n, ++last) << s.operation;
        EXPECT_EQ(n, numberOf.at(s.tool->id)) << s.operation;
    }
    EXPECT_GE(last, 5);

    const auto machine = kb.machine("AC-5AX");
    ASSERT_FALSE(prog.cutting.empty());
    std::map<std::string, const kb::ToolCutting*> cuttingOf;
    for (const auto& c : prog.cutting) cuttingOf[c.tool] = &c;
    for (const auto& s : route.steps) {
        if (!s.tool) continue;
        const auto* c = cuttingOf.count(s.tool->id) ? cuttingOf.at(s.tool->id) : nullptr;
        ASSERT_NE(c, nullptr) << s.operation << " " << s.tool->id;
        EXPECT_LE(c->rpm, machine.maxSpindleRpm * (1 + 1e-12)) << c->tool;
        EXPECT_LE(c->feed, machine.maxFeedMmMin * (1 + 1e-12)) << c->tool;
        EXPECT_GT(c->length, 0) << c->tool;
        if (s.operation == "face" || s.operation == "drill" || s.operation == "bore") {
            // The knowledge base's v_c and f_z: n = 1000 v_c / (pi D), v_f = f_z Z n, capped.
            EXPECT_EQ(c->active, std::vector<std::string>{"knowledge base"});
            EXPECT_DOUBLE_EQ(c->rpm, std::min(1000 * c->kbVc / (kPi * s.tool->diameter), machine.maxSpindleRpm));
            EXPECT_NEAR(c->feed, std::min(c->kbFz * s.tool->flutes * c->rpm, machine.maxFeedMmMin), 1e-9);
        } else {
            // The optimiser's optimum: within its chip load (1.5 x the knowledge base's f_z), with
            // the limits it met named, v_f = f_z Z n; not the knowledge base's raw speed.
            EXPECT_NE(c->active, std::vector<std::string>{"knowledge base"}) << c->tool;
            EXPECT_LE(c->fz, 1.5 * c->kbFz * (1 + 1e-9)) << c->tool;
            EXPECT_NEAR(c->feed, c->fz * s.tool->flutes * c->rpm, 1e-6 * c->feed) << c->tool;
            EXPECT_NE(c->rpm, std::min(1000 * c->kbVc / (kPi * s.tool->diameter), machine.maxSpindleRpm)) << c->tool;
        }
    }
    // Every operation's cutter carries its tool's number and speeds (the CL program's S and F).
    auto expectSpeeds = [&](const std::vector<impellerpath::Operation>& ops) {
        for (const auto& op : ops) {
            if (op.name == "turn") continue;  // the lathe's insert is the core's own
            ASSERT_TRUE(cuttingOf.count(op.cutter.id)) << op.name;
            EXPECT_EQ(op.cutter.rpm, cuttingOf.at(op.cutter.id)->rpm) << op.name;
            EXPECT_EQ(op.cutter.feed, cuttingOf.at(op.cutter.id)->feed) << op.name;
        }
    };
    ASSERT_EQ(prog.fiveAxis.operations.size(), 4u);  // roughing, blades, hub, fillets
    expectSpeeds(prog.fiveAxis.operations);
    expectSpeeds(prog.axial.operations);
    // The cut length is the tip's path over the cutting moves.
    const auto& rough = prog.fiveAxis.operations[0];
    long double length = 0;
    for (std::size_t i = 1; i < rough.moves.size(); ++i)
        if (!rough.moves[i].rapid)
            length += ((rough.moves[i].centre - rough.cutter.tipRadius * rough.moves[i].axis) -
                       (rough.moves[i - 1].centre - rough.cutter.tipRadius * rough.moves[i - 1].axis)).norm();
    EXPECT_NEAR(cuttingOf.at(rough.cutter.id)->length, static_cast<double>(length), 1e-9 * static_cast<double>(length));
    EXPECT_EQ(prog.rapids.linkCollisions, 0);
    EXPECT_GT(prog.rapids.links, 0);

    // A tool of the wrong kind is refused before any toolpath is made.
    auto steps = route.steps;
    for (auto& s : steps)
        if (s.operation == "rough_channels") s.tool = steps.front().tool ? steps.front().tool : steps[1].tool;
    EXPECT_NE(test::inputErrorOf([&] { kb::checkImpellerProgram(steps, kb, o); }).find("the channels need a ball"),
              std::string::npos);
    o.material = "unobtainium";
    EXPECT_NE(test::inputErrorOf([&] { kb::checkImpellerProgram(route.steps, kb, o); })
                  .find("unknown workpiece material 'unobtainium'"),
              std::string::npos);
}
