// aeronc._core: verification of a program against the part (a Z-dexel simulation). The program
// and the report cross as JSON text (docs/verification.md); every C++ and OCCT exception becomes
// VerifyError (a RuntimeError) with the core's message; the simulation runs without the GIL.
#include "Guarded.h"

#include <aeronc/core/Error.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/verify/ReportJson.h>
#include <aeronc/brep/ShapeMesh.h>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include <string>

namespace py = pybind11;
using namespace aeronc;

namespace {

PyObject* g_verifyError = nullptr;

nlohmann::json parse(const std::string& text, const char* what) {
    if (text.empty()) return nlohmann::json::object();
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw inputError(std::string(what) + " are not valid JSON: " + e.what());
    }
}

double meshOption(const nlohmann::json& o, const char* key, double fallback) {
    if (!o.contains(key)) return fallback;
    if (!o[key].is_number() || !(o[key].get<double>() > 0))
        throw inputError(std::string("option ") + key + " must be a positive number");
    return o[key].get<double>();
}

}  // namespace

// Registers simulate() and VerifyError on m.
void bindVerify(py::module_& m) {
    g_verifyError = PyErr_NewException("aeronc._core.VerifyError", PyExc_RuntimeError, nullptr);
    m.attr("VerifyError") = py::handle(g_verifyError);

    m.def(
        "simulate",
        [](const std::string& brep, const std::string& opsJson, const std::string& optionsJson) {
            return aeronc::python::guardedAs(g_verifyError, [&] {
                py::gil_scoped_release nogil;
                const auto program = verify::programFromJson(parse(opsJson, "the operations"));
                const auto options = parse(optionsJson, "the options");
                const auto sim = verify::simulationOptionsFromJson(options);
                const auto mesh = verify::meshShape(partFromBrepText(brep), meshOption(options, "deflection", 0.005),
                                                    meshOption(options, "angularDeflection", 0.5));
                return verify::toJson(verify::simulate(mesh, program, sim)).dump();
            });
        },
        py::arg("brep_text"), py::arg("ops_json"), py::arg("options_json") = std::string(),
        "Simulate operations (JSON, docs/verification.md) against the blank on the part given as BREP text; "
        "returns the report (gouges, collisions, coverage, leftover map) as JSON text.");
}
