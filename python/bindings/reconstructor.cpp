/// emit.Contact, emit.CONTACT_DTYPE and emit.Reconstructor: frames -> contacts and pressure
/// images, by any method, calibrated or not (pipeline/pipeline.hpp builds the models).
#include <pybind11/stl.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "calibration.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/limits.hpp"
#include "emit/frame/batch.hpp"
#include "emit/pipeline/pipeline.hpp"

namespace emit::python {

namespace {

/// One row of a frame stack's contacts (CONTACT_DTYPE): Contact's fields and the frame's index.
struct ContactRow {
  std::int64_t frame;
  double x_mm, y_mm, z_mm, nx, ny, nz;
  double area_mm2, pressure_N_per_mm2, peak_pressure_N_per_mm2, force_N;
  double x_std_mm, y_std_mm, pressure_std_N_per_mm2, force_std_N;
  double semi_major_mm, semi_minor_mm, orientation_deg, area_std_mm2, orientation_std_deg;
  std::int32_t element_count;
  std::int64_t id;  ///< the touch's (frame/contact_tracker.hpp), −1 untracked
  double vx_mm_per_s, vy_mm_per_s;
};

ContactRow row_of(std::int64_t frame, const Contact& c) {
  return {frame,
          c.x_mm,
          c.y_mm,
          c.z_mm,
          c.nx,
          c.ny,
          c.nz,
          c.area_mm2,
          c.pressure_N_per_mm2,
          c.peak_pressure_N_per_mm2,
          c.force_N,
          c.x_std_mm,
          c.y_std_mm,
          c.pressure_std_N_per_mm2,
          c.force_std_N,
          c.semi_major_mm,
          c.semi_minor_mm,
          c.orientation_deg,
          c.area_std_mm2,
          c.orientation_std_deg,
          c.element_count,
          c.id,
          c.vx_mm_per_s,
          c.vy_mm_per_s};
}

py::array_t<ContactRow> contact_rows(const std::vector<std::vector<Contact>>& per_frame) {
  std::size_t total = 0;
  for (const std::vector<Contact>& contacts : per_frame) total += contacts.size();
  py::array_t<ContactRow> rows(static_cast<py::ssize_t>(total));
  ContactRow* out = rows.mutable_data();
  for (std::size_t f = 0; f < per_frame.size(); ++f)
    for (const Contact& c : per_frame[f]) *out++ = row_of(static_cast<std::int64_t>(f), c);
  return rows;
}

/// The pipeline and its reconstructor, and the reference. Calls on one object take turns (a
/// Python thread may call while another one's call runs without the GIL); separate objects share
/// nothing and run at once.
class PythonReconstructor {
 public:
  PythonReconstructor(const Sensor& sensor, const PipelineOptions& pipeline_options, const FrameOptions& options,
                      const std::optional<PythonCalibration>& calibration)
      : options_(options),
        electrodes_(electrode_count_of(sensor)),
        adc_(sensor.adc),
        pipeline_(std::make_unique<Pipeline>(sensor, pipeline_options, calibration_of(calibration))),
        reconstructor_(pipeline_->reconstructor(options_)) {}

  Index electrodes() const { return electrodes_; }
  const AdcSpec& adc() const { return adc_; }
  const Pipeline& pipeline() const { return *pipeline_; }
  const Reconstructor& reconstructor() const { return reconstructor_; }
  std::mutex& mutex() { return mutex_; }

  void set_reference(const FrameStack& stack) {
    reference_ = average_reference(stack.frames());
    reconstructor_.set_reference(reference_);
    has_reference_ = true;
  }

  /// A copy of one of the last frame's images, taken while no other thread's call runs.
  Vector copy_of(const Vector& (Reconstructor::*image)() const) {
    const EmitCall call;  // a call in flight holds the mutex without the GIL
    const std::lock_guard lock(mutex_);
    return (reconstructor_.*image)();
  }

  const std::vector<Contact>& process(const FrameView& frame) {
    require_reference();
    return reconstructor_.process(frame);
  }

  /// Every frame's contacts; their pressure images into `pressure` (frames × triangles) if given.
  std::vector<std::vector<Contact>> process_all(const FrameStack& stack, int threads, double* pressure) {
    require_reference();
    // Linear methods always, contact fitting when asked for threads: independent frames
    // (Pipeline::reconstruct_batch fits each frame cold, whatever the thread count).
    if ((is_linear(pipeline_->method()) || threads > 1) && !pressure)
      return pipeline_->reconstruct_batch(options_, reference_,
                                          std::span<const double>(stack.frame(0),
                                                                  stack.count * static_cast<std::size_t>(electrodes_ *
                                                                                                         electrodes_)),
                                          threads);
    std::vector<std::vector<Contact>> contacts(stack.count);
    const Index triangles = reconstructor_.pressure().size();
    for (std::size_t f = 0; f < stack.count; ++f) {
      contacts[f] = reconstructor_.process(stack.view(f));
      if (pressure)
        Eigen::Map<Vector>(pressure + f * static_cast<std::size_t>(triangles), triangles) = reconstructor_.pressure();
    }
    return contacts;
  }

