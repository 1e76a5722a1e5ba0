// aeronc._core: the binding between FreeCAD's Python and the C++ core.
// Every C++ and OCCT exception stops here and becomes RecognitionError.
#include <aeronc/core/Error.h>
#include <aeronc/brep/OcctFaults.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/DomainTreeJson.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/kb/KnowledgeBase.h>
#include <aeronc/kb/ToolPlanning.h>
#include <aeronc/testparts/PanelGenerator.h>
#include <aeronc/toolselect/PlanJson.h>

#include <BRepTools.hxx>
#include <Standard_Failure.hxx>
#include <nlohmann/json.hpp>
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "Guarded.h"

namespace py = pybind11;
using namespace aeronc;
using aeronc::python::guarded;
void bindKinematics(py::module_& m);  // kinematics_bindings.cpp: 5-axis kinematics and posts

namespace {

struct PyCallbackAbort {};

recognition::RecogniseOptions makeOptions(const std::vector<std::array<double, 3>>& directions, double allowance,
                                          const py::object& blank, double lin, double ang, double chord,
                                          const py::object& progress) {
    recognition::RecogniseOptions o;
    for (auto& d : directions) o.directions.push_back({d[0], d[1], d[2]});
    o.blankAllowance = allowance;
    if (!blank.is_none()) {
        auto b = blank.cast<std::vector<double>>();
        if (b.size() != 6) throw inputError("blank must be (xmin, ymin, zmin, xmax, ymax, zmax)");
        o.blank = recognition::Blank{{b[0], b[1], b[2]}, {b[3], b[4], b[5]}};
    }
    o.linearTolerance = lin;
    o.angularTolerance = ang;
    o.chordTolerance = chord;
    if (!progress.is_none()) {
        o.progress = [progress](double f, const std::string& stage) {
            py::gil_scoped_acquire gil;
            py::object r = progress(f, stage);
            return r.is_none() ? true : r.cast<bool>();
        };
    }
    return o;
}

}  // namespace

void bindOptimise(py::module_& m);  // optimise_bindings.cpp
void bindToolpath(py::module_& m);  // toolpath_bindings.cpp: toolpaths of machining units
void bindCompensation(py::module_& m);  // compensation_bindings.cpp: datum holes and compensation
void bindChain(py::module_& m);     // chain_bindings.cpp
void bindVerify(py::module_& m);    // verify_bindings.cpp: simulation of a program against the part
void bindImpeller(py::module_& m);  // impeller_bindings.cpp: impeller recognition, test impellers

