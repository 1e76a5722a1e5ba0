// aeronc._core: the toolpaths of machining units, JSON text in and out (docs/toolpaths.md).
// Every C++ exception stops here and becomes ToolpathError (a RuntimeError) with the core's
// message; the computing runs without the GIL.
#include "Guarded.h"

#include <aeronc/core/Error.h>
#include <aeronc/toolpath/ToolpathJson.h>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
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
                std::vector<std::string> out;
                out.reserve(units.size());
                py::gil_scoped_release nogil;
                for (std::size_t i = 0; i < units.size(); ++i) {
                    try {
                        out.push_back(aeronc::toolpath::toolpathJson(units[i]));
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
}
