// aeronc._core: impeller recognition and dimension analysis, and the impeller test part. Shapes
// cross as BREP text, results as JSON text (docs/impeller.md); every C++ and OCCT exception
// becomes RecognitionError with the core's message; the work runs without the GIL, with OCCT's
// faults caught.
#include "Guarded.h"

#include <aeronc/brep/OcctFaults.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/impeller/Blank.h>
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/impeller/ProcessRoute.h>
#include <aeronc/kb/ImpellerRoute.h>
#include <aeronc/kb/KnowledgeBase.h>
#include <aeronc/core/Error.h>
#include <aeronc/impellerpath/AxialOperations.h>
#include <aeronc/impellerpath/ImpellerToolpaths.h>
#include <aeronc/post/Apt.h>
#include <aeronc/testparts/ImpellerGenerator.h>

#include <BRepTools.hxx>
#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include <optional>
#include <sstream>
#include <string>

namespace py = pybind11;
using namespace aeronc;

namespace {

nlohmann::json toolToJson(const impeller::CuttingTool& t) {
    return {{"id", t.id},         {"type", t.type},   {"material", t.material},         {"diameter", t.diameter},
            {"taperDeg", t.taperDeg}, {"reach", t.reach}, {"fluteLength", t.fluteLength}, {"shankDiameter", t.shankDiameter},
            {"flutes", t.flutes}};
}

double number(const nlohmann::json& j, const char* key, const std::string& where) {
    if (!j.contains(key) || !j[key].is_number()) throw inputError(where + ": \"" + key + "\" must be a number");
    return j[key].get<double>();
}

// The knowledge base's tool named by a request's cutter ({"tool": id, "number", "rpm", "feed"}).
const impeller::CuttingTool& requestedTool(const nlohmann::json& r, const std::string& where,
                                           const std::vector<impeller::CuttingTool>& tools) {
    if (!r.is_object()) throw inputError(where + " must be an object {tool, number, rpm, feed}");
    if (!r.contains("tool") || !r["tool"].is_string()) throw inputError(where + ": \"tool\" must be a tool id");
    const std::string id = r["tool"].get<std::string>();
    for (const auto& c : tools)
        if (c.id == id) return c;
    throw inputError(where + ": no tool " + id + " in the knowledge base");
}

// A ball or tapered ball cutter of the request with its shape from the knowledge base's tool.
impellerpath::CutterShape ballCutter(const nlohmann::json& r, const std::string& where,
                                     const std::vector<impeller::CuttingTool>& tools) {
    const auto& t = requestedTool(r, where, tools);
    if (t.type != "ball" && t.type != "tapered_ball")
        throw inputError(where + ": tool " + t.id + " is a " + t.type + " tool; the channels need a ball or tapered ball");
    impellerpath::CutterShape c;
    c.id = t.id;
    c.number = static_cast<int>(number(r, "number", where));
    c.tipRadius = t.diameter / 2, c.taperDeg = t.taperDeg, c.fluteLength = t.fluteLength, c.reach = t.reach;
    c.shankRadius = t.shankDiameter / 2;
    c.rpm = number(r, "rpm", where), c.feed = number(r, "feed", where);
    return c;
}

impellerpath::CutterShape cutterOf(const nlohmann::json& request, const char* role,
                                   const std::vector<impeller::CuttingTool>& tools) {
    if (!request.contains(role) || !request[role].is_object()) throw inputError(std::string("impeller toolpaths: no ") + role);
    return ballCutter(request[role], std::string("impeller toolpaths: ") + role, tools);
}

// A flat-bottomed cutter of the request (face mill, drill, flat end mill) for the axial steps.
impellerpath::CutterShape flatCutterOf(const nlohmann::json& r, const std::string& where,
                                       const std::vector<impeller::CuttingTool>& tools) {
    const auto& t = requestedTool(r, where, tools);
    if (t.type == "ball" || t.type == "tapered_ball")
        throw inputError(where + ": tool " + t.id + " is a " + t.type + " tool; this step needs a flat-bottomed tool");
    return impellerpath::flatCutter(t.id, static_cast<int>(number(r, "number", where)), t.diameter, t.fluteLength,
                                    t.reach, number(r, "rpm", where), number(r, "feed", where));
}

nlohmann::json cutterToJson(const impellerpath::CutterShape& c) {
    return {{"id", c.id},           {"number", c.number},   {"tipRadius", c.tipRadius}, {"taperDeg", c.taperDeg},
            {"fluteLength", c.fluteLength}, {"shankRadius", c.shankRadius}, {"reach", c.reach}, {"rpm", c.rpm},
            {"feed", c.feed}, {"flat", c.flat}};
}

nlohmann::json checkToJson(const impellerpath::CheckResult& r) {
    return {{"maxGougeMm", r.maxGouge}, {"holderCollisions", r.holderCollisions}, {"tilted", r.tilted},
            {"positions", r.positions}, {"worstAt", {r.worstAt[0], r.worstAt[1], r.worstAt[2]}},
            {"links", r.links}, {"linkCollisions", r.linkCollisions}};
}

impellerpath::CutterShape cutterFromJson(const nlohmann::json& j) {
    const std::string where = "impeller check: cutter";
    impellerpath::CutterShape c;
    c.id = j.value("id", std::string());
    c.number = static_cast<int>(number(j, "number", where));
    c.tipRadius = number(j, "tipRadius", where), c.taperDeg = number(j, "taperDeg", where);
    c.fluteLength = number(j, "fluteLength", where), c.shankRadius = number(j, "shankRadius", where);
    c.reach = number(j, "reach", where);
    c.flat = j.value("flat", false);
    return c;
}

}  // namespace

