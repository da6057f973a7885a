#include "emit/render/shaded_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "bitmap_font.hpp"
#include "emit/core/errors.hpp"
#include "field_drawing.hpp"

namespace emit {

namespace {

constexpr double ambient = 0.35, diffuse = 0.65;  ///< lambert_shade: 1 where the light falls square on
constexpr int min_panel_px = 40;
/// The colour bar's labels get room for %.4g's widest in practice, whatever the values.
constexpr double widest_value = -8.888e-88;
/// A mark (a line, a ring) is drawn where it is no further behind the surface seen there than this
/// fraction of the mesh's largest extent: what the surface's facets and a thick line's width take
/// from the depth of a mark on the surface near a silhouette (≈ 1 mm on a 40 mm dome), far less
/// than what lies between the near and the far side.
constexpr double mark_depth_tolerance = 0.02;
constexpr int ring_segments = 72;

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

}  // namespace

SurfaceView SurfaceView::looking_from(double azimuth_deg, double elevation_deg) {
  const double phi = radians(azimuth_deg), theta = radians(elevation_deg);
  SurfaceView view;
  view.toward_viewer = {std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta)};
  view.right = {-std::sin(phi), std::cos(phi), 0};
  view.up = view.toward_viewer.cross(view.right);
  return view;
}

Vector2 SurfaceView::to_px(const Vector3& point_mm) const {
  return {offset_x_px + scale_px_per_mm * point_mm.dot(right), offset_y_px - scale_px_per_mm * point_mm.dot(up)};
}

int SurfaceView::pixel_x(const Vector3& point_mm) const { return static_cast<int>(std::floor(to_px(point_mm).x())); }

int SurfaceView::pixel_y(const Vector3& point_mm) const { return static_cast<int>(std::floor(to_px(point_mm).y())); }

Vector3 shading_light_direction() { return Vector3(-1, -5, 7).normalized(); }

double lambert_shade(const Vector3& unit_normal) {
  return ambient + diffuse * std::abs(unit_normal.dot(shading_light_direction()));
}

namespace {

const std::string who = "render_shaded_surface";

Vector3 node(const Mesh& mesh, Index i) { return mesh.nodes_mm.row(i).transpose(); }

/// The extent of the mesh's projection on a view's right and up axes, in mm.
struct Extent {
  double min_right = std::numeric_limits<double>::infinity(), max_right = -min_right;
  double min_up = min_right, max_up = -min_right;
};

Extent projected_extent(const Mesh& mesh, const SurfaceView& view) {
  Extent e;
  for (Index i = 0; i < mesh.node_count(); ++i) {
    const double r = node(mesh, i).dot(view.right), u = node(mesh, i).dot(view.up);
    e.min_right = std::min(e.min_right, r);
    e.max_right = std::max(e.max_right, r);
    e.min_up = std::min(e.min_up, u);
    e.max_up = std::max(e.max_up, u);
  }
  return e;
}

/// Puts `view` in the square panel at (left_px, top_px) of size_px, its projection centred there.
void place(SurfaceView& view, const Extent& extent, int left_px, int top_px, int size_px, double scale_px_per_mm) {
  view.left_px = left_px;
  view.top_px = top_px;
  view.size_px = size_px;
  view.scale_px_per_mm = scale_px_per_mm;
  view.offset_x_px = left_px + 0.5 * size_px - scale_px_per_mm * 0.5 * (extent.min_right + extent.max_right);
  view.offset_y_px = top_px + 0.5 * size_px + scale_px_per_mm * 0.5 * (extent.min_up + extent.max_up);
}

int line_height_px() { return detail::text_height_px(detail::font_scale) + 4; }

std::string oblique_caption() {
  return "oblique: az " + std::to_string(int(oblique_azimuth_deg)) + ", el " +
         std::to_string(int(oblique_elevation_deg));
}
const std::string top_caption = "top: from +z";

/// A panel's caption, wrapped to the panel's width.
std::vector<std::string> caption_lines(const std::string& caption, int panel_px) {
  return detail::wrap_text(caption, panel_px);
}

/// The top of the panels: below the title, the panels' captions and the electrode numbers' margin.
int panels_top_px(const std::vector<std::string>& title_lines, int panel_px) {
  const std::size_t captions =
      std::max(caption_lines(oblique_caption(), panel_px).size(), caption_lines(top_caption, panel_px).size());
  return detail::title_height_px(title_lines) + detail::padding_px + line_height_px() * static_cast<int>(captions) +
         detail::label_margin_px;
}

std::vector<std::string> title_lines(const FieldImageOptions& options) {
  return detail::wrap_text(options.title, options.width_px - 2 * detail::padding_px);
}

int label_room_px(const FieldImageOptions& options) {
  return detail::text_width_px(detail::value_label(widest_value, options.unit), detail::font_scale);
}

}  // namespace

