// aeronc._core: impeller recognition and dimension analysis, and the impeller test part. Shapes
// cross as BREP text, results as JSON text (docs/impeller.md); every C++ and OCCT exception
// becomes RecognitionError with the core's message; the work runs without the GIL, with OCCT's
// faults caught.
#include "Guarded.h"

#include <aeronc/brep/OcctFaults.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/impeller/Blank.h>
#include <aeronc/impeller/BodyFusion.h>
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/impeller/ProcessRoute.h>
#include <aeronc/kb/ImpellerProgram.h>
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

#include <sstream>
#include <string>
#include <utility>
#include <vector>

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

// The route's steps of a request: [{position, operation, allowance, tool: {id} | id | null}], each
// tool the knowledge base's of that id (as edited by the user: any tool of the base).
std::vector<impeller::RouteStep> stepsOf(const nlohmann::json& request,
                                         const std::vector<impeller::CuttingTool>& tools) {
    const std::string where = "impeller program: steps";
    if (!request.contains("steps") || !request["steps"].is_array())
        throw inputError(where + " must be a list of the route's steps");
    std::vector<impeller::RouteStep> out;
    for (std::size_t i = 0; i < request["steps"].size(); ++i) {
        const auto& j = request["steps"][i];
        const std::string at = where + "[" + std::to_string(i) + "]";
        if (!j.is_object()) throw inputError(at + " must be an object {position, operation, allowance, tool}");
        impeller::RouteStep s;
        s.position = static_cast<int>(number(j, "position", at));
        if (!j.contains("operation") || !j["operation"].is_string()) throw inputError(at + ": \"operation\" must be text");
        s.operation = j["operation"].get<std::string>();
        if (j.contains("allowance") && !j["allowance"].is_null()) s.allowance = number(j, "allowance", at);
        if (j.contains("tool") && !j["tool"].is_null()) {
            const auto& t = j["tool"];
            const nlohmann::json& id = t.is_object() && t.contains("id") ? t["id"] : t;
            if (!id.is_string()) throw inputError(at + ": \"tool\" must be a tool id or {\"id\": id}");
            for (const auto& c : tools)
                if (c.id == id.get<std::string>()) s.tool = c;
            if (!s.tool)
                throw inputError(at + " (" + s.operation + "): no tool " + id.get<std::string>() + " in the knowledge base");
        }
        out.push_back(s);
    }
    return out;
}

nlohmann::json cutterToJson(const impellerpath::CutterShape& c) {
    return {{"id", c.id},           {"number", c.number},   {"tipRadius", c.tipRadius}, {"taperDeg", c.taperDeg},
            {"fluteLength", c.fluteLength}, {"shankRadius", c.shankRadius}, {"reach", c.reach}, {"rpm", c.rpm},
            {"feed", c.feed}, {"flat", c.flat}};
}

