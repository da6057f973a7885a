/// emit.Sensor (from a file, a dict, or the built-in one), emit.Mesh (numpy views of a mesh),
/// emit.Press, emit.load_frames and emit.methods.
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "emit/core/errors.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/model/method.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/sensor/press.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "json_value.hpp"

namespace emit::python {

namespace {

py::object python_of(const nlohmann::json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

}  // namespace

void bind_sensor(py::module_& m) {
  py::class_<Sensor>(m, "Sensor", R"(A tactile sensor: its sheet's shape, electrodes, materials and mesh size.

Made by Sensor.load(path) (a sensor file, README "Sensor description"), Sensor.from_dict(d) (the
same keys as a dict) or Sensor.default() (the paper's 60 x 60 mm sheet, 16 electrodes).)")
      .def_static(
          "load", [](const std::string& path) { return load_sheet_sensor(path); }, py::arg("path"),
          "Reads a sensor file (JSON). Raises InvalidInput naming the key that is wrong, IoError if unreadable.")
      .def_static(
          "from_dict",
          [](const py::dict& description, const std::string& base_dir) {
            nlohmann::json j;
            try {
              j = json_of(description);
            } catch (const InvalidInput& e) {
              throw InvalidInput(std::string("sensor dict: ") + e.what());
            }
            return with_sheet_surface(parse_sensor(j, "sensor dict", base_dir));
          },
          py::arg("description"), py::arg("base_dir") = ".",
          "A sensor from a dict with a sensor file's keys; a mesh or CAD file is found relative to base_dir.\n"
          "Raises InvalidInput naming an unknown or wrong key (a value NaN, infinite or beyond a double,\n"
          "text that is not Unicode, a value of no JSON kind), as Sensor.load names a file's.")
      .def_static("default", &default_sensor, "The built-in sensor: the paper's 60 x 60 mm sheet, 16 electrodes.")
      .def(
          "to_dict", [](const Sensor& sensor) { return python_of(sensor_to_json(sensor)); },
          "The sensor as a dict of a sensor file's keys (electrodes listed explicitly).")
      .def_property_readonly("name", [](const Sensor& sensor) { return sensor.name; })
      .def_property_readonly(
          "electrode_count", [](const Sensor& sensor) { return electrode_count_of(sensor); }, "N: frames are N x N.")
      .def_property_readonly("drive_voltage_V", [](const Sensor& sensor) { return sensor.drive_voltage_V; })
      .def(
          "mesh",
          [](const Sensor& sensor) {
            const EmitCall call;
            return generate_mesh(sensor, reconstruction_mesh_options(sensor));
          },
          "The reconstruction's mesh (Gmsh), as Reconstructor.mesh has it.")
      .def("__repr__", [](const Sensor& sensor) {
        return "<emit.Sensor '" + (sensor.name.empty() ? std::string("unnamed") : sensor.name) + "', " +
               std::to_string(electrode_count_of(sensor)) + " electrodes>";
      });

  py::class_<Mesh>(m, "Mesh", "A triangle mesh of the sheet. Its arrays are read-only views, without copies.")
      .def_property_readonly(
          "nodes_mm",
          [](const py::object& self) {
            const Mesh& mesh = self.cast<const Mesh&>();
            return view_of<double>(mesh.nodes_mm.data(), {mesh.node_count(), 3}, self);
          },
          "(V, 3) float64: node positions [mm].")
      .def_property_readonly(
          "triangles",
          [](const py::object& self) {
            const Mesh& mesh = self.cast<const Mesh&>();
            return view_of<int>(mesh.triangles.data(), {mesh.triangle_count(), 3}, self);
          },
          "(F, 3) int32: node indices of each triangle, counter-clockwise seen from +z.")
      .def_property_readonly(
          "electrodes",
          [](const py::object& self) {
            const Mesh& mesh = self.cast<const Mesh&>();
            py::list electrodes;
            for (const std::vector<int>& nodes : mesh.electrode_nodes)
              electrodes.append(view_of<int>(nodes.data(), {static_cast<py::ssize_t>(nodes.size())}, self));
            return electrodes;
          },
          "Per electrode, an int32 array of the (sorted) nodes on it.")
      .def_property_readonly(
          "triangle_areas_mm2",
          [](const Mesh& mesh) {
            Vector areas(mesh.triangle_count());
            for (Index t = 0; t < mesh.triangle_count(); ++t) areas[t] = mesh.triangle_area_mm2(t);
            return to_numpy(std::move(areas));
          },
          "(F,) float64: each triangle's area [mm^2].")
      .def_property_readonly("node_count", &Mesh::node_count)
      .def_property_readonly("triangle_count", &Mesh::triangle_count)
      .def("__repr__", [](const Mesh& mesh) {
        return "<emit.Mesh " + std::to_string(mesh.node_count()) + " nodes, " + std::to_string(mesh.triangle_count()) +
               " triangles, " + std::to_string(mesh.electrode_count()) + " electrodes>";
      });

  py::class_<Press>(m, "Press", "A press: a circular indenter at (x, y) [mm] with a force [N] (README, \"Files\").")
      .def(py::init(
               [](double x_mm, double y_mm, double force_N, double radius_mm, const std::string& profile, double z_mm) {
                 return Press{x_mm, y_mm, radius_mm, force_N, parse_press_profile(profile), z_mm};
               }),
           py::arg("x_mm"), py::arg("y_mm"), py::arg("force_N") = 10.0, py::arg("radius_mm") = 5.0,
           py::arg("profile") = "flat", py::arg("z_mm") = 0.0)
      .def_readwrite("x_mm", &Press::x_mm)
      .def_readwrite("y_mm", &Press::y_mm)
      .def_readwrite("z_mm", &Press::z_mm)
      .def_readwrite("force_N", &Press::force_N)
      .def_readwrite("radius_mm", &Press::radius_mm)
      .def_property_readonly("profile", [](const Press& press) { return profile_name(press.profile); })
      .def_property_readonly("pressure_N_per_mm2", &Press::pressure_N_per_mm2, "F / (pi r^2).")
      .def("__repr__", [](const Press& press) {
        return "Press(x_mm=" + py::repr(py::float_(press.x_mm)).cast<std::string>() +
               ", y_mm=" + py::repr(py::float_(press.y_mm)).cast<std::string>() +
               ", force_N=" + py::repr(py::float_(press.force_N)).cast<std::string>() +
               ", radius_mm=" + py::repr(py::float_(press.radius_mm)).cast<std::string>() + ", profile='" +
               profile_name(press.profile) + "')";
      });

  m.def(
      "load_frames",
      [](const std::string& path, const Sensor& sensor) {
        const int n = electrode_count_of(sensor);
        std::vector<Frame> frames;
        {
          const EmitCall call;
          frames = read_frames_csv(path, n);
        }
        py::array_t<double> stack({static_cast<py::ssize_t>(frames.size()), py::ssize_t{n}, py::ssize_t{n}});
        double* out = stack.mutable_data();
        for (const Frame& frame : frames) out = std::copy(frame.data(), frame.data() + frame.size(), out);
        return stack;
      },
      py::arg("path"), py::arg("sensor"),
      "A frames file (CSV, README \"Files\") as a (frames, N, N) float64 array.\n"
      "Raises InvalidInput naming the line and value that is wrong, IoError if unreadable.");
  m.def("methods", &method_names, "The reconstruction methods' names.");
}

}  // namespace emit::python