ShadedLayout plan_shaded_layout(const Mesh& mesh, const FieldImageOptions& options) {
  detail::check_field_inputs(mesh, Vector::Zero(mesh.node_count()), /*check_z=*/true, who);
  using detail::label_margin_px;
  const int panel_px = (options.width_px - 3 * label_margin_px - detail::bar_width_px - detail::bar_label_gap_px -
                        label_room_px(options) - detail::padding_px) /
                       2;
  if (panel_px < min_panel_px)
    throw InvalidInput(who + ": width_px " + std::to_string(options.width_px) + " leaves no room for the panels");
  ShadedLayout layout;
  layout.oblique = SurfaceView::looking_from(oblique_azimuth_deg, oblique_elevation_deg);
  layout.top = SurfaceView::looking_from(-90, 90);
  const Extent oblique = projected_extent(mesh, layout.oblique), top = projected_extent(mesh, layout.top);
  const double largest_mm = std::max({oblique.max_right - oblique.min_right, oblique.max_up - oblique.min_up,
                                      top.max_right - top.min_right, top.max_up - top.min_up});
  if (!(largest_mm > 0) || !std::isfinite(largest_mm)) throw InvalidInput(who + ": the mesh has no extent");
  const double scale_px_per_mm = panel_px / largest_mm;
  const int top_px = panels_top_px(title_lines(options), panel_px);
  place(layout.oblique, oblique, label_margin_px, top_px, panel_px, scale_px_per_mm);
  place(layout.top, top, 2 * label_margin_px + panel_px, top_px, panel_px, scale_px_per_mm);
  layout.width_px = options.width_px;
  layout.height_px = top_px + panel_px + label_margin_px;
  return layout;
}

namespace {

/// The depth of the nearest surface drawn so far at each pixel (−∞: none), row-major like Image.
class DepthBuffer {
 public:
  DepthBuffer(int width, int height)
      : width_(width),
        depth_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
               -std::numeric_limits<double>::infinity()) {}
  double& at(int x, int y) {
    return depth_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)];
  }

 private:
  int width_;
  std::vector<double> depth_;
};

Rgb shaded(Rgb colour, double shade) {
  auto channel = [shade](std::uint8_t c) { return static_cast<std::uint8_t>(std::lround(c * shade)); };
  return {channel(colour.r), channel(colour.g), channel(colour.b)};
}

/// The unit normal of triangle t (either side), or zero for a degenerate one.
Vector3 triangle_normal(const Mesh& mesh, Index t) {
  const Vector3 a = node(mesh, mesh.triangles(t, 0)), b = node(mesh, mesh.triangles(t, 1)),
                c = node(mesh, mesh.triangles(t, 2));
  const Vector3 n = (b - a).cross(c - a);
  return n.norm() > 0 ? Vector3(n.normalized()) : Vector3(Vector3::Zero());
}

