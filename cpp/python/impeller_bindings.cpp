// aeronc._core: impeller recognition and dimension analysis, and the impeller test part. Shapes
// cross as BREP text, results as JSON text (docs/impeller.md); every C++ and OCCT exception
// becomes RecognitionError with the core's message; the work runs without the GIL, with OCCT's
// faults caught.
#include "Guarded.h"

#include <aeronc/brep/OcctFaults.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/testparts/ImpellerGenerator.h>

#include <BRepTools.hxx>
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
