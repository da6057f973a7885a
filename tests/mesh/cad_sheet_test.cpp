// A CAD sheet (STEP through Gmsh's OpenCASCADE kernel; mesh/generate_mesh.hpp): the committed
// fingertip (examples/sensors/make_fingertip.cpp: a half capsule of radius R = 9 mm, its skin
// z ≥ 3 mm) meshed at its element size lies on the capsule, covers its area less the chords'
// shortfall, and has its 16 electrodes of 3 mm; bad electrode points are refused in one line.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

constexpr double radius_mm = 9, cut_z_mm = 3, phalanx_mm = 15;

/// The skin's area: the cylinder's part R·2 acos(3/9)·15 and the sphere's zone above z = 3 over
/// x ≥ 0, half of 2πR(R − 3).
double skin_area_mm2() {
  return radius_mm * 2 * std::acos(cut_z_mm / radius_mm) * phalanx_mm +
         std::numbers::pi * radius_mm * (radius_mm - cut_z_mm);
}

/// How far p is from the capsule's surface.
double off_capsule_mm(const Vector3& p) {
  return p.x() <= 0 ? std::abs(std::hypot(p.y(), p.z()) - radius_mm) : std::abs(p.norm() - radius_mm);
}

TEST(CadSheet, TheFingertipMeshIsItsSkinWithItsElectrodes) {
  const Sensor sensor = load_sensor(test::source_path("examples/sensors/fingertip.json"));
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  double worst_off_mm = 0, lowest_z_mm = 1e9, area_mm2 = 0, longest_mm = 0;
  for (Index v = 0; v < mesh.node_count(); ++v) {
    worst_off_mm = std::max(worst_off_mm, off_capsule_mm(mesh.nodes_mm.row(v).transpose()));
    lowest_z_mm = std::min(lowest_z_mm, mesh.nodes_mm(v, 2));
  }
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    area_mm2 += mesh.triangle_area_mm2(t);
    for (int k = 0; k < 3; ++k)
      longest_mm = std::max(longest_mm, (mesh.nodes_mm.row(mesh.triangles(t, k)) -
                                         mesh.nodes_mm.row(mesh.triangles(t, (k + 1) % 3)))
                                            .norm());
  }
  // Nodes are on the CAD surface (OpenCASCADE's own, to its tolerance, 1e-7 mm).
  EXPECT_LT(worst_off_mm, 1e-6);
  EXPECT_GT(lowest_z_mm, cut_z_mm - 1e-6);
  // A flat triangle of circumradius ρ under a sphere of radius R falls short of its patch by a
  // fraction ρ²/4R² at most (a cap over a disc: πρ²(1 + ρ²/4R²)); ρ ≤ h/√3 for the longest edge h.
  const double shortfall = (skin_area_mm2() - area_mm2) / skin_area_mm2();
  std::printf("fingertip: %ld triangles, area %.3f of %.3f mm² (shortfall %.2e, bound %.2e), longest edge %.2f mm\n",
              static_cast<long>(mesh.triangle_count()), area_mm2, skin_area_mm2(), shortfall,
              longest_mm * longest_mm / (12 * radius_mm * radius_mm), longest_mm);
  EXPECT_GT(shortfall, 0);
  EXPECT_LT(shortfall, longest_mm * longest_mm / (12 * radius_mm * radius_mm));
  // 16 electrodes, each a 3 mm curve of the border (arcs of radius ≥ √72 mm, whose chords of
  // length ≤ h fall short by at most h³/24r² each).
  ASSERT_EQ(mesh.electrode_count(), 16);
  for (int e = 0; e < 16; ++e) {
    double length_mm = 0;
    const auto edges = mesh.electrode_edges(e);
    for (const auto& edge : edges) length_mm += (mesh.nodes_mm.row(edge[0]) - mesh.nodes_mm.row(edge[1])).norm();
    const double bound_mm = static_cast<double>(edges.size()) * std::pow(longest_mm, 3) / (24 * 72);
    EXPECT_LE(length_mm, 3 + 1e-6) << "electrode " << e;
    EXPECT_GT(length_mm, 3 - bound_mm) << "electrode " << e;
  }
  // The twin's mesh is another, finer one (graded into the electrodes' ends).
  const Mesh twin = generate_mesh(sensor, twin_mesh_options(sensor));
  EXPECT_GT(twin.triangle_count(), 3 * mesh.triangle_count());
}

