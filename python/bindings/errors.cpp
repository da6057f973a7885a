/// emit's errors as Python exceptions: emit.Error, and under it InvalidInput (also a ValueError),
/// IoError (an OSError) and SolverError (a RuntimeError), each with emit's one-line message.
#include <Python.h>

#include "bindings.hpp"
#include "emit/core/errors.hpp"

namespace emit::python {

namespace {

/// A new exception class of the module, derived from `bases`.
PyObject* new_exception(py::module_& m, const char* name, const char* doc, py::tuple bases) {
  const std::string qualified = std::string("emit.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!type) throw py::error_already_set();
  m.add_object(name, py::handle(type));  // the module keeps the reference
  return type;
}

}  // namespace

void bind_errors(py::module_& m) {
  PyObject* error = new_exception(m, "Error", "Any error emit reports: its message says what is wrong and where.",
                                  py::make_tuple(py::handle(PyExc_Exception)));
  static PyObject* invalid_input =
      new_exception(m, "InvalidInput", "Bad input: a sensor, a file, an array or an option emit cannot use.",
                    py::make_tuple(py::handle(error), py::handle(PyExc_ValueError)));
  static PyObject* io_error = new_exception(m, "IoError", "A file or device that could not be read or written.",
                                            py::make_tuple(py::handle(error), py::handle(PyExc_OSError)));
  static PyObject* solver_error = new_exception(m, "SolverError", "A numerical step that failed (a singular system).",
                                                py::make_tuple(py::handle(error), py::handle(PyExc_RuntimeError)));
  static PyObject* any_error = error;
  // pybind11's translator type takes the exception_ptr by value.
  py::register_exception_translator([](std::exception_ptr thrown) {  // NOLINT(performance-unnecessary-value-param)
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InvalidInput& e) {
      PyErr_SetString(invalid_input, e.what());
    } catch (const IoError& e) {
      PyErr_SetString(io_error, e.what());
    } catch (const SolverError& e) {
      PyErr_SetString(solver_error, e.what());
    } catch (const Error& e) {
      PyErr_SetString(any_error, e.what());
    }
  });
}

}  // namespace emit::python
