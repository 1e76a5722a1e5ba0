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
#include <aeronc/testparts/ImpellerGenerator.h>

#include <BRepTools.hxx>
#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include <sstream>
#include <string>

namespace py = pybind11;
using namespace aeronc;

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
}