void bindImpeller(py::module_& m) {
    m.def(
        "recognise_impeller",
        [](const std::string& brep) {
            return python::guarded([&] {
                py::gil_scoped_release nogil;
                std::string json;
                runCatchingOcctFaults(
                    [&] {
                        const TopoDS_Shape part = partFromBrepText(brep);
                        const auto features = impeller::recogniseImpeller(part);
                        json = impeller::impellerToJson(features, impeller::measureImpeller(part, features));
                    },
                    "recognising the impeller");
                return json;
            });
        },
        py::arg("brep_text"),
        "Recognise the impeller in a solid given as BREP text (faces numbered as FreeCAD's FaceN) and "
        "measure it; returns JSON text (docs/impeller.md).");

    m.def(
        "impeller_program_data",
        [](const std::string& brep, double allowance, const std::string& kbPath, const std::string& sqlFolder,
           const std::string& route) {
            return python::guarded([&] {
                std::string blankBrep, json;
                {
                py::gil_scoped_release nogil;
                runCatchingOcctFaults(
                    [&] {
                        const TopoDS_Shape part = partFromBrepText(brep);
                        const auto features = impeller::recogniseImpeller(part);
                        const auto dims = impeller::measureImpeller(part, features);
                        const auto profile = impeller::outerProfile(part, features, allowance);
                        std::ostringstream os;
                        BRepTools::Write(impeller::revolveProfile(profile, features), os);
                        blankBrep = os.str();
                        const auto kb = kb::KnowledgeBase::openWithSqlFolder(kbPath, [&] { return sqlFolder; });
                        auto doc = nlohmann::json::parse(impeller::impellerToJson(features, dims));
                        doc["route"] = nlohmann::json::parse(impeller::routeToJson(kb::planImpellerRoute(kb, features, dims, route)));
                        doc["blank"] = {{"allowance", allowance}, {"axial", profile.axial}, {"radius", profile.radius}};
                        json = doc.dump(1);
                    },
                    "programming the impeller");
                }
                return py::make_tuple(json, blankBrep);
            });
        },
        py::arg("brep_text"), py::arg("allowance"), py::arg("kb_path"), py::arg("sql_folder"),
        py::arg("route") = std::string("impeller"),
        "Recognise and measure the impeller, build its blank (the outer profile grown by the allowance, "
        "revolved) and plan its route from the knowledge base at kb_path (built from sql_folder when "
        "missing): (json_text with \"route\" and \"blank\" added to recognise_impeller's, blank_brep_text).");

    m.def(
        "make_impeller",
        [](const std::string& specJson) {
            return python::guarded([&] {
                const auto spec = testparts::impellerSpecFromJson(specJson);
                testparts::Impeller imp;
                {
                    py::gil_scoped_release nogil;
                    runCatchingOcctFaults([&] { imp = testparts::makeImpeller(spec); }, "building the impeller");
                }
                std::ostringstream os;
                BRepTools::Write(imp.shape, os);
                return py::make_tuple(os.str(), testparts::truthToJson(imp.truth));
            });
        },
        py::arg("spec_json") = std::string(),
        "Build a generated impeller (spec keys: ImpellerSpec's fields): (brep_text, truth_json).");

    m.def(
        "impeller_tools",
        [](const std::string& kbPath, const std::string& sqlFolder) {
            return python::guarded([&] {
                const auto kb = kb::KnowledgeBase::openWithSqlFolder(kbPath, [&] { return sqlFolder; });
                auto list = nlohmann::json::array();
                for (const auto& t : kb::impellerTools(kb)) list.push_back(toolToJson(t));
                return list.dump(1);
            });
        },
        py::arg("kb_path"), py::arg("sql_folder"),
        "The tools the impeller route may choose (face mills, flat and ball end mills, drills, tapered balls) "
        "as JSON text: [{id, type, material, diameter, taperDeg, reach, fluteLength, shankDiameter, flutes}].");

    m.def(
        "impeller_toolpaths",
        [](const std::string& brep, const std::string& kbPath, const std::string& sqlFolder,
           const std::string& requestJson) {
            return python::guarded([&] {
                nlohmann::json request;
                try {
                    request = nlohmann::json::parse(requestJson);
                } catch (const nlohmann::json::exception& e) {
                    throw inputError(std::string("impeller toolpaths: the request is not JSON: ") + e.what());
                }
                const auto kb = kb::KnowledgeBase::openWithSqlFolder(kbPath, [&] { return sqlFolder; });
                const auto tools = kb::impellerTools(kb);
                const auto rougher = cutterOf(request, "rougher", tools);
                const auto finisher = cutterOf(request, "finisher", tools);
                std::optional<impellerpath::CutterShape> filletBall;
                if (request.contains("filletBall") && !request["filletBall"].is_null())
                    filletBall = ballCutter(request["filletBall"], "impeller toolpaths: filletBall", tools);
                // The axial steps (turning, facing, drilling, boring), when the request has "axial".
                std::optional<impellerpath::AxialCutters> axialCutters;
                impellerpath::AxialOptions axialOpt;
                if (request.contains("axial") && !request["axial"].is_null()) {
                    const auto& a = request["axial"];
                    const std::string aw = "impeller toolpaths: axial";
                    if (!a.is_object()) throw inputError(aw + " must be an object {faceMill, drill, boringMill}");
                    axialCutters.emplace();
                    for (auto [key, slot] : {std::pair{"faceMill", &axialCutters->faceMill},
                                             {"drill", &axialCutters->drill}, {"boringMill", &axialCutters->boringMill}})
                        if (a.contains(key) && !a[key].is_null()) *slot = flatCutterOf(a[key], aw + ": " + key, tools);
                    if (a.contains("drillAllowance")) axialOpt.drillAllowance = number(a, "drillAllowance", aw);
                    if (!(axialOpt.drillAllowance >= 0)) throw inputError(aw + ": drillAllowance must be >= 0");
                }
                impellerpath::PathOptions opt;
                const auto o = request.value("options", nlohmann::json::object());
                const std::string where = "impeller toolpaths: options";
                auto opt_num = [&](const char* key, double& field) {
                    if (o.contains(key)) field = number(o, key, where);
                };
                opt_num("roughAllowance", opt.roughAllowance);
                opt_num("stepDown", opt.stepDown);
                opt_num("stepOver", opt.stepOver);
                opt_num("finishStep", opt.finishStep);
                opt_num("safeDistance", opt.safeDistance);
                opt_num("maxTiltDeg", opt.maxTiltDeg);
                double stations = opt.stations, channels = opt.channels;
                opt_num("stations", stations);
                opt_num("channels", channels);
                if (!(stations >= 2 && stations <= 200)) throw inputError(where + ": stations wants 2 to 200");
                if (!(channels >= 0 && channels <= 1000)) throw inputError(where + ": channels wants 0 (all) or more");
                if (!(opt.roughAllowance >= 0) || !(opt.stepDown > 0) || !(opt.stepOver > 0 && opt.stepOver <= 1) ||
                    !(opt.finishStep > 0) || !(opt.safeDistance > 0) || !(opt.maxTiltDeg >= 0 && opt.maxTiltDeg < 90))
                    throw inputError(where + ": allowance >= 0, step-down > 0, step-over in (0, 1], finishing step > 0, "
                                             "safe distance > 0 and tilt 0-90 degrees");
                opt.stations = static_cast<int>(stations), opt.channels = static_cast<int>(channels);
                nlohmann::json out;
                {
                    py::gil_scoped_release nogil;
                    runCatchingOcctFaults(
                        [&] {
                            const TopoDS_Shape part = partFromBrepText(brep);
                            const auto features = impeller::recogniseImpeller(part);
                            const auto dims = impeller::measureImpeller(part, features);
                            const auto prog = impellerpath::impellerToolpaths(
                                part, features, dims, impellerpath::RouteCutters{rougher, finisher, filletBall}, opt);
                            // Moves as the posts take them: the tool tip and the unit axis.
                            auto opsToJson = [](const std::vector<impellerpath::Operation>& operations) {
                                auto ops = nlohmann::json::array();
                                for (const auto& op : operations) {
                                    auto moves = nlohmann::json::array();
                                    for (const auto& mv : op.moves) {
                                        const auto tip = mv.centre - op.cutter.tipRadius * mv.axis;
                                        moves.push_back({tip.x(), tip.y(), tip.z(), mv.axis.x(), mv.axis.y(),
                                                         mv.axis.z(), mv.rapid ? 1 : 0});
                                    }
                                    ops.push_back({{"name", op.name}, {"cutter", cutterToJson(op.cutter)}, {"moves", moves}});
                                }
                                return ops;
                            };
                            // The rapids against the blank, as a program read back is checked.
                            std::vector<std::pair<impellerpath::CutterShape, std::vector<impellerpath::Move>>> byOp;
                            for (const auto& op : prog.operations) byOp.push_back({op.cutter, op.moves});
                            const auto rapids = impellerpath::checkRapids(
                                impeller::outerProfile(part, features, opt.blankAllowance), features, byOp,
                                opt.rapidClearance - 1e-6);
                            out = {{"operations", opsToJson(prog.operations)},
                                   {"check", checkToJson(prog.check)},
                                   {"rapids", {{"checked", rapids.links}, {"collisions", rapids.linkCollisions}}}};
                            if (axialCutters) {
                                const auto axial = impellerpath::axialToolpaths(part, features, dims, *axialCutters, axialOpt);
                                out["axial"] = {{"operations", opsToJson(axial.operations)},
                                                {"check", checkToJson(axial.check)},
                                                {"notes", axial.notes}};
                            }
                        },
                        "computing the impeller toolpaths");
                }
                return out.dump();
            });
        },
        py::arg("brep_text"), py::arg("kb_path"), py::arg("sql_folder"), py::arg("request_json"),
        "5-axis toolpaths of the impeller in brep_text (docs/impeller.md §5). request_json: {rougher: {tool, "
        "number, rpm, feed}, finisher: {...}, filletBall: {...} (optional: finish_fillets), axial: {faceMill, drill, "
        "boringMill: {...}, drillAllowance} (optional: turn, face, drill, bore, drill_back, bore_back), options: "
        "{roughAllowance, stepDown, stepOver, finishStep, stations, safeDistance, maxTiltDeg, channels}}; the "
        "cutters' shapes come from the knowledge base's tools. Returns JSON text: {operations: [{name, cutter, "
        "moves: [[x, y, z, i, j, k, rapid]]}], check: {maxGougeMm, holderCollisions, tilted, positions, worstAt, "
        "links, linkCollisions}, rapids: {checked, collisions}, axial: {operations, check, notes}}, moves as tool "
        "tip and unit tool axis.");

    m.def(
        "impeller_check_apt",
        [](const std::string& brep, const std::string& aptText, const std::string& cuttersJson) {
            return python::guarded([&] {
                std::vector<impellerpath::CutterShape> cutters;
                try {
                    for (const auto& j : nlohmann::json::parse(cuttersJson)) cutters.push_back(cutterFromJson(j));
                } catch (const nlohmann::json::exception& e) {
                    throw inputError(std::string("impeller check: the cutters are not JSON: ") + e.what());
                }
                nlohmann::json out;
                {
                    py::gil_scoped_release nogil;
                    runCatchingOcctFaults(
                        [&] {
                            const TopoDS_Shape part = partFromBrepText(brep);
                            const auto features = impeller::recogniseImpeller(part);
                            const auto ops = impellerpath::movesOf(post::readApt(aptText), cutters);
                            out = checkToJson(impellerpath::checkProgram(part, features, ops));
                        },
                        "checking the impeller program");
                }
                return out.dump();
            });
        },
        py::arg("brep_text"), py::arg("apt_text"), py::arg("cutters_json"),
        "Check an APT program of the impeller (read back) against its blades and hub: the cutters "
        "([{number, tipRadius, taperDeg, fluteLength, shankRadius, reach}]) by tool number; returns JSON text "
        "{maxGougeMm, holderCollisions, positions, worstAt}.");
}