  double cpp_seconds_per_frame(const FrameStack& stack, bool batch, int threads, int repeats) {
    require_reference();
    const std::vector<Frame> frames = stack.frames();
    const auto start = std::chrono::steady_clock::now();
    for (int r = 0; r < repeats; ++r) {
      if (batch) pipeline_->reconstruct_batch(options_, reference_, frames, threads);
      else
        for (const Frame& frame : frames) reconstructor_.process(frame);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return seconds / static_cast<double>(frames.size() * static_cast<std::size_t>(repeats));
  }

 private:
  void require_reference() const {
    if (!has_reference_)
      throw InvalidInput("no reference frame yet: call set_reference(untouched frames) before reconstruct()");
  }

  FrameOptions options_;
  Index electrodes_;
  AdcSpec adc_;                         ///< the sensor's: the range its frames' readings must be in
  std::unique_ptr<Pipeline> pipeline_;  ///< before the reconstructor, which refers to it
  Reconstructor reconstructor_;
  Reference reference_;
  bool has_reference_ = false;
  std::mutex mutex_;
};

py::list contact_list(const std::vector<Contact>& contacts) {
  py::list list;
  for (const Contact& c : contacts) list.append(py::cast(c));
  return list;
}

}  // namespace

void bind_reconstructor(py::module_& m) {
  PYBIND11_NUMPY_DTYPE(ContactRow, frame, x_mm, y_mm, z_mm, nx, ny, nz, area_mm2, pressure_N_per_mm2,
                       peak_pressure_N_per_mm2, force_N, x_std_mm, y_std_mm, pressure_std_N_per_mm2, force_std_N,
                       semi_major_mm, semi_minor_mm, orientation_deg, area_std_mm2, orientation_std_deg, element_count,
                       id, vx_mm_per_s, vy_mm_per_s);
  m.attr("CONTACT_DTYPE") = py::dtype::of<ContactRow>();

  py::class_<Contact>(m, "Contact", R"(A contact: where the sheet is pressed and how hard.

The point (x_mm, y_mm, z_mm) on the sheet and its outward normal (nx, ny, nz); the area [mm^2];
mean and peak pressure [N/mm^2]; force [N]; 1-sigma uncertainties (contact fitting; 0 where
not estimated); the outline's ellipse of the same second moments, semi-axes [mm] and the major
axis's angle from x [deg] (the `shapes` method fits it, with 1-sigma of area and angle); the
outline's polygon, outline_mm, a (K, 2) array (not in CONTACT_DTYPE). Read-only.)")
      .def_readonly("x_mm", &Contact::x_mm)
      .def_readonly("y_mm", &Contact::y_mm)
      .def_readonly("z_mm", &Contact::z_mm)
      .def_readonly("nx", &Contact::nx)
      .def_readonly("ny", &Contact::ny)
      .def_readonly("nz", &Contact::nz)
      .def_readonly("area_mm2", &Contact::area_mm2)
      .def_readonly("pressure_N_per_mm2", &Contact::pressure_N_per_mm2)
      .def_readonly("peak_pressure_N_per_mm2", &Contact::peak_pressure_N_per_mm2)
      .def_readonly("force_N", &Contact::force_N)
      .def_readonly("x_std_mm", &Contact::x_std_mm)
      .def_readonly("y_std_mm", &Contact::y_std_mm)
      .def_readonly("pressure_std_N_per_mm2", &Contact::pressure_std_N_per_mm2)
      .def_readonly("force_std_N", &Contact::force_std_N)
      .def_readonly("semi_major_mm", &Contact::semi_major_mm)
      .def_readonly("semi_minor_mm", &Contact::semi_minor_mm)
      .def_readonly("orientation_deg", &Contact::orientation_deg)
      .def_readonly("area_std_mm2", &Contact::area_std_mm2)
      .def_readonly("orientation_std_deg", &Contact::orientation_std_deg)
      .def_readonly("element_count", &Contact::element_count)
      .def_readonly("id", &Contact::id,
                    "The touch's id, the same while it lasts (a Tracker's, or LiveStream's); -1 untracked.")
      .def_property_readonly(
          "phase", [](const Contact& c) { return std::string(touch_phase_name(c.phase)); },
          "'down' (the touch's first frame), 'move', 'up' (ended: its last state), or 'none' (untracked).")
      .def_readonly("vx_mm_per_s", &Contact::vx_mm_per_s, "Velocity along the chart's first axis [mm/s] (tracked).")
      .def_readonly("vy_mm_per_s", &Contact::vy_mm_per_s, "Along its second [mm/s].")
      .def_property_readonly(
          "outline_mm",
          [](const Contact& c) {
            py::array_t<double> vertices({static_cast<py::ssize_t>(c.outline.size), py::ssize_t{2}});
            auto v = vertices.mutable_unchecked<2>();
            for (int k = 0; k < c.outline.size; ++k) {
              const Vector2 p = c.outline.vertex_mm(k);
              v(k, 0) = p.x();
              v(k, 1) = p.y();
            }
            return vertices;
          },
          "The outline as a polygon, a (K, 2) array of its vertices [mm] in the sheet's chart (x, y on a flat "
          "sheet), counter-clockwise, the last joined to the first: a linear method's region's level line at "
          "its threshold, contact fitting's disc's, the `shapes` method's ellipse's (K = 0: none).")
      .def(
          "as_dict",
          [](const py::object& self) {
            py::dict fields;
            for (const py::handle name : py::dtype::of<ContactRow>().attr("names"))
              if (name.cast<std::string>() != "frame") fields[name] = self.attr(name);
            return fields;
          },
          "Its fields as a dict (the names of CONTACT_DTYPE but 'frame').")
      .def("__repr__", [](const Contact& c) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "Contact(x_mm=%.2f, y_mm=%.2f, force_N=%.3f, pressure_N_per_mm2=%.4f, area_mm2=%.1f)", c.x_mm,
                      c.y_mm, c.force_N, c.pressure_N_per_mm2, c.area_mm2);
        return std::string(text);
      });