PYBIND11_MODULE(_core, m) {
    m.doc() = "AeroNC core: machining-feature recognition and test parts";
    aeronc::python::errorType() = py::exception<Error>(m, "RecognitionError", PyExc_RuntimeError).ptr();
    aeronc::python::bindKnowledgeBase(m);

    // Reading and recognition run with OCCT's faults caught: a damaged shape that makes
    // OpenCASCADE fault raises RecognitionError, and FreeCAD's session goes on. Faces are
    // numbered as the shape numbers them: the FaceN of the object the shape came from.
    auto recogniseWith = [](const std::function<TopoDS_Shape()>& load, const std::string& origin,
                            const recognition::RecogniseOptions& o, const std::string& what) {
        recognition::DomainTree t;
        {
            py::gil_scoped_release nogil;
            runCatchingOcctFaults([&] { t = recognition::recogniseShape(load(), origin, o); }, what);
        }
        return recognition::toJson(t, -1);
    };

    m.def(
        "recognise_brep",
        [recogniseWith](const std::string& brep, const std::vector<std::array<double, 3>>& directions,
                        double allowance, const py::object& blank, double lin, double ang, double chord,
                        const py::object& progress) {
            return guarded([&] {
                const auto o = makeOptions(directions, allowance, blank, lin, ang, chord, progress);
                return recogniseWith([&] { return shapeFromBrepText(brep); }, "BREP text", o,
                                     "recognising the shape");
            });
        },
        py::arg("brep_text"), py::arg("directions") = std::vector<std::array<double, 3>>{},
        py::arg("allowance") = 0.0, py::arg("blank") = py::none(), py::arg("linear_tolerance") = 1e-3,
        py::arg("angular_tolerance") = 1e-3, py::arg("chord_tolerance") = 0.01, py::arg("progress") = py::none(),
        "Recognise the machining features of a solid given as BREP text; returns JSON text.");

    m.def(
        "recognise_file",
        [recogniseWith](const std::string& path, const std::vector<std::array<double, 3>>& directions,
                        double allowance, const py::object& blank, double lin, double ang, double chord,
                        const py::object& progress) {
            return guarded([&] {
                const auto o = makeOptions(directions, allowance, blank, lin, ang, chord, progress);
                return recogniseWith([&] { return loadPart(path); }, path, o, path);
            });
        },
        py::arg("path"), py::arg("directions") = std::vector<std::array<double, 3>>{}, py::arg("allowance") = 0.0,
        py::arg("blank") = py::none(), py::arg("linear_tolerance") = 1e-3, py::arg("angular_tolerance") = 1e-3,
        py::arg("chord_tolerance") = 0.01, py::arg("progress") = py::none(),
        "Recognise the machining features of a STEP or BREP file; returns JSON text.");

    m.def(
        "select_tools_tree",
        [](const std::string& treeJson, const std::string& kbPath, const std::string& material,
           const std::string& sqlFolder, const std::string& machine) {
            return guarded([&] {
                py::gil_scoped_release nogil;
                const auto tree = recognition::fromJson(treeJson);
                const auto kb = kb::KnowledgeBase::openWithSqlFolder(kbPath, [&] { return sqlFolder; });
                return toolselect::toJson(kb::planTools(tree, kb, material, machine), material, -1);
            });
        },
        py::arg("tree_json"), py::arg("kb_path"), py::arg("material"), py::arg("sql_folder"),
        py::arg("machine") = std::string(),
        "Plan the tools of a recognised machining-domain tree (the JSON text recognise_* returned) from "
        "the knowledge base at kb_path (built from sql_folder's schema.sql and default_data.sql when "
        "missing); returns JSON text.");

    m.def(
        "make_panel",
        [](const std::string& specJson) {
            return guarded([&] {
                testparts::PanelSpec s;
                const auto j = specJson.empty() ? nlohmann::json::object() : nlohmann::json::parse(specJson);
                auto get = [&](const char* k, auto& v) {
                    if (j.contains(k)) v = j.at(k).get<std::decay_t<decltype(v)>>();
                };
                get("pocketsX", s.pocketsX), get("pocketsY", s.pocketsY), get("pitch", s.pitch);
                get("ribThickness", s.ribThickness), get("border", s.border), get("thickness", s.thickness);
                get("webZ", s.webZ), get("cornerRadius", s.cornerRadius), get("floorFillet", s.floorFillet);
                get("lowerRibs", s.lowerRibs), get("lowerRibBy", s.lowerRibBy), get("islands", s.islands);
                get("openings", s.openings), get("lighteningHoles", s.lighteningHoles);
                get("boltHoles", s.boltHoles), get("joggles", s.joggles), get("flange", s.flange);
                get("bottomPockets", s.bottomPockets), get("bottomDepth", s.bottomDepth);
                testparts::Panel p;
                {
                    py::gil_scoped_release nogil;
                    p = testparts::makePanel(s);
                }
                std::ostringstream os;
                BRepTools::Write(p.shape, os);
                return py::make_tuple(os.str(), testparts::truthToJson(p));
            });
        },
        py::arg("spec_json") = std::string(), "Build a generated integral panel: (brep_text, truth_json).");
    bindOptimise(m);
    bindChain(m);
    bindKinematics(m);
    bindToolpath(m);
    bindCompensation(m);
    bindVerify(m);
    bindImpeller(m);
}