nlohmann::json checkToJson(const impellerpath::CheckResult& r) {
    return {{"maxGougeMm", r.maxGouge}, {"holderCollisions", r.holderCollisions}, {"tilted", r.tilted},
            {"positions", r.positions}, {"worstAt", {r.worstAt[0], r.worstAt[1], r.worstAt[2]}},
            {"links", r.links}, {"linkCollisions", r.linkCollisions}, {"minHolderGapMm", r.minHolderGap},
            {"leftOut", r.leftOut}};
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
        "fuse_bodies",
        [](const std::string& brep) {
            return python::guarded([&] {
                impeller::FusedBodies fused;
                {
                    py::gil_scoped_release nogil;
                    runCatchingOcctFaults([&] { fused = impeller::fuseBodies(shapeFromBrepText(brep)); },
                                          "fusing the bodies");
                }
                std::ostringstream os;
                BRepTools::Write(fused.solid, os);
                const nlohmann::json j{{"bodies", fused.bodies}, {"fused", fused.fused}, {"dropped", fused.dropped},
                                       {"fuzzyValue", fused.fuzzyValue}, {"facesFixed", fused.facesFixed},
                                       {"seconds", fused.seconds}, {"summary", fused.summary}};
                return py::make_tuple(os.str(), j.dump());
            });
        },
        py::arg("brep_text"),
        "Fuse the solids of a shape given as BREP text (a part exported as several bodies) into one "
        "valid solid, all fused to the largest in one Boolean (BodyFusion.h): (brep_text, summary_json with "
        "bodies, fused, dropped, fuzzyValue, facesFixed, seconds, summary).");

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
        "impeller_program",
        [](const std::string& brep, const std::string& kbPath, const std::string& sqlFolder,
           const std::string& requestJson) {
            return python::guarded([&] {
                nlohmann::json request;
                try {
                    request = nlohmann::json::parse(requestJson);
                } catch (const nlohmann::json::exception& e) {
                    throw inputError(std::string("impeller program: the request is not JSON: ") + e.what());
                }
                if (!request.is_object()) throw inputError("impeller program: the request must be an object {steps, ...}");
                const auto kb = kb::KnowledgeBase::openWithSqlFolder(kbPath, [&] { return sqlFolder; });
                const auto steps = stepsOf(request, kb::impellerTools(kb));
                kb::ImpellerProgramOptions opt;
                for (auto [key, field] : {std::pair{"material", &opt.material}, {"machine", &opt.machine}})
                    if (request.contains(key)) {
                        if (!request[key].is_string()) throw inputError(std::string("impeller program: \"") + key + "\" must be text");
                        *field = request[key].get<std::string>();
                    }
                impellerpath::PathOptions& paths = opt.paths;
                const auto o = request.value("options", nlohmann::json::object());
                const std::string where = "impeller program: options";
                if (!o.is_object()) throw inputError(where + " must be an object");
                auto opt_num = [&](const char* key, double& field) {
                    if (o.contains(key)) field = number(o, key, where);
                };
                opt_num("stepDown", paths.stepDown);
                opt_num("stepOver", paths.stepOver);
                opt_num("finishStep", paths.finishStep);
                opt_num("safeDistance", paths.safeDistance);
                opt_num("maxTiltDeg", paths.maxTiltDeg);
                double stations = paths.stations, channels = paths.channels;
                opt_num("stations", stations);
                opt_num("channels", channels);
                if (!(stations >= 2 && stations <= 200)) throw inputError(where + ": stations wants 2 to 200");
                if (!(channels >= 0 && channels <= 1000)) throw inputError(where + ": channels wants 0 (all) or more");
                if (!(paths.stepDown > 0) || !(paths.stepOver > 0 && paths.stepOver <= 1) || !(paths.finishStep > 0) ||
                    !(paths.safeDistance > 0) || !(paths.maxTiltDeg >= 0 && paths.maxTiltDeg < 90))
                    throw inputError(where + ": step-down > 0, step-over in (0, 1], finishing step > 0, "
                                             "safe distance > 0 and tilt 0-90 degrees");
                paths.stations = static_cast<int>(stations), paths.channels = static_cast<int>(channels);
                kb::checkImpellerProgram(steps, kb, opt);  // bad requests stop before the part is read
                nlohmann::json out;
                {
                    py::gil_scoped_release nogil;
                    runCatchingOcctFaults(
                        [&] {
                            const TopoDS_Shape part = partFromBrepText(brep);
                            const auto features = impeller::recogniseImpeller(part);
                            const auto dims = impeller::measureImpeller(part, features);
                            const auto prog = kb::programImpeller(part, features, dims, steps, kb, opt);
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
                            auto numbers = nlohmann::json::object();
                            for (const auto& [position, n] : prog.toolNumbers) numbers[std::to_string(position)] = n;
                            auto cutting = nlohmann::json::array();
                            for (const auto& c : prog.cutting)
                                cutting.push_back({{"tool", c.tool}, {"operation", c.operation}, {"rpm", c.rpm},
                                                   {"feed", c.feed}, {"plungeFeed", c.plungeFeed}, {"fz", c.fz},
                                                   {"ap", c.ap}, {"ae", c.ae}, {"length", c.length},
                                                   {"active", c.active}, {"kbFz", c.kbFz}, {"kbVc", c.kbVc},
                                                   {"steps", c.steps}});
                            out = {{"operations", opsToJson(prog.fiveAxis.operations)},
                                   {"check", checkToJson(prog.fiveAxis.check)},
                                   {"rapids", {{"checked", prog.rapids.links}, {"collisions", prog.rapids.linkCollisions}}},
                                   {"axial", {{"operations", opsToJson(prog.axial.operations)},
                                              {"check", checkToJson(prog.axial.check)},
                                              {"notes", prog.axial.notes}}},
                                   {"toolNumbers", numbers},
                                   {"cutting", cutting},
                                   {"seconds", {{"toolpaths", prog.toolpathSeconds}, {"cutting", prog.cuttingSeconds}}}};
                        },
                        "programming the impeller");
                }
                return out.dump();
            });
        },
        py::arg("brep_text"), py::arg("kb_path"), py::arg("sql_folder"), py::arg("request_json"),
        "The impeller program of the part in brep_text (kb::programImpeller, as `aeronc impeller-program` makes "
        "it; docs/impeller.md §5-§6). request_json: {steps: [the route's steps, as edited: {position, operation, "
        "allowance, tool: {id}}], material, machine, options: {stations, channels, stepDown, stepOver, "
        "finishStep, safeDistance, maxTiltDeg}}; tools from the knowledge base at kb_path (built from "
        "sql_folder when missing). Returns JSON text: {operations: [{name, cutter, moves: [[x, y, z, i, j, k, "
        "rapid]]}], check: {maxGougeMm, holderCollisions, tilted, positions, worstAt, links, linkCollisions}, "
        "rapids: {checked, collisions}, axial: {operations, check, notes}, toolNumbers: {position: number}, "
        "cutting: [{tool, operation, rpm, feed, plungeFeed, fz, ap, ae, length, active, kbFz, kbVc, steps}], "
        "seconds: {toolpaths, cutting}}, moves as tool tip and unit tool axis.");

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
