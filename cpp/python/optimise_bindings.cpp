// aeronc._core: the cutting-parameter optimiser for Python. Parameters and results cross as
// JSON text, like the rest of the module; every C++ exception becomes the module's error
// (Guarded.h).
#include "Guarded.h"

#include <aeronc/core/Error.h>
#include <aeronc/kb/OptimiseParameters.h>
#include <aeronc/optimise/ObjectiveMap.h>
#include <aeronc/optimise/Report.h>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include <string>

namespace py = pybind11;

namespace {

// The comparison (and, with mapPoints > 0, the objective map) of a complete parameter set, as
// (text, JSON). Runs without the GIL.
py::tuple solveParameters(const nlohmann::json& params, const std::string& method, unsigned long long seed,
                          int mapPoints) {
    std::string text, json;
    {
        py::gil_scoped_release nogil;
        aeronc::optimise::GeneticOptions ga;
        ga.seed = seed;
        const auto c = aeronc::optimise::compare(aeronc::optimise::parseParameters(params),
                                                 aeronc::optimise::parseMethod(method), ga);
        text = aeronc::optimise::toText(c);
        auto out = aeronc::optimise::toJson(c);
        out["parameters"] = params;  // as solved, after the knowledge base filled it in
        if (mapPoints > 0) {
            aeronc::optimise::MapBox box;
            box.nCount = box.fzCount = mapPoints;
            out["map"] = aeronc::optimise::objectiveMap(c.parameters.problem, c.primary(), box);
        }
        json = out.dump();
    }
    return py::make_tuple(text, json);
}

nlohmann::json parseJson(const std::string& text) { return aeronc::optimise::parameterJson(text); }

}  // namespace

// Registers optimise_cutting() and optimise_cutting_in() on m. Call it after the module's error
// class and KnowledgeBase exist.
void bindOptimise(py::module_& m) {
    m.def(
        "optimise_cutting",
        [](const std::string& paramsJson, const std::string& method, unsigned long long seed, const std::string& kbPath,
           const std::string& sqlFolder, int mapPoints) {
            return aeronc::python::guarded([&] {
                nlohmann::json params = parseJson(paramsJson);
                if (!kbPath.empty()) {
                    py::gil_scoped_release nogil;
                    const auto kb = aeronc::kb::KnowledgeBase::openWithSqlFolder(kbPath, [&] { return sqlFolder; });
                    params = aeronc::kb::withKnowledgeBase(kb, params);
                }
                return solveParameters(params, method, seed, mapPoints);
            });
        },
        py::arg("params_json"), py::arg("method") = std::string("nlopt"), py::arg("seed") = 1ULL,
        py::arg("kb_path") = std::string(), py::arg("sql_folder") = std::string(), py::arg("map_points") = 0,
        "Optimise spindle speed and feed per tooth for one milling operation. params_json is the parameter "
        "file's text (docs/cutting-optimisation.md); with kb_path its \"kb\" names are looked up there (built "
        "from sql_folder when missing). method: 'nlopt', 'ga' or 'both'. Returns (report_text, result_json); "
        "the JSON holds the solved \"parameters\", and with map_points > 0 a \"map\" of the combined objective "
        "over a map_points x map_points log grid of (n, f_z) around the optimum, for plotting.");
    m.def(
        "optimise_cutting_in",
        [](const aeronc::kb::KnowledgeBase& kb, const std::string& paramsJson, const std::string& method,
           unsigned long long seed, int mapPoints) {
            return aeronc::python::guarded([&] {
                // The knowledge base's connection stays with the GIL: Python may share the object.
                const auto params = aeronc::kb::withKnowledgeBase(kb, parseJson(paramsJson));
                return solveParameters(params, method, seed, mapPoints);
            });
        },
        py::arg("kb"), py::arg("params_json"), py::arg("method") = std::string("nlopt"), py::arg("seed") = 1ULL,
        py::arg("map_points") = 0,
        "optimise_cutting() with the \"kb\" names looked up in an open KnowledgeBase (no file opened per call: "
        "for many operations).");
}
