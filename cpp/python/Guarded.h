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

// Sets the Python exception `type` with `message`. A message may quote input that is not
// UTF-8 (a byte of a file, half a character): such bytes become \xNN escapes, so the caller
// always gets `type`, never a UnicodeDecodeError in its place.
inline void setError(PyObject* type, const std::string& message) {
    PyObject* text = PyUnicode_DecodeUTF8(message.data(), static_cast<Py_ssize_t>(message.size()), "backslashreplace");
    if (!text) {
        PyErr_Clear();
        PyErr_SetString(type, "a failure in the AeroNC core whose message cannot be shown");
        return;
    }
    PyErr_SetObject(type, text);
    Py_DECREF(text);
}

// Runs f; any C++ exception becomes the Python exception `type` with its message.
template <class F>
auto guardedAs(PyObject* type, F f) -> decltype(f()) {
    try {
        return f();
    } catch (const pybind11::error_already_set&) {
        throw;
    } catch (const Error& e) {
        setError(type, e.what());
    } catch (const Standard_Failure& e) {
        setError(type, std::string("OpenCASCADE: ") + e.GetMessageString());
    } catch (const std::exception& e) {
        setError(type, e.what());
    } catch (...) {
        setError(type, "unknown failure in the AeroNC core");
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