/// Rasterises every triangle into one view: per pixel, the value interpolated linearly and the
/// depth likewise; the pixel takes the nearest triangle's colour (the z-buffer), shaded per facet.
void fill_surface(Image& image, DepthBuffer& depth, const SurfaceView& view, const Mesh& mesh, const Vector& values,
                  const detail::ValueRange& range) {
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const double shade = lambert_shade(triangle_normal(mesh, t));
    std::array<Vector2, 3> p;
    std::array<double, 3> v{}, d{};
    for (int k = 0; k < 3; ++k) {
      const Vector3 corner = node(mesh, mesh.triangles(t, k));
      p[k] = view.to_px(corner);
      d[k] = view.depth_mm(corner);
      v[k] = values[mesh.triangles(t, k)];
    }
    detail::for_each_triangle_pixel(image, p, [&](int x, int y, const std::array<double, 3>& w) {
      const double z = w[0] * d[0] + w[1] * d[1] + w[2] * d[2];
      if (z <= depth.at(x, y)) return;
      depth.at(x, y) = z;
      image.set(x, y, shaded(colormap(range.fraction(w[0] * v[0] + w[1] * v[1] + w[2] * v[2])), shade));
    });
  }
}

/// Draws the marks (lines, rings, labels) over one view's surface, each only where it is in sight.
class MarkPainter {
 public:
  MarkPainter(Image& image, DepthBuffer& depth, const SurfaceView& view, double tolerance_mm)
      : image_(image), depth_(depth), view_(view), tolerance_mm_(tolerance_mm) {}

  /// Whether a point at this pixel and depth is not behind the surface there.
  bool in_sight(int x, int y, double depth_mm) {
    if (x < 0 || y < 0 || x >= image_.width() || y >= image_.height()) return false;
    return depth_mm >= depth_.at(x, y) - tolerance_mm_;  // no surface there: −∞
  }

  /// The thick segment ab in 3D: each pixel within half_width_px of it where the segment's
  /// nearest point is in sight (tested at that point's pixel, so that a hidden line does not show
  /// its edge beyond a silhouette, and a line in sight keeps its width there).
  void segment(const Vector3& a, const Vector3& b, double half_width_px, Rgb colour) {
    const double da = view_.depth_mm(a), db = view_.depth_mm(b);
    const Vector2 pa = view_.to_px(a), pb = view_.to_px(b);
    detail::for_each_segment_pixel(image_, pa, pb, half_width_px, [&](int x, int y, double s) {
      const Vector2 nearest = pa + s * (pb - pa);
      if (in_sight(static_cast<int>(std::floor(nearest.x())), static_cast<int>(std::floor(nearest.y())),
                   da + s * (db - da)))
        image_.set(x, y, colour);
    });
  }

  const SurfaceView& view() const { return view_; }
  Image& image() { return image_; }

 private:
  Image& image_;
  DepthBuffer& depth_;
  const SurfaceView& view_;
  double tolerance_mm_;
};

void draw_edges(MarkPainter& painter, const Mesh& mesh, const std::vector<std::array<int, 2>>& edges,
                double half_width_px, Rgb colour) {
  for (const auto& [a, b] : edges) painter.segment(node(mesh, a), node(mesh, b), half_width_px, colour);
}

/// The centre of the mesh's bounding box: the labels go away from its projection.
Vector3 mesh_centre(const Mesh& mesh) {
  return 0.5 * (mesh.nodes_mm.colwise().minCoeff() + mesh.nodes_mm.colwise().maxCoeff()).transpose();
}

/// The electrodes, thick, and the number of each whose middle (the node of it nearest its nodes'
/// mean) is in sight, away from the mesh's centre as the view shows it.
void draw_electrodes(MarkPainter& painter, const Mesh& mesh) {
  const Vector2 centre_px = painter.view().to_px(mesh_centre(mesh));
  for (int e = 0; e < mesh.electrode_count(); ++e) {
    const std::vector<int>& nodes = mesh.electrode_nodes[e];
    if (nodes.empty()) continue;
    draw_edges(painter, mesh, mesh.electrode_edges(e), detail::electrode_half_width_px, detail::electrode_colour);
    Vector3 mean = Vector3::Zero();
    for (int n : nodes) mean += node(mesh, n);
    mean /= static_cast<double>(nodes.size());
    const int middle = *std::min_element(nodes.begin(), nodes.end(), [&](int a, int b) {
      return (node(mesh, a) - mean).squaredNorm() < (node(mesh, b) - mean).squaredNorm();
    });
    const Vector3 anchor = node(mesh, middle);
    if (!painter.in_sight(painter.view().pixel_x(anchor), painter.view().pixel_y(anchor),
                          painter.view().depth_mm(anchor)))
      continue;
    const Vector2 anchor_px = painter.view().to_px(anchor);
    Vector2 away = anchor_px - centre_px;
    away = away.norm() > 0 ? away.normalized() : Vector2(0, -1);
    detail::draw_electrode_label(painter.image(), e, anchor_px, away);
  }
}

