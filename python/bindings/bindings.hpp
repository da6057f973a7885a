#pragma once
/// \file bindings.hpp
/// The Python module's parts, one file each: errors, the sensor and its mesh, the twin, the
/// reconstructor, calibration, live sources. module.cpp calls them in this order (a part may use
/// the classes of those before it).
#include <pybind11/pybind11.h>

#include "emit/core/threads.hpp"

namespace emit::python {

namespace py = pybind11;

/// Around every call into emit's computations: the GIL released, so that other Python threads
/// run meanwhile, and the BLAS at emit's thread count (the CLI's: one), numpy's own count coming
/// back after (core/threads.hpp).
struct EmitCall {
  py::gil_scoped_release release;
  EmitBlasThreads blas;
};

void bind_errors(py::module_& m);         ///< errors.cpp
void bind_sensor(py::module_& m);         ///< sensor.cpp: Sensor, Mesh, Press, load_frames, methods
void bind_twin(py::module_& m);           ///< twin.cpp: Twin, simulate
void bind_calibration(py::module_& m);    ///< calibration.cpp: Calibration, calibrate
void bind_reconstructor(py::module_& m);  ///< reconstructor.cpp: Contact, CONTACT_DTYPE, Reconstructor
void bind_tracker(py::module_& m);        ///< tracker.cpp: Tracker
void bind_live(py::module_& m);           ///< live.cpp: LiveStream

}  // namespace emit::python
