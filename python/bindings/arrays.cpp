#include "arrays.hpp"

#include <cmath>

#include "emit/acquire/electrode_health.hpp"
#include "emit/core/errors.hpp"

namespace emit::python {

namespace {

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) text += (d ? ", " : "") + std::to_string(array.shape(d));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

}  // namespace

FrameStack frame_stack(const py::handle& frames, Index electrodes, const AdcSpec& adc, const std::string& what,
                       bool readings_may_be_missing) {
  const py::array given = py::array::ensure(frames);
  if (!given) throw InvalidInput(what + ": expected a numpy array (or a nested list) of numbers");
  const py::ssize_t n = electrodes;
  const bool single = given.ndim() == 2;
  const bool shaped = (single && given.shape(0) == n && given.shape(1) == n) ||
                      (given.ndim() == 3 && given.shape(1) == n && given.shape(2) == n);
  if (!shaped)
    throw InvalidInput(what + ": expected an (N, N) or (frames, N, N) array with N = " + std::to_string(n) +
                       ", got shape " + shape_text(given));
  const char kind = given.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw InvalidInput(what + ": expected numbers (float64), got dtype " + py::str(given.dtype()).cast<std::string>());
  FrameStack stack{DoubleArray::ensure(given), single, single ? 1 : static_cast<std::size_t>(given.shape(0)),
                   electrodes};
  if (!stack.array) throw InvalidInput(what + ": could not be read as float64");
  const auto per_frame = static_cast<std::size_t>(n * n);
  const double* values = stack.array.data();
  for (std::size_t i = 0; i < stack.count * per_frame && !readings_may_be_missing; ++i)
    if (!std::isfinite(values[i])) {
      const std::size_t f = i / per_frame, l = i % per_frame / static_cast<std::size_t>(n),
                        m = i % static_cast<std::size_t>(n);
      throw InvalidInput(what + ": " + (single ? "" : "frame " + std::to_string(f) + ", ") + "value [" +
                         std::to_string(l) + ", " + std::to_string(m) + "] is not a finite number (" +
                         std::to_string(values[i]) + ")");
    }
  // The readings' range as the commands check a frames file's (acquire/electrode_health.hpp).
  for (std::size_t f = 0; f < stack.count; ++f)
    if (const std::string problem = reading_out_of_range(stack.view(f), adc); !problem.empty())
      throw InvalidInput(what + ": " + (single ? "" : "frame " + std::to_string(f) + ": ") + problem);
  return stack;
}

std::vector<Frame> FrameStack::frames() const {
  std::vector<Frame> copies;
  copies.reserve(count);
  for (std::size_t f = 0; f < count; ++f) copies.emplace_back(view(f));
  return copies;
}

py::array_t<double> to_numpy(Vector&& vector) {
  auto* owned = new Vector(std::move(vector));
  const py::capsule free_when_done(owned, [](void* p) { delete static_cast<Vector*>(p); });
  return py::array_t<double>(owned->size(), owned->data(), free_when_done);
}

py::array_t<double> to_numpy(Frame&& frame) {
  auto* owned = new Frame(std::move(frame));
  const py::capsule free_when_done(owned, [](void* p) { delete static_cast<Frame*>(p); });
  return py::array_t<double>({owned->rows(), owned->cols()}, owned->data(), free_when_done);
}

}  // namespace emit::python
