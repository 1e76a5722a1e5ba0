// aeronc._core: the toolpaths of machining units, JSON text in and out (docs/toolpaths.md).
// Every C++ exception stops here and becomes ToolpathError (a RuntimeError) with the core's
// message; the computing runs without the GIL.
#include "Guarded.h"

#include <aeronc/core/Error.h>
#include <aeronc/toolpath/PathText.h>
#include <aeronc/toolpath/ToolpathJson.h>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <string>
#include <thread>
#include <vector>

namespace py = pybind11;

namespace {
PyObject* g_toolpathError = nullptr;
}

void bindToolpath(py::module_& m) {
    g_toolpathError = PyErr_NewException("aeronc._core.ToolpathError", PyExc_RuntimeError, nullptr);
    m.attr("ToolpathError") = py::handle(g_toolpathError);

    m.def(
        "toolpath",
        [](const std::string& unit) {
            return aeronc::python::guardedAs(g_toolpathError, [&] {
                py::gil_scoped_release nogil;
                return aeronc::toolpath::toolpathJson(unit);
            });
        },
        py::arg("unit_json"),
        "The toolpath of one machining unit (JSON text, see docs/toolpaths.md); returns JSON text.");

    m.def(
        "toolpaths",
        [](const std::vector<std::string>& units) {
            return aeronc::python::guardedAs(g_toolpathError, [&] {
                // The units are independent: one worker per core takes the next one in turn.
                std::vector<std::string> out(units.size());
                std::vector<std::exception_ptr> failed(units.size());
                {
                    py::gil_scoped_release nogil;
                    std::atomic<std::size_t> next{0};
                    auto work = [&] {
                        for (std::size_t i; (i = next++) < units.size();) {
                            try {
                                out[i] = aeronc::toolpath::toolpathJson(units[i]);
                            } catch (...) {
                                failed[i] = std::current_exception();
                            }
                        }
                    };
                    const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
                    std::vector<std::thread> pool;
                    for (std::size_t k = 1; k < std::min(cores, units.size()); ++k) pool.emplace_back(work);
                    work();
                    for (std::thread& t : pool) t.join();
                }
                for (std::size_t i = 0; i < units.size(); ++i) {
                    if (!failed[i]) continue;
                    try {
                        std::rethrow_exception(failed[i]);
                    } catch (const aeronc::Error& e) {
                        throw aeronc::Error(e.kind(), "unit " + std::to_string(i) + ": " + e.what());
                    }
                }
                return out;
            });
        },
        py::arg("unit_jsons"),
        "The toolpaths of a list of machining units, computed without the GIL; returns a list of JSON texts. "
        "The first unit that fails raises ToolpathError naming its index.");

    m.def(
        "toolpath_program",
        [](const std::vector<std::string>& units, const std::string& label, double horizontalFeed,
           double verticalFeed, double horizontalRapid, double verticalRapid) {
            return aeronc::python::guardedAs(g_toolpathError, [&] {
                using namespace aeronc::toolpath;
                Toolpath all;
                std::string text;
                double seconds = 0;
                {
                    py::gil_scoped_release nogil;
                    for (std::size_t i = 0; i < units.size(); ++i) {
                        try {
                            Toolpath t = toolpathOfJson(units[i]);
                            all.moves.insert(all.moves.end(), t.moves.begin(), t.moves.end());
                            all.cutLength += t.cutLength;
                            all.rapidLength += t.rapidLength;
                        } catch (const aeronc::Error& e) {
                            throw aeronc::Error(e.kind(), "unit " + std::to_string(i) + ": " + e.what());
                        }
                    }
                    const PathFeeds feeds{horizontalFeed, verticalFeed, horizontalRapid, verticalRapid};
                    text = pathText(all, feeds, label);
                    seconds = estimatedSeconds(all, feeds);
                }
                py::dict out;
                out["gcode"] = text;
                out["moves"] = all.moves.size();
                out["cutLength"] = all.cutLength;
                out["rapidLength"] = all.rapidLength;
                out["seconds"] = seconds;
                return out;
            });
        },
        py::arg("unit_jsons"), py::arg("label"), py::arg("horizontal_feed"), py::arg("vertical_feed"),
        py::arg("horizontal_rapid") = 0.0, py::arg("vertical_rapid") = 0.0,
        "The toolpaths of a list of machining units one after the other, as the G-code text of a FreeCAD Path "
        "(feeds in mm/s) with their lengths and estimated seconds (rapid rates 0: rapids take no time): "
        "{\"gcode\", \"moves\", \"cutLength\", \"rapidLength\", \"seconds\"}.");
}
