/// emit.LiveStream: a live source ("sim", "file:PATH", "serial:PATH[@BAUD]") as a Python iterator
/// of (frame, contacts), through the live loop (live/live_loop.hpp): the baseline captured from
/// the first frames, followed while nothing touches, each later frame reconstructed.
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "calibration.hpp"
#include "emit/live/live_loop.hpp"
#include "emit/live/open_source.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit::python {

namespace {

class LiveStream {
 public:
  LiveStream(const Sensor& sensor, const std::string& spec, const PipelineOptions& pipeline_options,
             const std::optional<PythonCalibration>& calibration, const SourceOptions& source_options,
             const LiveOptions& options)
      : max_frames_(options.max_frames) {
    pipeline_ = std::make_unique<Pipeline>(sensor, pipeline_options, calibration_of(calibration));
    source_ = open_source(spec, sensor, source_options);
    loop_ = std::make_unique<LiveLoop>(*source_, *pipeline_, options);
  }

  /// The next reconstructed frame's contacts; null at the source's end or after max_frames.
  /// \throw IoError when the source fails (finished() is its normal end only: frame_source.hpp).
  /// Waits for frames without the GIL, taking it back between them to let Ctrl-C through.
  const std::vector<Contact>* next() {
    while (true) {
      if (source_->finished() || (max_frames_ > 0 && loop_->stats().frames >= max_frames_)) return nullptr;
      const std::vector<Contact>* contacts = nullptr;
      {
        const EmitCall call;
        contacts = loop_->step();
      }
      if (contacts) return contacts;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
  }

  const LiveLoop& loop() const { return *loop_; }
  const Pipeline& pipeline() const { return *pipeline_; }
  std::string description() const { return source_->description(); }

 private:
  std::uint64_t max_frames_;
  std::unique_ptr<Pipeline> pipeline_;
  std::unique_ptr<FrameSource> source_;
  std::unique_ptr<LiveLoop> loop_;  ///< last: it refers to the source and the pipeline
};

}  // namespace

void bind_live(py::module_& m) {
  py::class_<LiveStream>(m, "LiveStream", R"(A live source as an iterator of (frame, contacts), as `emit live` reads it.

source: "sim" (a finger moving over the twin's sheet), "sim:random", "sim:fixed" (at the middle), "sim:fixed:X,Y[,F]",
"file:PATH" (a recording) or "serial:PATH[@BAUD]" (the board). The first capture_frames frames
are averaged into the baseline and not yielded; each later frame comes as its (N, N) volts and its
list of Contact. A recording ends the iteration at its end; max_frames > 0 ends it after that many.
A source that fails raises emit.IoError with its message (a recording cut mid-packet or corrupt,
after the frames before it; the twin's error; a serial port gone longer than reconnect_s seconds:
a pulled cable put back within them is no failure): a failure never ends the iteration quietly.)")
      .def(py::init([](const std::string& source, const std::optional<Sensor>& sensor, const std::string& method,
                       const std::optional<PythonCalibration>& calibration, double frames_per_s, std::uint64_t seed,
                       bool loop, int capture_frames, std::uint64_t max_frames, const std::string& cache_dir,
                       double reconnect_s) {
             PipelineOptions pipeline;
             pipeline.method = parse_method(method);
             pipeline.cache_dir = cache_dir;
             SourceOptions source_options;
             source_options.frames_per_s = frames_per_s;
             source_options.seed = seed;
             source_options.loop = loop;
             source_options.reconnect_s = reconnect_s;
             LiveOptions options;
             options.reference.capture_frames = capture_frames;
             options.max_frames = max_frames;
             options.poll = std::chrono::milliseconds(50);
             const EmitCall call;
             return std::make_unique<LiveStream>(sensor ? *sensor : default_sensor(), source, pipeline, calibration,
                                                 source_options, options);
           }),
           py::arg("source"), py::arg("sensor") = py::none(), py::arg("method") = "paper",
           py::arg("calibration") = py::none(), py::kw_only(), py::arg("frames_per_s") = 50.0, py::arg("seed") = 1,
           py::arg("loop") = false, py::arg("capture_frames") = 10, py::arg("max_frames") = 0,
           py::arg("cache_dir") = "", py::arg("reconnect_s") = 30.0)
      .def("__iter__", [](py::object self) { return self; })
      .def("__next__",
           [](LiveStream& self) {
             const std::vector<Contact>* contacts = self.next();
             if (!contacts) throw py::stop_iteration();
             py::list list;
             for (const Contact& c : *contacts) list.append(py::cast(c));
             return py::make_tuple(to_numpy(Frame(self.loop().last_frame().volts)), list);
           })
      .def_property_readonly(
          "sequence", [](const LiveStream& self) { return self.loop().last_frame().sequence; },
          "The source's number of the last frame.")
      .def_property_readonly(
          "ended",
          [](const LiveStream& self) {
            py::list list;
            for (const Contact& c : self.loop().tracker().ended()) list.append(py::cast(c));
            return list;
          },
          "The touches that ended with the last frame: each its last state, phase 'up' (the contacts carry "
          "their touches' id, phase and velocity).")
      .def_property_readonly(
          "board_time_s", [](const LiveStream& self) { return self.loop().last_frame().board_time_s; },
          "When the board took the last frame [s], on the board's clock.")
      .def_property_readonly(
          "host_time_s",
          [](const LiveStream& self) { return 1e-9 * static_cast<double>(self.loop().last_host_time_ns()); },
          "When the last frame reached this computer [s since the Unix epoch, the system clock: time.time()'s].")
      .def_property_readonly(
          "pressure", [](const LiveStream& self) { return to_numpy(Vector(self.loop().reconstructor().pressure())); },
          "The last frame's pressure per triangle of `mesh` [N/mm^2].")
      .def_property_readonly(
          "mesh", [](const LiveStream& self) -> const Mesh& { return self.pipeline().model().mesh; },
          py::return_value_policy::reference_internal)
      .def_property_readonly(
          "frames_missed", [](const LiveStream& self) { return self.loop().stats().frames_missed; },
          "Frames the source numbered but never handed out.")
      .def_property_readonly("description", &LiveStream::description);
}

}  // namespace emit::python
