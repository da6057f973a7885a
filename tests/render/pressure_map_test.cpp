// The pressure map's file: a flat sheet's picture as it always was, a curved sheet's the shaded
// two-panel one.
#include "emit/render/pressure_map.hpp"

#include <cstdint>
#include <filesystem>

#include <gtest/gtest.h>

#include "emit/mesh/element_to_node.hpp"
#include "emit/mesh/flatness.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/render/image.hpp"
#include "emit/render/shaded_surface.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace fs = std::filesystem;

/// FNV-1a over the pixels: one number that changes with any byte of the picture.
std::uint64_t fnv1a(const std::vector<std::uint8_t>& bytes) {
  std::uint64_t hash = 14695981039346656037ULL;
  for (const std::uint8_t byte : bytes) hash = (hash ^ byte) * 1099511628211ULL;
  return hash;
}

/// A pressure peaked at (20, 35) mm falling to 0 at 30 mm from it, per element.
Vector peaked_pressure(const Mesh& mesh) {
  Vector pressure(mesh.triangle_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    pressure[t] = std::max(0.0, 0.3 - 0.01 * (mesh.triangle_centroid_mm(t).head<2>() - Vector2(20, 35)).norm());
  return pressure;
}

// The shaded picture is for curved sheets only: a flat one's pixels are pinned to those emit wrote
// before it (commit 72074ef, the default sensor's reconstruction mesh), so any change to the flat
// picture, by the refactoring that shares its drawing with the shaded one or otherwise, fails here.
TEST(PressureMap, FlatSheetKeepsItsPictureByteForByte) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  const std::string folder = test::temp_folder("pressure_map_flat");
  write_pressure_map(mesh, peaked_pressure(mesh), {{Vector2(20, 35), 5.0}, {Vector2(45, 15), 3.0}},
                     "frame 3: pressure (fit), 2 contacts", folder + "/flat.png");
  const Image image = read_png(folder + "/flat.png");
  EXPECT_EQ(image.width(), 640);
  EXPECT_EQ(image.height(), 494);
  EXPECT_EQ(fnv1a(image.rgb()), 16561855106294323117ULL);
  fs::remove_all(folder);
}

// A curved sheet (the dome) gets the two-panel picture, of the size its layout says, and the flat
// picture's size would differ: 640 px wide against 1024.
TEST(PressureMap, CurvedSheetGetsTheShadedTwoPanelPicture) {
  const Sensor sensor = load_sensor(test::source_path("examples/sensors/dome25.json"));
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  ASSERT_FALSE(is_flat(mesh));
  const std::string folder = test::temp_folder("pressure_map_curved");
  const std::string title = "frame 0: pressure (fit), 1 contact";
  write_pressure_map(mesh, Vector::Constant(mesh.triangle_count(), 0.1), {{Vector2(3, 4), 2.0, 9.0}}, title,
                     folder + "/dome.png");
  const Image image = read_png(folder + "/dome.png");
  FieldImageOptions options;
  options.width_px = shaded_pressure_map_width_px;
  options.title = title;
  options.unit = "N/mm2";
  const ShadedLayout layout = plan_shaded_layout(mesh, options);
  EXPECT_EQ(image.width(), layout.width_px);
  EXPECT_EQ(image.height(), layout.height_px);
  options.min_value = 0;  // and the same picture as render_shaded_surface draws with those options
  const Vector nodal = element_to_node(mesh, Vector::Constant(mesh.triangle_count(), 0.1));
  EXPECT_EQ(image.rgb(), render_shaded_surface(mesh, nodal, {{Vector2(3, 4), 2.0, 9.0}}, options).rgb());
  fs::remove_all(folder);
}

// mesh/flatness.hpp: heights of round-off (1e-9 of the 10 mm extent) are flat; a micrometre is not.
TEST(PressureMap, OnlyAMeshOffThePlaneIsCurved) {
  Mesh mesh = test::strip_mesh(10, 10, 2, 2);
  EXPECT_TRUE(is_flat(mesh));
  mesh.nodes_mm(4, 2) = -1e-11;
  EXPECT_TRUE(is_flat(mesh));
  mesh.nodes_mm(4, 2) = -1e-3;
  EXPECT_FALSE(is_flat(mesh));
}

}  // namespace
}  // namespace emit
