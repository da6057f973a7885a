// A sheet from an STL surface (mesh/stl_sheet.hpp): the CAD fingertip's mesh written as ASCII
// STL (each triangle with its own three vertices, as STL has it) is read back as one surface with
// its 16 electrodes of 3 mm placed on its border by point and width, exactly 3 mm along it; a
// press on it is fitted on the surface; bad electrodes are refused in one line.
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/mesh/stl_sheet.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/sensor/press.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

void write_ascii_stl(const Mesh& mesh, const std::string& path) {
  std::ofstream out(path);
  out.precision(17);
  out << "solid fingertip\n";
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    out << " facet normal 0 0 1\n  outer loop\n";
    for (int k = 0; k < 3; ++k) {
      const auto p = mesh.nodes_mm.row(mesh.triangles(t, k));
      out << "   vertex " << p.x() << " " << p.y() << " " << p.z() << "\n";
    }
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid fingertip\n";
}

/// The fingertip's description with its surface from `stl` and electrodes of `width_mm` at the
/// CAD electrodes' midpoints.
nlohmann::json stl_fingertip(const std::string& stl, double width_mm) {
  nlohmann::json j = nlohmann::json::parse(std::ifstream(test::source_path("examples/sensors/fingertip.json")));
  j["shape"]["file"] = stl;
  for (auto& e : j["electrodes"]) e["width_mm"] = width_mm;
  return j;
}

TEST(StlSheet, TheFingertipAsStlHasItsElectrodesAndFitsAPress) {
  const std::string dir = test::temp_folder("stl_sheet");
  const Sensor cad = load_sensor(test::source_path("examples/sensors/fingertip.json"));
  const Mesh cad_mesh = generate_mesh(cad, reconstruction_mesh_options(cad));
  write_ascii_stl(cad_mesh, dir + "/fingertip.stl");
  const Sensor sensor = with_sheet_surface(parse_sensor(stl_fingertip(dir + "/fingertip.stl", 3)));
  const Mesh mesh = read_stl_sheet(sensor);
  // Repeated vertices merged: the CAD mesh's nodes, and one per electrode end not on one of its
  // nodes (the CAD mesh has nodes at its electrodes' ends, so none here).
  EXPECT_EQ(mesh.node_count(), cad_mesh.node_count());
  EXPECT_EQ(mesh.triangle_count(), cad_mesh.triangle_count());
  ASSERT_EQ(mesh.electrode_count(), 16);
  for (int e = 0; e < 16; ++e) {
    double length_mm = 0;
    for (const auto& edge : mesh.electrode_edges(e))
      length_mm += (mesh.nodes_mm.row(edge[0]) - mesh.nodes_mm.row(edge[1])).norm();
    // The stretch of the border polyline 3 mm long, to the micrometre an end may snap by.
    EXPECT_NEAR(length_mm, 3, 2e-3) << "electrode " << e;
  }
  // The STL is both twin and reconstruction mesh: a press is found on the surface within the
  // curved sheets' target of 0.3 mm.
  Pipeline pipeline(sensor, {Method::fit, 0, "", {}});
  Reconstructor reconstructor = pipeline.reconstructor();
  Twin twin(sensor);
  reconstructor.set_reference({twin.exact_frame({}), 1});
  const Press press = press_at_chart(sensor.shape, {-6, 2}, 2.5, 2);
  const Vector3 p(press.x_mm, press.y_mm, press.z_mm);
  const auto& contacts = reconstructor.process(twin.exact_frame({press}));
  ASSERT_EQ(contacts.size(), 1u);
  const double error_mm = (Vector3(contacts[0].x_mm, contacts[0].y_mm, contacts[0].z_mm) - p).norm();
  std::printf("STL fingertip: press at (%.1f, %.1f, %.2f) found %.3f mm away\n", p.x(), p.y(), p.z(), error_mm);
  EXPECT_LT(error_mm, 0.3);
  // An electrode whose ends fall between border nodes splits the border there.
  nlohmann::json shifted = stl_fingertip(dir + "/fingertip.stl", 2.5);
  shifted["electrodes"][0]["at_mm"] = {8.4, 1.2, 3};  // 1.2 mm round the tip's circle
  const Mesh split = read_stl_sheet(parse_sensor(shifted));
  EXPECT_GT(split.node_count(), cad_mesh.node_count());
  double first_mm = 0;
  for (const auto& edge : split.electrode_edges(0))
    first_mm += (split.nodes_mm.row(edge[0]) - split.nodes_mm.row(edge[1])).norm();
  EXPECT_NEAR(first_mm, 2.5, 2e-3);
}