  py::class_<PythonReconstructor>(m, "Reconstructor", R"(Frames -> contacts and pressure images, by one method.

Building it builds the method's models (mesh, Jacobian, operator; for 'fit' the contact fitter):
seconds, once; with cache_dir the linear operator is kept on disk for the next time. Then
set_reference(untouched frames), and reconstruct(frames) per frame or per stack.)")
      .def(py::init([](const Sensor& sensor, const std::string& method,
                       const std::optional<PythonCalibration>& calibration, const std::string& cache_dir,
                       double lambda2, double threshold_fraction, double min_contact_area_mm2, bool track_contacts,
                       double contact_radius_mm) {
             PipelineOptions pipeline;
             pipeline.method = parse_method(method);
             pipeline.lambda2 = lambda2;
             pipeline.cache_dir = cache_dir;
             FrameOptions options;
             options.threshold_fraction = threshold_fraction;
             options.min_contact_area_mm2 = min_contact_area_mm2;
             options.track_contacts = track_contacts;
             options.contact_radius_mm = contact_radius_mm;
             pipeline.validate();  // the library's rules, as the CLI's options say them, before any work
             check_frame_options(pipeline.method, options);
             const EmitCall call;
             return std::make_unique<PythonReconstructor>(sensor, pipeline, options, calibration);
           }),
           py::arg("sensor"), py::arg("method") = "fit", py::arg("calibration") = py::none(), py::kw_only(),
           py::arg("cache_dir") = "", py::arg("lambda2") = 0.0, py::arg("threshold_fraction") = 0.5,
           py::arg("min_contact_area_mm2") = 0.0, py::arg("track_contacts") = true, py::arg("contact_radius_mm") = 0.0,
           "method: one of emit.methods(). calibration: an emit.Calibration of the method's kind, or None. "
           "contact_radius_mm: for 'fit' and 'shapes', the indenter's radius declared (0: not): every contact's "
           "area held at pi R^2.")
      .def(
          "set_reference",
          [](PythonReconstructor& self, const py::handle& frames) {
            const FrameStack stack = frame_stack(frames, self.electrodes(), self.adc(), "reference", true);
            const EmitCall call;
            const std::lock_guard lock(self.mutex());
            self.set_reference(stack);
          },
          py::arg("frames"),
          "The untouched sheet: one frame (N, N), or (K, N, N) averaged (outliers left out; a reading NaN or inf "
          "is left out of its mean, and masked in every frame if no frame holds it).")
      .def(
          "reconstruct",
          [](PythonReconstructor& self, const py::handle& frames, int threads, bool pressure) -> py::object {
            limits::check_thread_count("threads", threads);
            const FrameStack stack = frame_stack(frames, self.electrodes(), self.adc(), "frames", true);
            if (stack.single) {
              std::vector<Contact> found;
              Vector image;
              {
                const EmitCall call;
                const std::lock_guard lock(self.mutex());
                found = self.process(stack.view(0));
                if (pressure) image = self.reconstructor().pressure();
              }
              if (!pressure) return contact_list(found);
              return py::make_tuple(contact_list(found), to_numpy(std::move(image)));
            }
            const py::ssize_t triangles = self.pipeline().model().mesh.triangle_count();
            std::optional<py::array_t<double>> images;
            if (pressure) images.emplace(std::vector<py::ssize_t>{static_cast<py::ssize_t>(stack.count), triangles});
            double* images_out = images ? images->mutable_data() : nullptr;
            std::vector<std::vector<Contact>> contacts;
            {
              const EmitCall call;
              const std::lock_guard lock(self.mutex());
              contacts = self.process_all(stack, threads, images_out);
            }
            py::array_t<ContactRow> rows = contact_rows(contacts);
            if (!pressure) return rows;
            return py::make_tuple(rows, *images);
          },
          py::arg("frames"), py::kw_only(), py::arg("threads") = 1, py::arg("pressure") = false,
          R"(Contacts of one frame or of a stack, against the reference.

frames (N, N): a list of Contact, strongest first. frames (F, N, N): one structured array of every
frame's contacts (CONTACT_DTYPE; its 'frame' field says whose), the linear methods split across
`threads`; contact fitting goes in order, tracking from frame to frame, or with threads > 1 fits
each frame on its own, split across them (the same contacts for any count). pressure=True also returns
the pressure image per triangle of `mesh` [N/mm^2]: (triangles,) or (F, triangles). A reading that
is NaN or inf (a board's dropped reading) or at the ADC's top code (clipped) is masked in its frame,
as `emit reconstruct` masks it (docs/physics.md, "Bad readings").)")
      .def(
          "cpp_seconds_per_frame",
          [](PythonReconstructor& self, const py::handle& frames, bool batch, int threads, int repeats) {
            limits::check_thread_count("threads", threads);
            const FrameStack stack = frame_stack(frames, self.electrodes(), self.adc(), "frames");
            if (repeats < 1) throw InvalidInput("repeats must be at least 1, got " + std::to_string(repeats));
            const EmitCall call;
            const std::lock_guard lock(self.mutex());
            return self.cpp_seconds_per_frame(stack, batch, threads, repeats);
          },
          py::arg("frames"), py::kw_only(), py::arg("batch") = false, py::arg("threads") = 1, py::arg("repeats") = 1,
          R"(The benchmarks' baseline: seconds per frame of the same frames in C++ alone, no Python per frame.

batch=False: Reconstructor::process on each frame in turn, as reconstruct(frame) calls it.
batch=True: Pipeline::reconstruct_batch on the frames as a std::vector<Frame>, as `emit
reconstruct` runs the linear methods (contact fitting: each frame fitted on its own).
bench/python_bench.py sets reconstruct() against it.)")
      .def_property_readonly(
          "pressure", [](PythonReconstructor& self) { return to_numpy(self.copy_of(&Reconstructor::pressure)); },
          "The last frame's pressure per triangle of `mesh` [N/mm^2], 0 below the threshold.")
      .def_property_readonly(
          "image", [](PythonReconstructor& self) { return to_numpy(self.copy_of(&Reconstructor::image)); },
          "The last frame's linear image (eq. 7) per triangle [V] (0 while contact fitting tracks).")
      .def_property_readonly(
          "mesh", [](const PythonReconstructor& self) -> const Mesh& { return self.pipeline().model().mesh; },
          py::return_value_policy::reference_internal, "The reconstruction's mesh (the images are per triangle of it).")
      .def_property_readonly("method",
                             [](const PythonReconstructor& self) { return method_name(self.pipeline().method()); })
      .def_property_readonly("calibrated", [](const PythonReconstructor& self) { return self.pipeline().calibrated(); })
      .def_property_readonly("electrode_count", &PythonReconstructor::electrodes)
      .def_property_readonly(
          "fit_rms_misfit_mV",
          [](const PythonReconstructor& self) -> std::optional<double> {
            const FitResult* fit = self.reconstructor().fit_result();
            if (!fit) return std::nullopt;
            return 1e3 * fit->rms_misfit_V;
          },
          "Contact fitting: the last frame's rms misfit [mV]; None for a linear method.")
      .def("__repr__", [](const PythonReconstructor& self) {
        return "<emit.Reconstructor " + std::string(method_name(self.pipeline().method())) +
               (self.pipeline().calibrated() ? ", calibrated, " : ", uncalibrated, ") +
               std::to_string(self.pipeline().model().mesh.triangle_count()) + " triangles>";
      });
}

}  // namespace emit::python
