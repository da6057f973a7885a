// The pressure map's file: a flat sheet's picture as it always was, a curved sheet's the shaded
// two-panel one.
#include "emit/render/pressure_map.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "emit/frame/contacts.hpp"
#include "emit/mesh/element_to_node.hpp"
#include "emit/mesh/flatness.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/render/field_image.hpp"
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
// Re-pinned for the labels' real font (render/text.hpp: DejaVu Sans, not the bitmap font), the
// colour bar's ticks and the scale bar (field_drawing.hpp); again for the mm axes along the sheet
// (draw_mm_axes: 40 px of y axis at the left take from the sheet's width, 22 px of x axis below).
TEST(PressureMap, FlatSheetKeepsItsPictureByteForByte) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  const std::string folder = test::temp_folder("pressure_map_flat");
  write_pressure_map(mesh, peaked_pressure(mesh), {{Vector2(20, 35), 5.0}, {Vector2(45, 15), 3.0}},
                     "frame 3: pressure (fit), 2 contacts", folder + "/flat.png");
  const Image image = read_png(folder + "/flat.png");
  EXPECT_EQ(image.width(), 640);
  EXPECT_EQ(image.height(), 499);
  EXPECT_EQ(fnv1a(image.rgb()), 9201242327073925840ULL);
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

/// The sheet points [mm] of the picture's white pixels (the outlines' 1 px white middle: the map's
/// colours all have blue or green below 230) within `reach_mm` of `centre`.
std::vector<Vector2> white_points(const Image& image, const FieldLayout& layout, const Vector2& centre,
                                  double reach_mm) {
  std::vector<Vector2> points;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Rgb c = image.get(x, y);
      const Vector2 p(layout.min_x_mm + (x + 0.5 - layout.origin_x_px) / layout.scale_px_per_mm,
                      layout.max_y_mm - (y + 0.5 - layout.origin_y_px) / layout.scale_px_per_mm);
      if (c.r >= 230 && c.g >= 230 && c.b >= 230 && (p - centre).norm() < reach_mm) points.push_back(p);
    }
  return points;
}

// A contact with an outline is marked by its ellipse, not by the circle of its area: a bar's
// contact (semi-axes 4 and 1 mm, at 30°) is drawn as a ring whose white pixels reach 4 mm along
// 30° and 1 mm across it; the same contact without an outline gets the circle of its area, and
// a round outline a circle of its radius.
TEST(PressureMap, AContactsMarkIsItsOutlinesEllipse) {
  const Mesh mesh = test::strip_mesh(10, 10, 10, 10);
  Contact bar;
  bar.x_mm = 5, bar.y_mm = 5, bar.area_mm2 = 4 * std::numbers::pi;  // π·4·1
  bar.semi_major_mm = 4, bar.semi_minor_mm = 1, bar.orientation_deg = 30;
  const Circle mark = contact_outline(bar);
  EXPECT_TRUE(mark.ellipse);
  EXPECT_EQ(mark.radius_mm, 4.0);
  EXPECT_EQ(mark.semi_minor_mm, 1.0);
  FieldLayout layout;
  const Image image = render_field(mesh, mesh.nodes_mm.col(0), {mark}, {}, &layout);  // about 50 px/mm
  const Vector2 centre(5, 5), along(std::cos(std::numbers::pi / 6), std::sin(std::numbers::pi / 6));
  const Vector2 across(-along.y(), along.x());
  const std::vector<Vector2> white = white_points(image, layout, centre, 4.6);
  ASSERT_GT(white.size(), 200u);
  double reach_along = 0, reach_across = 0;
  for (const Vector2& p : white) {
    reach_along = std::max(reach_along, std::abs((p - centre).dot(along)));
    reach_across = std::max(reach_across, std::abs((p - centre).dot(across)));
  }
  // The white line is 2 px wide about the ellipse: its pixels' centres reach the semi-axis plus
  // at most a pixel's diagonal (0.03 mm at this scale), and at least the semi-axis less one.
  const double pixel_mm = std::sqrt(2.0) / layout.scale_px_per_mm;
  EXPECT_NEAR(reach_along, 4.0, pixel_mm);
  EXPECT_NEAR(reach_across, 1.0, pixel_mm);

  Contact disc = bar;
  disc.semi_major_mm = 0;  // no outline: the circle of its area, radius 2 mm
  const Circle circle = contact_outline(disc);
  EXPECT_FALSE(circle.ellipse);
  EXPECT_NEAR(circle.radius_mm, 2.0, 1e-12);
  disc.semi_major_mm = disc.semi_minor_mm = 2;  // a round outline stays a circle
  const Image round = render_field(mesh, mesh.nodes_mm.col(0), {contact_outline(disc)}, {}, &layout);
  double nearest = 10, farthest = 0;
  for (const Vector2& p : white_points(round, layout, centre, 4.6)) {
    nearest = std::min(nearest, (p - centre).norm());
    farthest = std::max(farthest, (p - centre).norm());
  }
  EXPECT_NEAR(nearest, 2.0, pixel_mm);
  EXPECT_NEAR(farthest, 2.0, pixel_mm);
}

// A contact with an outline's polygon is marked by the polygon: a square of side 6 mm drawn as
// its four sides: its white pixels reach the corners (not the ellipse's 3 mm) and lie on the
// sides, within a pixel.
TEST(PressureMap, AContactsMarkIsItsOutlinesPolygon) {
  const Mesh mesh = test::strip_mesh(10, 10, 10, 10);
  Contact square;
  square.x_mm = 5, square.y_mm = 5, square.area_mm2 = 36, square.semi_major_mm = square.semi_minor_mm = 3;
  for (const Vector2& p : {Vector2(2, 2), Vector2(8, 2), Vector2(8, 8), Vector2(2, 8)}) square.outline.push_back(p);
  const Circle mark = contact_outline(square);
  ASSERT_EQ(mark.polygon_mm.size(), 4u);
  EXPECT_EQ(mark.polygon_mm[1], Vector3(8, 2, 0));  // a flat sheet's chart is its plane
  FieldLayout layout;
  const Image image = render_field(mesh, mesh.nodes_mm.col(0), {mark}, {}, &layout);
  const Vector2 centre(5, 5);
  const std::vector<Vector2> white = white_points(image, layout, centre, 4.6);
  ASSERT_GT(white.size(), 200u);
  const double pixel_mm = std::sqrt(2.0) / layout.scale_px_per_mm;
  double farthest = 0, off_the_sides = 0;
  for (const Vector2& p : white) {
    farthest = std::max(farthest, (p - centre).norm());
    off_the_sides = std::max(off_the_sides, std::abs((p - centre).cwiseAbs().maxCoeff() - 3));
  }
  EXPECT_NEAR(farthest, 3 * std::sqrt(2.0), pixel_mm);  // the corners, not the ellipse's 3 mm
  EXPECT_LT(off_the_sides, pixel_mm);
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
