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
                const auto mesh = meshShape(partFromBrepText(brep), meshOption(options, "deflection", 0.002),
                                                    meshOption(options, "angularDeflection", 0.5));
                return verify::toJson(verify::simulate(mesh, program, sim)).dump();
            });
        },
        py::arg("brep_text"), py::arg("ops_json"), py::arg("options_json") = std::string(),
        "Simulate operations (JSON, docs/verification.md) against the blank on the part given as BREP text; "
        "returns the report (gouges, collisions, coverage, leftover map) as JSON text.");

    m.def(
        "simulate_setups",
        [](const std::string& brep, const std::string& setupsJson, const std::string& optionsJson) {
            return aeronc::python::guardedAs(g_verifyError, [&] {
                py::gil_scoped_release nogil;
                const auto j = parse(setupsJson, "the setups");
                if (!j.is_array() || j.empty()) throw inputError("the setups must be a non-empty list");
                std::vector<verify::SetupProgram> setups;
                for (const auto& s : j) {
                    if (!s.is_object() || !s.contains("program") || !s.contains("rotation") || !s.contains("translation"))
                        throw inputError("each setup needs \"program\", \"rotation\" (9 numbers) and \"translation\" (3)");
                    verify::SetupProgram sp;
                    sp.name = s.value("name", std::string("setup ") + std::to_string(setups.size() + 1));
                    const auto& r = s.at("rotation");
                    const auto& t = s.at("translation");
                    if (!r.is_array() || r.size() != 9 || !t.is_array() || t.size() != 3)
                        throw inputError("setup " + sp.name + ": rotation needs 9 numbers and translation 3");
                    for (int i = 0; i < 9; ++i) sp.toPart.rotation[std::size_t(i)] = r.at(std::size_t(i)).get<double>();
                    for (int i = 0; i < 3; ++i) sp.toPart.translation[std::size_t(i)] = t.at(std::size_t(i)).get<double>();
                    sp.program = verify::programFromJson(s.at("program"));
                    setups.push_back(std::move(sp));
                }
                const auto options = parse(optionsJson, "the options");
                const auto sim = verify::simulationOptionsFromJson(options);
                const auto mesh = meshShape(partFromBrepText(brep), meshOption(options, "deflection", 0.002),
                                                    meshOption(options, "angularDeflection", 0.5));
                nlohmann::json out = nlohmann::json::array();
                for (const auto& report : verify::simulateSetups(mesh, setups, sim)) out.push_back(verify::toJson(report));
                return out.dump();
            });
        },
        py::arg("brep_text"), py::arg("setups_json"), py::arg("options_json") = std::string(),
        "Simulate several setups of one part in order (JSON list of {name, rotation, translation: the motion "
        "from the setup's frame to the part's, program}); each in its own frame from the whole blank, its rapids "
        "checked against what the setups before left. Returns the reports as a JSON list.");
}