// The sensor read with its surface: the chart's heights are the reconstruction mesh's, its area
// theirs; its outline is the border seen from +z (x from −15 to √72, |y| ≤ √72). Written as a
// .msh and read back as a mesh-file sensor, it is the same sheet.
TEST(CadSheet, TheSensorReadsItsSurfaceAndItsMeshFileIsTheSameSheet) {
  const Sensor sensor = load_sheet_sensor(test::source_path("examples/sensors/fingertip.json"));
  ASSERT_TRUE(sensor.shape.surface);
  EXPECT_TRUE(is_curved(sensor.shape));
  EXPECT_NEAR(surface_point_mm(sensor.shape, {0, 0}).z(), radius_mm, 0.02);  // the apex, under a chord's sag
  EXPECT_NEAR((surface_normal(sensor.shape, {-7, 0}) - Vector3::UnitZ()).norm(), 0, 0.1);
  const Border& outline = sheet_outline(sensor);
  EXPECT_NEAR(outline.distance_to_border_mm({-7, 0}), 8, 1e-6);  // to the back edge x = −15
  const std::string dir = test::temp_folder("cad_sheet");
  write_msh(generate_mesh(sensor, reconstruction_mesh_options(sensor)), dir + "/fingertip.msh");
  std::ofstream(dir + "/from_msh.json") << R"({"shape": {"type": "mesh", "file": "fingertip.msh"}})";
  const Sensor from_msh = load_sheet_sensor(dir + "/from_msh.json");
  ASSERT_TRUE(from_msh.shape.surface);
  EXPECT_NEAR(surface_area_mm2(from_msh.shape), surface_area_mm2(sensor.shape), 1e-9);
  EXPECT_EQ(generate_mesh(from_msh, reconstruction_mesh_options(from_msh)).electrode_count(), 16);
}

TEST(CadSheet, BadElectrodePointsAndFilesAreRefusedInOneLine) {
  const std::string path = test::source_path("examples/sensors/fingertip.json");
  nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
  j["shape"]["file"] = test::source_path("examples/sensors/fingertip.step");
  const auto meshed = [](const nlohmann::json& description) {
    return test::error_of([&] { generate_mesh(parse_sensor(description), MeshOptions{}); });
  };
  nlohmann::json far = j;
  far["electrodes"][3]["at_mm"] = {-1.5, 8.4853, 5};
  EXPECT_NE(meshed(far).find("electrode 3 at (-1.5, 8.485, 5) mm: no border curve within 0.5 mm (the nearest is 2 mm "
                             "away); split the CAD border where the electrodes end"),
            std::string::npos)
      << meshed(far);
  nlohmann::json same = j;
  same["electrodes"][3]["at_mm"] = j["electrodes"][4]["at_mm"];
  EXPECT_NE(meshed(same).find("electrode 4 at (-6.375, 8.485, 3) mm: names the same border curve as electrode 3"),
            std::string::npos)
      << meshed(same);
  const std::string dir = test::temp_folder("cad_sheet_bad");
  std::ofstream(dir + "/not.step") << "solid sheet\n";
  nlohmann::json not_step = j;
  not_step["shape"]["file"] = dir + "/not.step";
  EXPECT_NE(meshed(not_step).find("not a STEP file (its first line is not \"ISO-10303-21;\")"), std::string::npos);
  nlohmann::json missing = j;
  missing["shape"]["file"] = dir + "/missing.stp";
  EXPECT_NE(meshed(missing).find("missing.stp\": no such CAD file"), std::string::npos) << meshed(missing);
  // Its area is known once read (502 mm²): at 1 µm that is 502 / (√3/4 · 1e-6) ≈ 1.16e9 triangles,
  // refused before meshing.
  nlohmann::json tiny = j;
  tiny["mesh"]["element_size_mm"] = 0.001;
  const Sensor tiny_sensor = parse_sensor(tiny);
  EXPECT_NE(test::error_of([&] {
              generate_mesh(tiny_sensor, reconstruction_mesh_options(tiny_sensor));
            }).find(": about 1.16e+09 triangles at 0.001 mm, beyond the limit of 1e+06"),
            std::string::npos);
  nlohmann::json no_electrodes = j;
  no_electrodes.erase("electrodes");
  EXPECT_EQ(test::error_of([&] { parse_sensor(no_electrodes); }),
            "sensor: electrodes: missing: a CAD sheet names each electrode's border curve, [{\"at_mm\": [x, y, z]}, "
            "...]");
  nlohmann::json flat_point = j;
  flat_point["electrodes"][0]["at_mm"] = {8.4853, 0};
  EXPECT_EQ(test::error_of([&] { parse_sensor(flat_point); }),
            "sensor: electrodes[0].at_mm: must be a point [x, y, z] in mm, got [8.4853,0]");
}

