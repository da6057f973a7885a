/// The compiled half of the Python package `emit` (python/emit/__init__.py re-exports it).
#include "bindings.hpp"
#include "emit/core/version.hpp"

PYBIND11_MODULE(_emit, m) {
  m.doc() = "emit's C++ library for Python: sensors, meshes, the twin, reconstruction, calibration, live sources.";
  m.attr("__version__") = emit::version();
  emit::python::bind_errors(m);
  emit::python::bind_sensor(m);
  emit::python::bind_twin(m);
  emit::python::bind_calibration(m);
  emit::python::bind_reconstructor(m);
  emit::python::bind_tracker(m);
  emit::python::bind_live(m);
}
