#pragma once
/// \file arrays.hpp
/// numpy arrays in and out of the bindings: frames read in place where their layout allows
/// (C-ordered float64; anything else is converted once, as numpy's own functions do), checked for
/// shape, finiteness and the ADC's range with one-line messages; results handed to numpy without
/// a copy, the array owning the C++ buffer.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit::python {

namespace py = pybind11;

/// A C-ordered float64 array: the caller's own when it already is one, otherwise converted.
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// Frames as the bindings take them: (N, N) or (frames, N, N), every value finite.
struct FrameStack {
  DoubleArray array;   ///< holds the values (the caller's array when it was C-ordered float64)
  bool single = true;  ///< given as one (N, N) frame
  std::size_t count = 0;
  Index electrodes = 0;
  const double* frame(std::size_t f) const {
    return array.data() + f * static_cast<std::size_t>(electrodes * electrodes);
  }
  FrameView view(std::size_t f) const { return {frame(f), electrodes, electrodes}; }
  /// Copies, for the library calls that take std::vector<Frame> (averaging, calibration).
  std::vector<Frame> frames() const;
};

/// \throw InvalidInput "<what>: expected an (N, N) or (frames, N, N) array with N = 16, got shape (3, 4)",
/// or naming the first value that is not a finite number (unless `readings_may_be_missing`: then
/// NaN and inf are a board's lost readings, which the reconstructor masks), or the first reading the sensor's ADC
/// cannot give, as the commands say it of a frames file ("frames: frame 2: ground 0, sense 5
/// reads 1200 V, outside the ADC's 0 to 3.3 V (sensor "adc")"; acquire/electrode_health.hpp).
FrameStack frame_stack(const py::handle& frames, Index electrodes, const AdcSpec& adc, const std::string& what,
                       bool readings_may_be_missing = false);

/// The values of `vector`, moved into a numpy array that owns them (no copy).
py::array_t<double> to_numpy(Vector&& vector);
/// A frame as an (N, N) array, moved (no copy).
py::array_t<double> to_numpy(Frame&& frame);

/// A read-only array over `data` kept alive by `owner` (a Python object holding the C++ one).
template <typename T>
py::array_t<T> view_of(const T* data, std::vector<py::ssize_t> shape, const py::handle& owner) {
  py::array_t<T> array(std::move(shape), data, owner);
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

}  // namespace emit::python
