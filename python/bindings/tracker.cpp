#include <pybind11/stl.h>

#include <optional>
#include <vector>

#include "bindings.hpp"
#include "emit/frame/contact_tracker.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit::python {

namespace {

py::list contact_list(const std::vector<Contact>& contacts) {
  py::list list;
  for (const Contact& c : contacts) list.append(py::cast(c));
  return list;
}

}  // namespace

void bind_tracker(py::module_& m) {
  py::class_<ContactTracker>(m, "Tracker", R"(Touches over time, from frames' contacts: the tracker `emit live` runs.

Each update(contacts, time_s) gives the frame's contacts again with `id` (the same while the touch
lasts, never reused), `phase` ('down' on its first frame, then 'move') and velocity
(vx_mm_per_s, vy_mm_per_s); `ended` then holds the touches that ended, each its last state with
phase 'up'. The rule (least-cost pairing on predicted place and force, gated; merges, splits and
coasting) is docs/physics.md's "Touch over time". For recorded frames: reconstruct each frame,
then update with its time (e.g. its index / frames per second).)")
      .def(py::init([](const std::optional<Sensor>& sensor, double gate_mm, int coast_frames, bool filter,
                       double force_weight, int max_contacts) {
             TrackerOptions options;
             options.gate_mm = gate_mm;
             options.coast_frames = coast_frames;
             options.filter = filter;
             options.force_weight = force_weight;
             return std::make_unique<ContactTracker>(options, max_contacts, sensor ? sensor->shape : Shape{});
           }),
           py::arg("sensor") = py::none(), py::kw_only(), py::arg("gate_mm") = 15.0, py::arg("coast_frames") = 1,
           py::arg("filter") = false, py::arg("force_weight") = 0.25, py::arg("max_contacts") = 64)
      .def(
          "update",
          [](ContactTracker& self, const std::vector<Contact>& contacts, double time_s) {
            return contact_list(self.update(contacts, time_s));
          },
          py::arg("contacts"), py::arg("time_s"),
          "This frame's contacts with their touches' id, phase and velocity (and filtered place with filter=True).")
      .def_property_readonly(
          "ended", [](const ContactTracker& self) { return contact_list(self.ended()); },
          "The touches that ended at the last update: each its last state, phase 'up'.")
      .def("reset", &ContactTracker::reset, "Forget every touch (they end at the next update); ids go on.")
      .def_property_readonly("live_count", &ContactTracker::live_count, "Touches alive (seen or coasting).");
}

}  // namespace emit::python