/// The unit normal of the triangle whose centroid is nearest `point`.
Vector3 normal_near(const Mesh& mesh, const Vector3& point) {
  Index nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const double d = (mesh.triangle_centroid_mm(t) - point).squaredNorm();
    if (d < best) {
      best = d;
      nearest = t;
    }
  }
  const Vector3 n = triangle_normal(mesh, nearest);
  return n.isZero() ? Vector3(0, 0, 1) : n;
}

/// Each circle in the surface's tangent plane at its centre, as render_field draws it: white 2 px
/// wide with a dark pixel either side.
void draw_outlines(MarkPainter& painter, const Mesh& mesh, const std::vector<Circle>& outlines) {
  for (const Circle& circle : outlines) {
    const Vector3 centre(circle.center_mm.x(), circle.center_mm.y(), circle.z_mm);
    if (!centre.allFinite() || !std::isfinite(circle.radius_mm)) continue;  // nothing sensible to draw
    const Vector3 n = normal_near(mesh, centre);
    const Vector3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    std::array<Vector3, ring_segments + 1> ring;
    for (int k = 0; k <= ring_segments; ++k) {
      const double angle = 2 * std::numbers::pi * k / ring_segments;
      ring[k] = centre + circle.radius_mm * (std::cos(angle) * e1 + std::sin(angle) * e2);
    }
    for (const auto& [half_width, colour] : {std::pair{2.0, detail::outline_shadow}, std::pair{1.0, detail::white}})
      for (int k = 0; k < ring_segments; ++k) painter.segment(ring[k], ring[k + 1], half_width, colour);
  }
}

void draw_caption(Image& image, const SurfaceView& view, const std::string& caption) {
  const std::vector<std::string> lines = caption_lines(caption, view.size_px);
  const int first = view.top_px - detail::label_margin_px - line_height_px() * static_cast<int>(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i)
    detail::draw_text(image, view.left_px, first + line_height_px() * static_cast<int>(i), lines[i],
                      detail::text_colour, detail::font_scale);
}

}  // namespace

Image render_shaded_surface(const Mesh& mesh, const Vector& nodal_values, const std::vector<Circle>& outlines,
                            const FieldImageOptions& options, ShadedLayout* layout) {
  detail::check_field_inputs(mesh, nodal_values, /*check_z=*/true, who);
  const detail::ValueRange range = detail::value_range(nodal_values, options, who);
  const ShadedLayout plan = plan_shaded_layout(mesh, options);
  const double extent_mm = (mesh.nodes_mm.colwise().maxCoeff() - mesh.nodes_mm.colwise().minCoeff()).maxCoeff();

  Image image(plan.width_px, plan.height_px, detail::white);
  DepthBuffer depth(plan.width_px, plan.height_px);
  const std::vector<std::array<int, 2>> border = mesh.border_edges();
  for (const SurfaceView* view : {&plan.oblique, &plan.top}) {
    fill_surface(image, depth, *view, mesh, nodal_values, range);
    MarkPainter painter(image, depth, *view, mark_depth_tolerance * extent_mm);
    draw_edges(painter, mesh, border, detail::border_half_width_px, detail::border_colour);
    draw_electrodes(painter, mesh);
    draw_outlines(painter, mesh, outlines);
  }
  draw_caption(image, plan.oblique, oblique_caption());
  draw_caption(image, plan.top, top_caption);
  const detail::Box bar{plan.top.left_px + plan.top.size_px + detail::label_margin_px, plan.top.top_px,
                        detail::bar_width_px, plan.top.size_px};
  detail::draw_colour_bar(image, bar, detail::value_label(range.min, options.unit),
                          detail::value_label(range.max, options.unit));
  detail::draw_title(image, title_lines(options));
  if (layout) *layout = plan;
  return image;
}

}  // namespace emit
