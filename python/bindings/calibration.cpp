/// emit.Calibration (load, save) and emit.calibrate (from presses of known place and force).
#include "calibration.hpp"

#include <pybind11/stl.h>

#include <string>
#include <variant>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/pipeline/press_calibration.hpp"

namespace emit::python {

void bind_calibration(py::module_& m) {
  py::class_<PythonCalibration>(m, "Calibration",
                                R"(A method's calibration: eq. 8's a1, a2, a3 for the linear methods, or
the contact law and sheet as contact fitting sees them. Made by emit.calibrate or Calibration.load.)")
      .def_static(
          "load",
          [](const std::string& path) {
            return PythonCalibration{load_calibration(path), 0, std::nullopt, std::nullopt};
          },
          py::arg("path"),
          "Reads a calibration file (as `emit calibrate` writes). Raises InvalidInput naming the key, IoError.")
      .def(
          "save",
          [](const PythonCalibration& calibration, const std::string& path) {
            write_calibration(path, calibration.calibration);
          },
          py::arg("path"),
          "Writes it as JSON, replacing `path` only once the whole file is written (a device or FIFO is written "
          "into directly, never replaced). Raises IoError naming it.")
      .def_property_readonly(
          "kind",
          [](const PythonCalibration& c) {
            return std::holds_alternative<LinearCalibration>(c.calibration) ? "linear" : "fit";
          },
          "'linear' (for paper, noser, laplacian) or 'fit' (for contact fitting).")
      .def_property_readonly(
          "force_law",
          [](const PythonCalibration& c) -> std::optional<py::dict> {
            const auto* linear = std::get_if<LinearCalibration>(&c.calibration);
            if (!linear || !linear->force_law) return std::nullopt;
            const ImageForceLaw& f = *linear->force_law;
            py::dict law;
            law["b1_V_mm2"] = f.b1_V_mm2;
            law["b2"] = f.b2;
            law["b3"] = f.b3;
            law["log_std"] = f.log_std;
            law["indenter_radius_mm"] = f.indenter_radius_mm;
            return law;
          },
          "A linear calibration's force law, F = (b1/I + b2)^b3 on the image's integral I [V mm^2] (its keys as "
          "in the file); None for contact fitting, or a file written before it (forces are then the image's).")
      .def_readonly("presses", &PythonCalibration::presses, "Single presses it was fitted on (0: read from a file).")
      .def_readonly("rms_N_per_mm2", &PythonCalibration::rms_N_per_mm2,
                    "The calibrated pressure's rms error over those presses (None: read from a file).")
      .def_readonly("max_abs_N_per_mm2", &PythonCalibration::max_abs_N_per_mm2)
      .def("__repr__", [](const PythonCalibration& c) {
        std::string text = std::string("<emit.Calibration for ") + calibration_kind(c.calibration);
        if (c.rms_N_per_mm2)
          text += ", " + std::to_string(c.presses) + " presses, rms " + std::to_string(*c.rms_N_per_mm2) + " N/mm^2";
        return text + ">";
      });

  m.def(
      "calibrate",
      [](const Sensor& sensor, const py::handle& reference, const py::handle& frames, const PressSequence& presses,
         const std::string& method, double lambda2, double threshold_fraction, bool fit_sheet,
         const std::string& cache_dir) {
        const Index n = electrode_count_of(sensor);
        const FrameStack references = frame_stack(reference, n, sensor.adc, "reference");
        const FrameStack stack = frame_stack(frames, n, sensor.adc, "frames");
        PressCalibrationOptions options;
        options.method = parse_method(method);
        options.lambda2 = lambda2;
        options.threshold_fraction = threshold_fraction;
        options.fit_sheet = fit_sheet;
        options.cache_dir = cache_dir;
        const EmitCall call;
        const PressCalibrationResult result =
            calibrate_from_presses(sensor, options, average_reference(references.frames()), stack.frames(), presses);
        return PythonCalibration{result.calibration, result.presses, result.rms_N_per_mm2, result.max_abs_N_per_mm2};
      },
      py::arg("sensor"), py::arg("reference"), py::arg("frames"), py::arg("presses"), py::kw_only(),
      py::arg("method") = "fit", py::arg("lambda2") = 0.0, py::arg("threshold_fraction") = 0.5,
      py::arg("fit_sheet") = true, py::arg("cache_dir") = "",
      R"(Calibrates `method` from presses of known place and force (`emit calibrate`).

reference: untouched frames, (N, N) or (K, N, N), averaged. frames: (F, N, N), one per entry of
presses (a list of lists of Press); frames of one press each are calibrated on. Returns a Calibration.)");
}

}  // namespace emit::python
