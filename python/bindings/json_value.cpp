#include "json_value.hpp"

#include <Python.h>

#include <limits>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"

namespace emit::python {

namespace py = pybind11;

namespace {

/// A sensor nests four levels deep (excitation.readings[i][j]); this is room enough, and keeps a
/// list nested 10^5 deep from overflowing the stack.
constexpr int max_depth = 64;

std::string key_path(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
std::string item_path(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }
/// Where a message's value is: "shape.width_mm: ", or nothing at the top (the caller names the dict).
std::string at(const std::string& path) { return path.empty() ? "" : path + ": "; }

/// A non-str key as Python writes it, in ASCII: 3, (1, 2), None.
std::string ascii_repr(const py::handle& value) {
  PyObject* text = PyObject_ASCII(value.ptr());
  if (!text) {
    PyErr_Clear();
    return std::string("a ") + Py_TYPE(value.ptr())->tp_name;
  }
  return py::reinterpret_steal<py::str>(text).cast<std::string>();
}

/// A str as UTF-8. \throw InvalidInput "<path>: <what>"\ud800" is not Unicode text (a lone
/// surrogate)", the text quoted with what UTF-8 cannot hold escaped as Python escapes it.
std::string utf8_of(const py::handle& text, const std::string& path, const std::string& what) {
  Py_ssize_t size = 0;
  if (const char* bytes = PyUnicode_AsUTF8AndSize(text.ptr(), &size)) return {bytes, static_cast<std::size_t>(size)};
  PyErr_Clear();
  std::string escaped = "(unreadable)";
  if (PyObject* ascii = PyUnicode_AsEncodedString(text.ptr(), "ascii", "backslashreplace")) {
    escaped = PyBytes_AsString(ascii);
    Py_DECREF(ascii);
  } else {
    PyErr_Clear();
  }
  throw InvalidInput(at(path) + what + quote_input(escaped) + " is not Unicode text (a lone surrogate)");
}

nlohmann::json integer_of(const py::handle& value) {
  int overflow = 0;
  const long long i = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
  if (overflow == 0 && !(i == -1 && PyErr_Occurred())) return i;
  PyErr_Clear();
  if (overflow > 0) {
    const unsigned long long u = PyLong_AsUnsignedLongLong(value.ptr());
    if (!PyErr_Occurred()) return u;
    PyErr_Clear();
  }
  // Beyond 64 bits: the double it rounds to, infinite past 1.8e308 (10**400 as 1e400 would be).
  const double x = PyLong_AsDouble(value.ptr());
  if (!PyErr_Occurred()) return x;
  PyErr_Clear();
  return overflow > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
}

nlohmann::json convert(const py::handle& value, const std::string& path, int depth) {
  if (depth > max_depth) throw InvalidInput(at(path) + "nested deeper than " + std::to_string(max_depth) + " levels");
  PyObject* v = value.ptr();
  if (v == Py_None) return nullptr;
  if (PyBool_Check(v)) return v == Py_True;  // before int: bool is an int in Python
  if (PyLong_Check(v)) return integer_of(value);
  if (PyFloat_Check(v)) return PyFloat_AsDouble(v);
  if (PyUnicode_Check(v)) return utf8_of(value, path, "");
  if (PyDict_Check(v)) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      if (!PyUnicode_Check(key.ptr()))
        throw InvalidInput(key_path(path, ascii_repr(key)) + ": a key must be a string (this one is of type " +
                           Py_TYPE(key.ptr())->tp_name + ")");
      const std::string name = utf8_of(key, path, "the key ");
      object[name] = convert(item, key_path(path, name), depth + 1);
    }
    return object;
  }
  if (PyList_Check(v) || PyTuple_Check(v)) {
    nlohmann::json array = nlohmann::json::array();
    std::size_t i = 0;
    for (const py::handle item : value) array.push_back(convert(item, item_path(path, i++), depth + 1));
    return array;
  }
  // numpy's scalars: an integer by its __index__, a float by its __float__.
  if (PyIndex_Check(v)) {
    if (PyObject* i = PyNumber_Index(v)) return integer_of(py::reinterpret_steal<py::object>(i));
    PyErr_Clear();
  }
  if (Py_TYPE(v)->tp_as_number && Py_TYPE(v)->tp_as_number->nb_float) {
    const double x = PyFloat_AsDouble(v);
    if (!PyErr_Occurred()) return x;
    PyErr_Clear();
  }
  throw InvalidInput(at(path) + "a value of type " + Py_TYPE(v)->tp_name +
                     " is not JSON (a dict, list, tuple, str, number, bool or None is)");
}

}  // namespace

nlohmann::json json_of(const py::handle& value) { return convert(value, "", 0); }

}  // namespace emit::python