// A closed STEP solid (a sphere; tests/data/cad/closed_sphere.step, written by Gmsh's OpenCASCADE)
// has no border: its electrodes were "no border curve within 0.5 mm (the nearest is inf mm away)".
TEST(CadSheet, AClosedSurfaceIsRefusedSayingWhatIsExpected) {
  const nlohmann::json j = {{"shape",
                             {{"type", "mesh"}, {"file", test::source_path("tests/data/cad/closed_sphere.step")}}},
                            {"electrodes",
                             {{{"at_mm", {10, 0, 0}}}, {{"at_mm", {0, 10, 0}}}, {{"at_mm", {-10, 0, 0}}}}}};
  const Sensor sensor = parse_sensor(j);
  const std::string error = test::error_of([&] { generate_mesh(sensor, reconstruction_mesh_options(sensor)); });
  EXPECT_NE(error.find("closed_sphere.step\": the CAD surface is closed (a solid's skin, or a closed shell): it has no "
                       "open border for the electrodes; the sheet must be an open surface"),
            std::string::npos)
      << error;
  EXPECT_EQ(error.find("inf mm"), std::string::npos) << error;
}

// A word where a STEP number should be (a coordinate "NAN"): OpenCASCADE printed "Incorrect Syntax"
// to the terminal and ran on for over a minute. emit reads the file's words first and names the line.
TEST(CadSheet, AStepFileThatIsNotStepIsRefusedNamingTheLine) {
  const std::string dir = test::temp_folder("cad_sheet_step_words");
  std::string step = test::read_text(test::source_path("examples/sensors/fingertip.step"));
  const std::string point = "CARTESIAN_POINT('',(-15.,8.485281374238,3.))";
  ASSERT_NE(step.find(point), std::string::npos);
  const std::string before = step.substr(0, step.find(point));
  const auto line = static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n')) + 1;
  nlohmann::json j = nlohmann::json::parse(std::ifstream(test::source_path("examples/sensors/fingertip.json")));
  const auto meshed = [&](const std::string& text) {
    std::ofstream(dir + "/sheet.step") << text;
    j["shape"]["file"] = dir + "/sheet.step";
    const Sensor sensor = parse_sensor(j);
    return test::error_of([&] { generate_mesh(sensor, reconstruction_mesh_options(sensor)); });
  };
  std::string nan = step;
  nan.replace(nan.find(point), point.size(), "CARTESIAN_POINT('',(-15.,NAN,3.))");
  EXPECT_EQ(meshed(nan), "\"" + dir + "/sheet.step\": line " + std::to_string(line) +
                             ": \"NAN\" stands where a value should be (a keyword is followed by \"(\") (not a STEP "
                             "file, ISO 10303-21)");
  std::string huge = step;
  huge.replace(huge.find(point), point.size(), "CARTESIAN_POINT('',(-15.,1.E999,3.))");
  EXPECT_NE(meshed(huge).find("line " + std::to_string(line) + ": the number \"1.E999\" is not finite"),
            std::string::npos)
      << meshed(huge);
  EXPECT_NE(meshed(step.substr(0, step.find(point)) + "CARTESIAN_POINT('cut").find("the file ends inside a string"),
            std::string::npos);
}

// A CAD file's name of 5,000 characters: the file system refused it and the message's reason was
// empty ("meshing s: "). Now it says so, quoting the name's start.
TEST(CadSheet, AFileNameTooLongIsSaidSo) {
  nlohmann::json j = nlohmann::json::parse(std::ifstream(test::source_path("examples/sensors/fingertip.json")));
  j["shape"]["file"] = std::string(5000, 'a') + ".step";
  const Sensor sensor = parse_sensor(j, "s.json", "/tmp");
  const std::string error = test::error_of([&] { generate_mesh(sensor, reconstruction_mesh_options(sensor)); });
  EXPECT_EQ(error, "\"/tmp/" + std::string(35, 'a') +
                       "...\": the CAD file's name is too long for the file system (5010 characters; at most 255 "
                       "between slashes, 4095 in all)");
}

}  // namespace
}  // namespace emit