TEST(StlSheet, BadElectrodesAreRefusedInOneLine) {
  const std::string dir = test::temp_folder("stl_sheet_bad");
  const Sensor cad = load_sensor(test::source_path("examples/sensors/fingertip.json"));
  write_ascii_stl(generate_mesh(cad, reconstruction_mesh_options(cad)), dir + "/f.stl");
  const auto read = [](const nlohmann::json& j) { return test::error_of([&] { read_stl_sheet(parse_sensor(j)); }); };
  EXPECT_NE(read(stl_fingertip(dir + "/f.stl", 5)).find("f.stl\": electrodes 0 and 1 overlap"), std::string::npos)
      << read(stl_fingertip(dir + "/f.stl", 5));
  nlohmann::json far = stl_fingertip(dir + "/f.stl", 3);
  far["electrodes"][2]["at_mm"] = {0, 0, 9};
  EXPECT_NE(read(far).find("f.stl\": electrode 2 at (0, 0, 9) mm is 10.4 mm from the border (at most 0.5)"),
            std::string::npos)
      << read(far);
  nlohmann::json no_width = stl_fingertip(dir + "/f.stl", 3);
  no_width["electrodes"][1].erase("width_mm");
  EXPECT_EQ(test::error_of([&] { parse_sensor(no_width); }), "sensor: electrodes[1].width_mm: missing");
  nlohmann::json missing = stl_fingertip(dir + "/none.stl", 3);
  EXPECT_NE(read(missing).find("none.stl\": no such STL file"), std::string::npos) << read(missing);
}

/// A 20 mm square of n × n squares, two triangles each, as ASCII STL; corner 0 of triangle `nan_at`
/// (if ≥ 0) not a number.
std::string square_stl(int n, int nan_at = -1) {
  std::string text = "solid square\n";
  const double h = 20.0 / n;
  int t = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (const auto& corners : {std::array<std::array<int, 2>, 3>{{{i, j}, {i + 1, j}, {i + 1, j + 1}}},
                                  std::array<std::array<int, 2>, 3>{{{i, j}, {i + 1, j + 1}, {i, j + 1}}}}) {
        text += "facet normal 0 0 1\nouter loop\n";
        for (int k = 0; k < 3; ++k)
          text += (t == nan_at && k == 0 ? std::string("vertex nan 0 0")
                                         : "vertex " + std::to_string(corners[k][0] * h) + " " +
                                               std::to_string(corners[k][1] * h) + " 0") +
                  "\n";
        text += "endloop\nendfacet\n";
        ++t;
      }
  return text + "endsolid square\n";
}

nlohmann::json square_sheet(const std::string& stl) {
  nlohmann::json electrodes = nlohmann::json::array();
  for (const auto& [x, y] : {std::pair{10, 0}, {20, 10}, {10, 20}, {0, 10}})
    electrodes.push_back({{"at_mm", {x, y, 0}}, {"width_mm", 2}});
  return {{"name", "square"}, {"shape", {{"type", "mesh"}, {"file", stl}}}, {"electrodes", electrodes}};
}

// One NaN corner failed an assertion inside Gmsh's STL reader: the process aborted (exit 134), a
// Python interpreter with it. emit reads the file first and names the triangle.
TEST(StlSheet, ACornerThatIsNotANumberIsRefusedBeforeGmshReadsIt) {
  const std::string dir = test::temp_folder("stl_sheet_nan");
  std::ofstream(dir + "/nan.stl") << square_stl(4, 0);
  const Sensor sensor = parse_sensor(square_sheet(dir + "/nan.stl"));
  EXPECT_EQ(test::error_of([&] { read_stl_sheet(sensor); }),
            "\"" + dir + "/nan.stl\": triangle 0 (line 2): corner 0 is (nan, 0, 0), not finite numbers");
  EXPECT_EQ(test::error_of([&] { with_sheet_surface(sensor); }),
            "\"" + dir + "/nan.stl\": triangle 0 (line 2): corner 0 is (nan, 0, 0), not finite numbers");
  std::ofstream(dir + "/good.stl") << square_stl(4);
  EXPECT_EQ(read_stl_sheet(parse_sensor(square_sheet(dir + "/good.stl"))).electrode_count(), 4);
}

// mesh.max_triangles (and emit mesh --max-triangles, through MeshOptions) held for drawn sheets
// only: an STL of any size was read whole. It holds for a file's sheet too, counted as it is read.
TEST(StlSheet, TheTriangleLimitHoldsForAnStlSheet) {
  const std::string dir = test::temp_folder("stl_sheet_limit");
  std::ofstream(dir + "/square.stl") << square_stl(10);  // 200 triangles
  nlohmann::json j = square_sheet(dir + "/square.stl");
  j["mesh"] = {{"max_triangles", 100}};
  EXPECT_NE(test::error_of([&] {
              with_sheet_surface(parse_sensor(j));
            }).find("square.stl\": more than 100 triangles (line 702), beyond the limit of 100 triangles"),
            std::string::npos)
      << test::error_of([&] { with_sheet_surface(parse_sensor(j)); });
  j["mesh"] = {{"max_triangles", 1000}};
  const Sensor sensor = with_sheet_surface(parse_sensor(j));
  MeshOptions options = reconstruction_mesh_options(sensor);
  options.max_triangles = 150;
  EXPECT_NE(test::error_of([&] { generate_mesh(sensor, options); }).find("beyond the limit of 150 triangles"),
            std::string::npos);
  options.max_triangles = 200;  // the file's 200, and then the electrodes' ends split a few more
  EXPECT_GE(generate_mesh(sensor, options).triangle_count(), 200);
}

}  // namespace
}  // namespace emit
