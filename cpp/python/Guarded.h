#pragma once
// The binding boundary: every C++ and OCCT exception becomes a Python exception (the module's
// RecognitionError, a RuntimeError, unless told otherwise) with the core's message; Python
// exceptions pass through.
#include <aeronc/core/Error.h>

#include <Standard_Failure.hxx>
#include <pybind11/pybind11.h>

#include <string>

namespace aeronc::python {

// The module's exception type, set once when the module loads.
inline PyObject*& errorType() {
    static PyObject* type = nullptr;
    return type;
}

// Runs f; any C++ exception becomes the Python exception `type` with its message.
template <class F>
auto guardedAs(PyObject* type, F f) -> decltype(f()) {
    try {
        return f();
    } catch (const pybind11::error_already_set&) {
        throw;
    } catch (const Error& e) {
        PyErr_SetString(type, e.what());
    } catch (const Standard_Failure& e) {
        PyErr_SetString(type, (std::string("OpenCASCADE: ") + e.GetMessageString()).c_str());
    } catch (const std::exception& e) {
        PyErr_SetString(type, e.what());
    } catch (...) {
        PyErr_SetString(type, "unknown failure in the AeroNC core");
    }
    throw pybind11::error_already_set();
}

// guardedAs() with the module's RecognitionError.
template <class F>
auto guarded(F f) -> decltype(f()) {
    return guardedAs(errorType(), f);
}


void bindKnowledgeBase(pybind11::module_& m);

}  // namespace aeronc::python
