// The shaded picture of a curved sheet: where points land in each panel, the Lambert shading, the
// z-buffer hiding the far side, the marks (circles, electrodes' numbers) drawn only where they are
// in sight, and the bottom panel a sleeve gets for its underside.
#include "emit/render/shaded_surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "picture_checks.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

FieldImageOptions of_width(int width_px) {
  FieldImageOptions options;
  options.width_px = width_px;
  return options;
}

Vector3 node(const Mesh& mesh, Index i) { return mesh.nodes_mm.row(i).transpose(); }
double luminance(Rgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

/// How far a colour's chromaticity, (r, g, b) / (r + g + b), is from that of the map's top
/// (yellow). Shading scales all three channels alike, so this is blind to it up to rounding; the
/// orange of the electrodes, the white of outlines and the dark border are all far from it.
double distance_from_yellow(Rgb c) {
  const Rgb top = colormap(1);
  const double sum = c.r + c.g + c.b, top_sum = top.r + top.g + top.b;
  // A pixel darker than half the map's top is none of its colours, whatever its hue: the
  // anti-aliased edge of a label's dark text over an electrode's orange ((113, 56, 10), (71, 40,
  // 15)) comes near yellow's.
  if (2 * sum < top_sum) return 1;
  return std::hypot(c.r / sum - top.r / top_sum, c.g / sum - top.g / top_sum, c.b / sum - top.b / top_sum);
}

struct Pixel {
  int x = 0, y = 0;
};

/// The pixel of the view's panel whose colour is nearest yellow.
Pixel most_yellow(const Image& image, const SurfaceView& view) {
  Pixel best;
  double nearest = 2;
  for (int y = view.top_px; y < view.top_px + view.size_px; ++y)
    for (int x = view.left_px; x < view.left_px + view.size_px; ++x)
      if (const double d = distance_from_yellow(image.get(x, y)); d < nearest) {
        nearest = d;
        best = {x, y};
      }
  return best;
}

Rgb pixel_at(const Image& image, const SurfaceView& view, const Vector3& point_mm) {
  return image.get(view.pixel_x(point_mm), view.pixel_y(point_mm));
}

/// The node of the dome nearest the surface point above (x, y).
Index node_near(const Vector2& xy_mm) {
  const Vector3 point = surface_point_mm(test::dome_sensor().shape, xy_mm);
  Index best = 0;
  (test::dome_mesh().nodes_mm.rowwise() - point.transpose()).rowwise().squaredNorm().minCoeff(&best);
  return best;
}

/// A Gaussian bump of width `sigma_mm` about `centre` (3D distance), 1 at its top.
Vector bump(const Mesh& mesh, const Vector3& centre, double sigma_mm) {
  Vector values(mesh.node_count());
  for (Index i = 0; i < mesh.node_count(); ++i)
    values[i] = std::exp(-(node(mesh, i) - centre).squaredNorm() / (2 * sigma_mm * sigma_mm));
  return values;
}

TEST(ShadedSurface, ViewsAreRightHandedAndTheTopViewIsTheFlatPicturesFrame) {
  const SurfaceView top = SurfaceView::looking_from(-90, 90);
  EXPECT_NEAR((top.right - Vector3(1, 0, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((top.up - Vector3(0, 1, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((top.toward_viewer - Vector3(0, 0, 1)).norm(), 0, 1e-15);
  const SurfaceView oblique = SurfaceView::looking_from(oblique_azimuth_deg, oblique_elevation_deg);
  EXPECT_NEAR((oblique.right.cross(oblique.up) - oblique.toward_viewer).norm(), 0, 1e-15);
  EXPECT_NEAR(oblique.up.norm(), 1, 1e-15);
  EXPECT_NEAR(oblique.toward_viewer.z(), 0.5, 1e-15);    // sin 30°
  EXPECT_NEAR(oblique.toward_viewer.y(), -0.75, 1e-15);  // cos 30° sin −60°: the viewer at −y
}

// A bump peaked at a point of the dome's near side: in each panel the pixel nearest yellow (the
// map's top) is where that point projects, to the bump's flat top (within 0.3 mm of the peak the
// value is above 0.995, a 0.2 % change of colour against rounding's 1/37 of blue) and the facets'
// linear interpolation: 3 px at the panels' ≈ 8.5 px/mm.
TEST(ShadedSurface, APeakedFieldIsBrightestWhereItsPointProjectsInBothPanels) {
  const Mesh& mesh = test::dome_mesh();
  const Vector3 peak = node(mesh, node_near({8, -6}));
  ShadedLayout layout;
  const Image image = render_shaded_surface(mesh, bump(mesh, peak, 3), {}, of_width(1024), &layout);
  EXPECT_EQ(image.width(), 1024);
  EXPECT_EQ(image.height(), layout.height_px);
  for (const SurfaceView* view : {&layout.oblique, &layout.top}) {
    const Pixel found = most_yellow(image, *view);
    const double off_px = std::hypot(found.x - view->pixel_x(peak), found.y - view->pixel_y(peak));
    EXPECT_LE(off_px, 3) << "found (" << found.x << ", " << found.y << ")";
    // Not trivially so: the point lands well away from the panel's centre.
    const Vector2 from_centre =
        view->to_px(peak) - Vector2(view->left_px, view->top_px) - Vector2::Constant(0.5 * view->size_px);
    EXPECT_GT(from_centre.norm(), 30);
  }
}

// A uniform field: every facet's colour is the map's middle times its Lambert shade, 0.35 +
// 0.65 |n·l|. Of the facets the oblique view sees face on (n·v > 0.5, well inside the rim), the one
// the light falls on most squarely and the one it grazes most differ by that ratio, each channel
// to rounding (±½ unit before and after the shade).
TEST(ShadedSurface, AFacetFacingTheLightIsBrighterByLambertsRatio) {
  const Mesh& mesh = test::dome_mesh();
  ShadedLayout layout;
  FieldImageOptions options;
  options.width_px = 1024;
  options.min_value = 0;
  options.max_value = 2;
  const Image image = render_shaded_surface(mesh, Vector::Constant(mesh.node_count(), 1), {}, options, &layout);
  const Vector3 light = shading_light_direction();
  Index lit = -1, grazed = -1;
  double most = -1, least = 2;
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const Vector3 a = node(mesh, mesh.triangles(t, 0)), b = node(mesh, mesh.triangles(t, 1)),
                  c = node(mesh, mesh.triangles(t, 2));
    const Vector3 n = (b - a).cross(c - a).normalized();
    if (std::abs(n.dot(layout.oblique.toward_viewer)) < 0.5 || mesh.triangle_centroid_mm(t).head<2>().norm() > 14)
      continue;
    const double cosine = std::abs(n.dot(light));
    if (cosine > most) most = cosine, lit = t;
    if (cosine < least) least = cosine, grazed = t;
  }
  ASSERT_GE(lit, 0);
  const double lit_shade = 0.35 + 0.65 * most, grazed_shade = 0.35 + 0.65 * least;
  EXPECT_GT(lit_shade / grazed_shade, 1.25) << "the dome's facets should span a range of light";
  const Rgb base = colormap(0.5);
  const Rgb lit_colour = pixel_at(image, layout.oblique, mesh.triangle_centroid_mm(lit));
  const Rgb grazed_colour = pixel_at(image, layout.oblique, mesh.triangle_centroid_mm(grazed));
  for (const auto& [colour, shade] : {std::pair{lit_colour, lit_shade}, std::pair{grazed_colour, grazed_shade}}) {
    EXPECT_NEAR(colour.r, base.r * shade, 0.5 + 1e-9);
    EXPECT_NEAR(colour.g, base.g * shade, 0.5 + 1e-9);
    EXPECT_NEAR(colour.b, base.b * shade, 0.5 + 1e-9);
  }
  // The green channel (the largest) as a ratio, with rounding's widest interval.
  const double ratio = double(lit_colour.g) / grazed_colour.g;
  EXPECT_GE(ratio, (base.g * lit_shade - 0.5) / (base.g * grazed_shade + 0.5));
  EXPECT_LE(ratio, (base.g * lit_shade + 0.5) / (base.g * grazed_shade - 0.5));
  EXPECT_GT(ratio, 1.2);
}

/// The mesh with its triangles in the opposite order: a z-buffer draws the same picture, a painter
/// that lets the last triangle win does not.
Mesh reversed(const Mesh& mesh) {
  Mesh out = mesh;
  out.triangles = mesh.triangles.colwise().reverse();
  return out;
}

// A hot patch on the far side, near the rim opposite the oblique viewer: its normal turns away
// from the viewer (n·v ≈ −0.2 on the sphere there), so the near side covers it. The oblique panel
// shows the near side's coldest colour at its projection, whichever order the triangles come in;
// the top view sees the patch.
TEST(ShadedSurface, TheFarSideIsHiddenInTheObliqueView) {
  const Vector3 viewer = SurfaceView::looking_from(oblique_azimuth_deg, oblique_elevation_deg).toward_viewer;
  const Vector2 away = -17 * viewer.head<2>().normalized();  // 17 mm from the axis, opposite the viewer
  const Vector3 hidden = node(test::dome_mesh(), node_near(away));
  ASSERT_LT(surface_normal(test::dome_sensor().shape, hidden.head<2>()).dot(viewer), -0.15);
  for (const Mesh& mesh : {test::dome_mesh(), reversed(test::dome_mesh())}) {
    ShadedLayout layout;
    const Image image = render_shaded_surface(mesh, bump(mesh, hidden, 1.5), {}, of_width(1024), &layout);
    EXPECT_GT(distance_from_yellow(pixel_at(image, layout.oblique, hidden)), 0.3);
    EXPECT_LT(distance_from_yellow(pixel_at(image, layout.top, hidden)), 0.05);
    // What is drawn there is the near side, cold: dark purple, blue over green.
    const Rgb near = pixel_at(image, layout.oblique, hidden);
    EXPECT_GT(near.b, near.g);
  }
}

/// How many pixels of the view's panel differ between two pictures.
int changed_pixels(const Image& a, const Image& b, const SurfaceView& view) {
  int changed = 0;
  for (int y = view.top_px; y < view.top_px + view.size_px; ++y)
    for (int x = view.left_px; x < view.left_px + view.size_px; ++x) changed += !(a.get(x, y) == b.get(x, y));
  return changed;
}

// At the default width (panels of 173 px, ≈ 4.3 px/mm) a circle of radius 2 mm is a ring of about
// 2π · 2 mm · 4.3 px/mm · 4 px ≈ 220 pixels (the oblique view foreshortens it): one on the near
// side shows in both panels; one on the far side, 15–19 mm from the axis opposite the viewer (6 mm
// and more behind the near side), only in the top view, not through the dome.
TEST(ShadedSurface, CirclesAreDrawnWhereTheyAreInSight) {
  const Mesh& mesh = test::dome_mesh();
  const Vector3 viewer = SurfaceView::looking_from(oblique_azimuth_deg, oblique_elevation_deg).toward_viewer;
  const Vector3 near = surface_point_mm(test::dome_sensor().shape, 8 * viewer.head<2>().normalized());
  const Vector3 far = surface_point_mm(test::dome_sensor().shape, -17 * viewer.head<2>().normalized());
  const Vector values = Vector::Constant(mesh.node_count(), 1);
  ShadedLayout layout;
  const Image plain = render_shaded_surface(mesh, values, {}, {}, &layout);
  const Image near_ring = render_shaded_surface(mesh, values, {{near.head<2>(), 2.0, near.z()}}, {});
  const Image far_ring = render_shaded_surface(mesh, values, {{far.head<2>(), 2.0, far.z()}}, {});
  EXPECT_GT(changed_pixels(plain, near_ring, layout.oblique), 100);
  EXPECT_GT(changed_pixels(plain, near_ring, layout.top), 100);
  EXPECT_EQ(changed_pixels(plain, far_ring, layout.oblique), 0);
  EXPECT_GT(changed_pixels(plain, far_ring, layout.top), 100);
}

// A mark's label (a contact's id and force) is written up and right of its ring, white on a dark
// edge, in each panel where the mark's point is in sight: the near mark's in both, the far one's
// in the top view only. A scale bar in mm is under the colour bar.
TEST(ShadedSurface, AMarksLabelIsWrittenWhereItIsInSightAndAScaleBarIsBelow) {
  const Mesh& mesh = test::dome_mesh();
  const Vector3 viewer = SurfaceView::looking_from(oblique_azimuth_deg, oblique_elevation_deg).toward_viewer;
  const Vector3 near = surface_point_mm(test::dome_sensor().shape, 8 * viewer.head<2>().normalized());
  const Vector3 far = surface_point_mm(test::dome_sensor().shape, -17 * viewer.head<2>().normalized());
  const Vector values = Vector::Constant(mesh.node_count(), 0);  // the map's darkest: the label's white shows
  ShadedLayout layout;
  const auto white_up_right = [&](const Image& image, const SurfaceView& view, const Vector3& point) {
    const Vector2 at = view.to_px(point);
    int n = 0;
    for (int y = static_cast<int>(at.y()) - 40; y < static_cast<int>(at.y()); ++y)
      for (int x = static_cast<int>(at.x()); x < static_cast<int>(at.x()) + 60; ++x)
        n += x >= 0 && y >= 0 && x < image.width() && y < image.height() && image.get(x, y) == Rgb{255, 255, 255};
    return n;
  };
  for (const auto& [point, in_oblique] : {std::pair{near, true}, std::pair{far, false}}) {
    Circle plain{point.head<2>(), 2.0, point.z()};
    Circle labelled = plain;
    labelled.label = "#7  3.5 N";
    const Image without = render_shaded_surface(mesh, values, {plain}, {}, &layout);
    const Image with = render_shaded_surface(mesh, values, {labelled}, {});
    // The ring itself is white too: the label adds white pixels beyond it.
    EXPECT_GT(white_up_right(with, layout.top, point) - white_up_right(without, layout.top, point), 20);
    const int oblique = white_up_right(with, layout.oblique, point) - white_up_right(without, layout.oblique, point);
    if (in_oblique) EXPECT_GT(oblique, 20);
    else EXPECT_EQ(oblique, 0);
  }
  // The scale bar: under the colour bar (right of the last panel, below its bottom), a dark run.
  const Image image = render_shaded_surface(mesh, values, {}, {}, &layout);
  const SurfaceView& last = layout.top;
  int longest = 0;
  for (int y = last.top_px + last.size_px + 1; y < image.height(); ++y) {
    int run = 0;
    for (int x = last.left_px + last.size_px; x < image.width(); ++x) {
      run = luminance(image.get(x, y)) < 100 ? run + 1 : 0;
      longest = std::max(longest, run);
    }
  }
  // Its length is a round one at the views' scale (1, 2 or 5 × 10^k mm within its end pixels).
  EXPECT_LE(test::px_from_round_length(longest, last.scale_px_per_mm), 2.0 + 1e-9) << longest << " px";
  EXPECT_GE(longest, 20);
}

// An ellipse (a contact's outline) is drawn in the tangent plane along its direction seen from +z:
// at the dome's apex, where that plane is level, the top view shows it as it is. Semi-axes 6 and
// 1.5 mm at 30°: the pixels it changes reach the semi-axes (times the view's px/mm) along 30° and
// across, plus the 2 px half-width of its dark edge and a pixel's half-diagonal, no more.
TEST(ShadedSurface, AnEllipseIsDrawnAlongItsAxes) {
  const Mesh& mesh = test::dome_mesh();
  const Vector3 apex = surface_point_mm(test::dome_sensor().shape, Vector2(0, 0));
  const Vector values = Vector::Constant(mesh.node_count(), 1);
  ShadedLayout layout;
  const Image plain = render_shaded_surface(mesh, values, {}, {}, &layout);
  Circle ellipse{apex.head<2>(), 6.0, apex.z()};
  ellipse.ellipse = true, ellipse.semi_minor_mm = 1.5, ellipse.orientation_deg = 30;
  const Image drawn = render_shaded_surface(mesh, values, {ellipse}, {});
  const SurfaceView& top = layout.top;
  const Vector2 centre = top.to_px(apex);
  const Vector3 major(std::cos(std::numbers::pi / 6), std::sin(std::numbers::pi / 6), 0);
  const Vector2 along = (top.to_px(apex + major) - centre).normalized();
  const double px_per_mm = (top.to_px(apex + major) - centre).norm();
  const Vector2 across(-along.y(), along.x());
  double reach_along = 0, reach_across = 0;
  for (int y = top.top_px; y < top.top_px + top.size_px; ++y)
    for (int x = top.left_px; x < top.left_px + top.size_px; ++x)
      if (!(plain.get(x, y) == drawn.get(x, y))) {
        const Vector2 d = Vector2(x + 0.5, y + 0.5) - centre;
        reach_along = std::max(reach_along, std::abs(d.dot(along)));
        reach_across = std::max(reach_across, std::abs(d.dot(across)));
      }
  const double edge_px = 2 + std::sqrt(0.5);
  EXPECT_GE(reach_along, 6 * px_per_mm);
  EXPECT_LE(reach_along, 6 * px_per_mm + edge_px);
  EXPECT_GE(reach_across, 1.5 * px_per_mm);
  EXPECT_LE(reach_across, 1.5 * px_per_mm + edge_px);
}

// The layout depends on the width, title and unit, not the values: the two panels are squares side
// by side, the colour bar to their right, all within the width.
TEST(ShadedSurface, LayoutIsTwoSquarePanelsWithinTheWidth) {
  FieldImageOptions options;
  options.width_px = 1024;
  options.unit = "N/mm2";
  const ShadedLayout layout = plan_shaded_layout(test::dome_mesh(), options);
  EXPECT_EQ(layout.width_px, 1024);
  EXPECT_EQ(layout.oblique.size_px, layout.top.size_px);
  EXPECT_EQ(layout.oblique.top_px, layout.top.top_px);
  EXPECT_GE(layout.top.left_px, layout.oblique.left_px + layout.oblique.size_px);
  EXPECT_GT(layout.oblique.size_px, 300);
  EXPECT_GE(layout.height_px, layout.top.top_px + layout.top.size_px);
  // Every node lands in its panel in both views.
  for (Index i = 0; i < test::dome_mesh().node_count(); ++i)
    for (const SurfaceView* view : {&layout.oblique, &layout.top}) {
      const Vector2 p = view->to_px(node(test::dome_mesh(), i));
      EXPECT_TRUE(p.x() >= view->left_px && p.x() <= view->left_px + view->size_px && p.y() >= view->top_px &&
                  p.y() <= view->top_px + view->size_px)
          << "node " << i;
    }
  options.width_px = 300;
  EXPECT_THROW(plan_shaded_layout(test::dome_mesh(), options), InvalidInput);
}

/// The example sleeve (examples/sensors/sleeve.json: radius 15 mm about the x axis, x from −30 to
/// 30, 8 electrodes on each rim) and its reconstruction mesh, made once.
const Mesh& sleeve_mesh() {
  static const Mesh mesh = [] {
    const Sensor sensor = load_sensor(test::source_path("examples/sensors/sleeve.json"));
    return generate_mesh(sensor, reconstruction_mesh_options(sensor));
  }();
  return mesh;
}

/// The sleeve's point at x and angle θ about the x axis from +y towards +z: (x, 15 cos θ, 15 sin θ).
Vector3 on_sleeve(double x_mm, double angle_deg) {
  const double a = angle_deg * std::numbers::pi / 180;
  return {x_mm, 15 * std::cos(a), 15 * std::sin(a)};
}

Index nearest_node(const Mesh& mesh, const Vector3& point) {
  Index best = 0;
  (mesh.nodes_mm.rowwise() - point.transpose()).rowwise().squaredNorm().minCoeff(&best);
  return best;
}

// The dome is all in sight from above (its top view sees every facet), so it keeps its two panels;
// the sleeve's underside is seen by neither view from above but for what the oblique view sees of
// it (outside, down to 56° below the side facing the viewer; inside, through the open end): about
// a third of its area by the facing test alone (124° of 360°), less the inside's share. So it gets
// the third panel, from −z (x right, y down), beside the other two and as large, all within the
// width, every node inside it.
TEST(ShadedSurface, TheSleeveGetsABottomPanelTheDomeDoesNot) {
  EXPECT_LT(unseen_from_above_fraction(test::dome_mesh()), 0.005);
  EXPECT_FALSE(plan_shaded_layout(test::dome_mesh(), of_width(1024)).bottom.has_value());
  const Mesh& mesh = sleeve_mesh();
  const double unseen = unseen_from_above_fraction(mesh);
  EXPECT_GT(unseen, 0.2);
  EXPECT_LT(unseen, 124.0 / 360 + 0.02);
  const ShadedLayout layout = plan_shaded_layout(mesh, of_width(1024));
  ASSERT_TRUE(layout.bottom.has_value());
  const SurfaceView& bottom = *layout.bottom;
  EXPECT_NEAR((bottom.right - Vector3(1, 0, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((bottom.up - Vector3(0, -1, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((bottom.toward_viewer - Vector3(0, 0, -1)).norm(), 0, 1e-15);
  EXPECT_EQ(bottom.size_px, layout.top.size_px);
  EXPECT_EQ(bottom.top_px, layout.top.top_px);
  EXPECT_EQ(bottom.scale_px_per_mm, layout.top.scale_px_per_mm);
  EXPECT_GE(bottom.left_px, layout.top.left_px + layout.top.size_px);
  EXPECT_LE(bottom.left_px + bottom.size_px, layout.width_px);
  for (Index i = 0; i < mesh.node_count(); ++i) {
    const Vector2 p = bottom.to_px(node(mesh, i));
    ASSERT_TRUE(p.x() >= bottom.left_px && p.x() <= bottom.left_px + bottom.size_px && p.y() >= bottom.top_px &&
                p.y() <= bottom.top_px + bottom.size_px)
        << "node " << i;
  }
}

// A bump on the sleeve's underside, 70° below the side facing +y (n·v ≈ −0.73 for the oblique
// viewer, −0.94 from +z): the bottom panel shows it, its most yellow pixel within 3 px of where
// its peak projects and that pixel yellow; the oblique and top panels show no yellow anywhere (the
// bump has fallen to nothing 14 mm of arc away, where the oblique view's silhouette is).
TEST(ShadedSurface, APressOnTheSleevesUndersideShowsInTheBottomPanelOnly) {
  const Mesh& mesh = sleeve_mesh();
  const Vector3 peak = node(mesh, nearest_node(mesh, on_sleeve(8, -70)));
  ShadedLayout layout;
  const Image image = render_shaded_surface(mesh, bump(mesh, peak, 3), {}, of_width(1024), &layout);
  ASSERT_TRUE(layout.bottom.has_value());
  const Pixel found = most_yellow(image, *layout.bottom);
  EXPECT_LE(std::hypot(found.x - layout.bottom->pixel_x(peak), found.y - layout.bottom->pixel_y(peak)), 3)
      << "found (" << found.x << ", " << found.y << ")";
  EXPECT_LT(distance_from_yellow(pixel_at(image, *layout.bottom, peak)), 0.05);
  for (const SurfaceView* view : {&layout.oblique, &layout.top}) {
    const Pixel nearest = most_yellow(image, *view);
    EXPECT_GT(distance_from_yellow(image.get(nearest.x, nearest.y)), 0.2);
  }
}

/// The sleeve with only the electrodes `keep` (the others' node lists emptied: not drawn).
Mesh with_electrodes(const Mesh& mesh, const std::vector<int>& keep) {
  Mesh out = mesh;
  for (int e = 0; e < out.electrode_count(); ++e)
    if (std::find(keep.begin(), keep.end(), e) == keep.end()) out.electrode_nodes[e].clear();
  return out;
}

Vector3 electrode_mean(const Mesh& mesh, int e) {
  Vector3 mean = Vector3::Zero();
  for (int n : mesh.electrode_nodes[e]) mean += node(mesh, n);
  return mean / static_cast<double>(mesh.electrode_nodes[e].size());
}

/// How many pixels differ between two pictures in the columns [x0, x1), all rows.
int changed_in_columns(const Image& a, const Image& b, int x0, int x1) {
  int changed = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = x0; x < x1; ++x) changed += !(a.get(x, y) == b.get(x, y));
  return changed;
}

// In the top view an electrode on the sleeve's +x rim below (z < 0) lies exactly under its mirror
// image above: their numbers would land on the same spot. Drawn alone, the one below changes
// nothing from the top panel's left edge to the bottom panel's (its number and its line are hidden
// by the top half, though the rim's pixels are ones the surface does not cover); the one above
// does (its number: ≥ 20 pixels), and the one below shows in the bottom panel (at its right, the
// +x side). The oblique panel's marks are all left of the top panel.
TEST(ShadedSurface, AnElectrodeHiddenInAPanelGetsNoNumberThere) {
  const Mesh& mesh = sleeve_mesh();
  int below = -1, above = -1;
  for (int e = 0; e < mesh.electrode_count() && above < 0; ++e) {
    const Vector3 m = electrode_mean(mesh, e);
    if (m.x() < 0 || m.z() > -5) continue;
    for (int f = 0; f < mesh.electrode_count(); ++f) {
      const Vector3 n = electrode_mean(mesh, f);
      if (n.x() > 0 && std::abs(n.y() - m.y()) < 0.5 && std::abs(n.z() + m.z()) < 0.5) {
        below = e;
        above = f;
      }
    }
  }
  ASSERT_GE(above, 0) << "no electrode pair mirrored in z = 0 on the +x rim";
  const Vector values = Vector::Constant(mesh.node_count(), 0.5);
  ShadedLayout layout;
  const Image none = render_shaded_surface(with_electrodes(mesh, {}), values, {}, of_width(1024), &layout);
  const Image only_below = render_shaded_surface(with_electrodes(mesh, {below}), values, {}, of_width(1024));
  const Image only_above = render_shaded_surface(with_electrodes(mesh, {above}), values, {}, of_width(1024));
  ASSERT_TRUE(layout.bottom.has_value());
  const int x0 = layout.top.left_px, x1 = layout.bottom->left_px;
  EXPECT_EQ(changed_in_columns(none, only_below, x0, x1), 0);
  EXPECT_GT(changed_in_columns(none, only_above, x0, x1), 20);
  EXPECT_GT(changed_in_columns(none, only_below, layout.bottom->left_px, layout.width_px), 20);
}

// Circles on the sleeve's underside: one at the bottom (θ = −90°) is hidden in the oblique and
// top panels, one 20° below the side facing +y, near the top view's silhouette, too: its tangent
// plane reaches 0.47 mm past the silhouette (15 cos 20° + 4 sin 20° > 15), where no surface covers
// the pixels, but the surface under those points is the underside, which the top half hides. Both
// show in the bottom panel.
TEST(ShadedSurface, CirclesOnTheSleevesUndersideAreHiddenFromAbove) {
  const Mesh& mesh = sleeve_mesh();
  const Vector values = Vector::Constant(mesh.node_count(), 0.5);
  ShadedLayout layout;
  const Image plain = render_shaded_surface(mesh, values, {}, of_width(2048), &layout);
  ASSERT_TRUE(layout.bottom.has_value());
  for (const double angle : {-90.0, -20.0}) {
    const Vector3 c = on_sleeve(5, angle);
    const Image ring = render_shaded_surface(mesh, values, {{c.head<2>(), 4.0, c.z()}}, of_width(2048));
    EXPECT_EQ(changed_pixels(plain, ring, layout.oblique), 0) << angle;
    EXPECT_EQ(changed_pixels(plain, ring, layout.top), 0) << angle;
    EXPECT_GT(changed_pixels(plain, ring, *layout.bottom), 200) << angle;
  }
}

TEST(ShadedSurface, RejectsValuesThatDoNotMatchTheMesh) {
  EXPECT_THROW(render_shaded_surface(test::dome_mesh(), Vector::Zero(7), {}, {}), InvalidInput);
}

}  // namespace
}  // namespace emit
