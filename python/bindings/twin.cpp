/// emit.Twin (the digital twin: presses -> frames, on its own finer mesh) and emit.simulate.
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "emit/core/limits.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/twin/twin.hpp"

namespace emit::python {

namespace {

/// The frames of each frame's presses, as one (frames, N, N) array.
/// As many frames as one call may make (core/limits.hpp), the CLI's bound on `emit simulate`.
void check_frames_held(const PressSequence& presses, int electrodes) {
  limits::check_frames_held("presses", static_cast<double>(presses.size()), electrodes, "simulate them in parts");
}

py::array_t<double> frames_of(Twin& twin, const PressSequence& presses) {
  const py::ssize_t n = twin.sensor().electrode_count();
  check_frames_held(presses, static_cast<int>(n));
  py::array_t<double> stack({static_cast<py::ssize_t>(presses.size()), n, n});
  double* out = stack.mutable_data();
  const EmitCall call;
  for (const std::vector<Press>& frame_presses : presses) {
    const Frame frame = twin.frame(frame_presses);
    out = std::copy(frame.data(), frame.data() + frame.size(), out);
  }
  return stack;
}

TwinOptions twin_options(int mesh_seed, std::uint64_t noise_seed, bool adc) {
  TwinOptions options;
  options.mesh_seed = mesh_seed;
  options.noise_seed = noise_seed;
  options.adc = adc;
  return options;
}

}  // namespace

void bind_twin(py::module_& m) {
  py::class_<Twin>(m, "Twin", R"(The digital twin of a sensor: frames of presses as its board would read them.

It meshes the sheet finer than the reconstruction does, another mesh (no inverse crime), and
applies the sensor's ADC (quantisation, noise, clipping) unless adc=False.)")
      .def(py::init([](const Sensor& sensor, int mesh_seed, std::uint64_t noise_seed, bool adc) {
             const EmitCall call;
             return std::make_unique<Twin>(sensor, twin_options(mesh_seed, noise_seed, adc));
           }),
           py::arg("sensor"), py::kw_only(), py::arg("mesh_seed") = 1, py::arg("noise_seed") = 1, py::arg("adc") = true)
      .def(
          "frame",
          [](Twin& twin, const std::vector<Press>& presses) {
            Frame frame;
            {
              const EmitCall call;
              frame = twin.frame(presses);
            }
            return to_numpy(std::move(frame));
          },
          py::arg("presses"), "One frame (N, N) of these presses (a list; empty: untouched), with fresh noise.")
      .def(
          "frames", [](Twin& twin, const PressSequence& presses) { return frames_of(twin, presses); },
          py::arg("presses"), "A (frames, N, N) array: one frame per list of presses.")
      .def(
          "exact_frame",
          [](Twin& twin, const std::vector<Press>& presses) {
            Frame frame;
            {
              const EmitCall call;
              frame = twin.exact_frame(presses);
            }
            return to_numpy(std::move(frame));
          },
          py::arg("presses"), "The noise-free frame of the physics, before the ADC.")
      .def_property_readonly("mesh", &Twin::mesh, py::return_value_policy::reference_internal,
                             "The twin's own (finer) mesh.")
      .def_property_readonly("sensor", &Twin::sensor, py::return_value_policy::reference_internal);

  m.def(
      "simulate",
      [](const Sensor& sensor, const PressSequence& presses, int mesh_seed, std::uint64_t noise_seed, bool adc) {
        check_frames_held(presses, electrode_count_of(sensor));  // before the twin is meshed
        std::unique_ptr<Twin> twin;
        {
          const EmitCall call;
          twin = std::make_unique<Twin>(sensor, twin_options(mesh_seed, noise_seed, adc));
        }
        return frames_of(*twin, presses);
      },
      py::arg("sensor"), py::arg("presses"), py::kw_only(), py::arg("mesh_seed") = 1, py::arg("noise_seed") = 1,
      py::arg("adc") = true,
      "Frames of presses from the twin: presses is a list with one list of Press per frame (an empty\n"
      "list: an untouched frame). Returns a (frames, N, N) float64 array [V].");
}

}  // namespace emit::python
