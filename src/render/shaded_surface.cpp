#include "emit/render/shaded_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "emit/core/errors.hpp"
#include "field_drawing.hpp"
#include "text.hpp"

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
/// Where a mark falls on a pixel the surface does not cover (past a silhouette or a rim seen edge
/// on), the surface within this many pixels decides whether it is in sight.
constexpr int uncovered_window_px = 2;
constexpr int ring_segments = 72;
/// unseen_from_above_fraction's z-buffers: the mesh's largest extent across this many pixels.
constexpr int probe_px = 256;

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

/// The depth of the nearest surface drawn so far at each pixel (−∞: none), row-major like Image.
class DepthBuffer {
 public:
  DepthBuffer(int width, int height)
      : width_(width),
        depth_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
               -std::numeric_limits<double>::infinity()) {}
  double& at(int x, int y) { return depth_[index(x, y)]; }
  double at(int x, int y) const { return depth_[index(x, y)]; }

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  }
  int width_;
  std::vector<double> depth_;
};

/// The unit normal of triangle t (either side), or zero for a degenerate one.
Vector3 triangle_normal(const Mesh& mesh, Index t) {
  const Vector3 a = node(mesh, mesh.triangles(t, 0)), b = node(mesh, mesh.triangles(t, 1)),
                c = node(mesh, mesh.triangles(t, 2));
  const Vector3 n = (b - a).cross(c - a);
  return n.norm() > 0 ? Vector3(n.normalized()) : Vector3(Vector3::Zero());
}

/// Calls visit(t, x, y, weights, depths) for every pixel of `bounds` that triangle t covers in
/// `view`, for every triangle: `depths` its corners' depths, `weights` the pixel's barycentric ones.
template <typename Visit>
void for_each_surface_pixel(const Image& bounds, const SurfaceView& view, const Mesh& mesh, Visit&& visit) {
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    std::array<Vector2, 3> p;
    std::array<double, 3> d{};
    for (int k = 0; k < 3; ++k) {
      const Vector3 corner = node(mesh, mesh.triangles(t, k));
      p[k] = view.to_px(corner);
      d[k] = view.depth_mm(corner);
    }
    detail::for_each_triangle_pixel(bounds, p,
                                    [&](int x, int y, const std::array<double, 3>& w) { visit(t, x, y, w, d); });
  }
}

/// The largest extent of the mesh's bounding box: the marks' depth tolerance is a share of it.
double box_extent_mm(const Mesh& mesh) {
  return (mesh.nodes_mm.colwise().maxCoeff() - mesh.nodes_mm.colwise().minCoeff()).maxCoeff();
}

int line_height_px() { return detail::text_height_px(detail::font_scale) + 4; }

std::string oblique_caption() {
  return "oblique: az " + std::to_string(int(oblique_azimuth_deg)) + ", el " +
         std::to_string(int(oblique_elevation_deg));
}
const std::string top_caption = "top: from +z";
const std::string bottom_caption = "bottom: from -z";

SurfaceView bottom_view() { return SurfaceView::looking_from(-90, -90); }

/// A panel's caption, wrapped to the panel's width.
std::vector<std::string> caption_lines(const std::string& caption, int panel_px) {
  return detail::wrap_text(caption, panel_px);
}

/// The top of the panels: below the title, the panels' captions and the electrode numbers' margin.
int panels_top_px(const std::vector<std::string>& title_lines, int panel_px, bool with_bottom) {
  std::size_t captions =
      std::max(caption_lines(oblique_caption(), panel_px).size(), caption_lines(top_caption, panel_px).size());
  if (with_bottom) captions = std::max(captions, caption_lines(bottom_caption, panel_px).size());
  return detail::title_height_px(title_lines) + detail::padding_px + line_height_px() * static_cast<int>(captions) +
         detail::label_margin_px;
}

std::vector<std::string> title_lines(const FieldImageOptions& options) {
  return detail::wrap_text(options.title, options.width_px - 2 * detail::padding_px);
}

int label_room_px(const FieldImageOptions& options) {
  return detail::text_width_px(detail::value_label(widest_value, options.unit), detail::font_scale);
}

double largest_extent_mm(const Extent& a, const Extent& b) {
  return std::max({a.max_right - a.min_right, a.max_up - a.min_up, b.max_right - b.min_right, b.max_up - b.min_up});
}

}  // namespace

double unseen_from_above_fraction(const Mesh& mesh) {
  detail::check_field_inputs(mesh, Vector::Zero(mesh.node_count()), /*check_z=*/true, "unseen_from_above_fraction");
  std::array<SurfaceView, 2> views{SurfaceView::looking_from(oblique_azimuth_deg, oblique_elevation_deg),
                                   SurfaceView::looking_from(-90, 90)};
  const std::array<Extent, 2> extents{projected_extent(mesh, views[0]), projected_extent(mesh, views[1])};
  const double largest_mm = largest_extent_mm(extents[0], extents[1]);
  if (!(largest_mm > 0) || !std::isfinite(largest_mm)) return 0;
  const Image bounds(probe_px + 1, probe_px + 1, detail::white);
  const double tolerance_mm = mark_depth_tolerance * box_extent_mm(mesh);
  std::vector<char> seen(static_cast<std::size_t>(mesh.triangle_count()), 0);
  for (std::size_t v = 0; v < views.size(); ++v) {
    place(views[v], extents[v], 0, 0, probe_px, probe_px / largest_mm);
    DepthBuffer depth(bounds.width(), bounds.height());
    for_each_surface_pixel(bounds, views[v], mesh,
                           [&](Index, int x, int y, const std::array<double, 3>& w, const std::array<double, 3>& d) {
                             depth.at(x, y) = std::max(depth.at(x, y), w[0] * d[0] + w[1] * d[1] + w[2] * d[2]);
                           });
    for (Index t = 0; t < mesh.triangle_count(); ++t) {
      const Vector3 centroid = mesh.triangle_centroid_mm(t);
      const int x = views[v].pixel_x(centroid), y = views[v].pixel_y(centroid);
      // A centroid on no covered pixel (an edge-on sliver) counts as seen.
      if (x < 0 || y < 0 || x >= bounds.width() || y >= bounds.height() ||
          views[v].depth_mm(centroid) >= depth.at(x, y) - tolerance_mm)
        seen[static_cast<std::size_t>(t)] = 1;
    }
  }
  double unseen = 0, total = 0;
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const double area = mesh.triangle_area_mm2(t);
    total += area;
    if (!seen[static_cast<std::size_t>(t)]) unseen += area;
  }
  return total > 0 ? unseen / total : 0;
}

ShadedLayout plan_shaded_layout(const Mesh& mesh, const FieldImageOptions& options) {
  detail::check_field_inputs(mesh, Vector::Zero(mesh.node_count()), /*check_z=*/true, who);
  using detail::label_margin_px;
  ShadedLayout layout;
  layout.oblique = SurfaceView::looking_from(oblique_azimuth_deg, oblique_elevation_deg);
  layout.top = SurfaceView::looking_from(-90, 90);
  const Extent oblique = projected_extent(mesh, layout.oblique), top = projected_extent(mesh, layout.top);
  double largest_mm = largest_extent_mm(oblique, top);
  if (!(largest_mm > 0) || !std::isfinite(largest_mm)) throw InvalidInput(who + ": the mesh has no extent");
  const bool with_bottom = unseen_from_above_fraction(mesh) > bottom_panel_min_unseen_fraction;
  const int panels = with_bottom ? 3 : 2;
  const int panel_px = (options.width_px - (panels + 1) * label_margin_px - detail::bar_width_px -
                        detail::bar_label_gap_px - label_room_px(options) - detail::padding_px) /
                       panels;
  if (panel_px < min_panel_px)
    throw InvalidInput(who + ": width_px " + std::to_string(options.width_px) + " leaves no room for the panels");
  Extent bottom;
  if (with_bottom) {
    layout.bottom = bottom_view();
    bottom = projected_extent(mesh, *layout.bottom);
    largest_mm = std::max(largest_mm, largest_extent_mm(bottom, bottom));
  }
  const double scale_px_per_mm = panel_px / largest_mm;
  const int top_px = panels_top_px(title_lines(options), panel_px, with_bottom);
  place(layout.oblique, oblique, label_margin_px, top_px, panel_px, scale_px_per_mm);
  place(layout.top, top, 2 * label_margin_px + panel_px, top_px, panel_px, scale_px_per_mm);
  if (with_bottom) place(*layout.bottom, bottom, 3 * label_margin_px + 2 * panel_px, top_px, panel_px, scale_px_per_mm);
  layout.width_px = options.width_px;
  layout.height_px = top_px + panel_px + label_margin_px;
  return layout;
}

namespace {

Rgb shaded(Rgb colour, double shade) {
  auto channel = [shade](std::uint8_t c) { return static_cast<std::uint8_t>(std::lround(c * shade)); };
  return {channel(colour.r), channel(colour.g), channel(colour.b)};
}

/// Rasterises every triangle into one view: per pixel, the value interpolated linearly and the
/// depth likewise; the pixel takes the nearest triangle's colour (the z-buffer), shaded per facet.
void fill_surface(Image& image, DepthBuffer& depth, const SurfaceView& view, const Mesh& mesh, const Vector& values,
                  const detail::ValueRange& range) {
  Index current = -1;
  double shade = 0;
  std::array<double, 3> v{};
  for_each_surface_pixel(image, view, mesh,
                         [&](Index t, int x, int y, const std::array<double, 3>& w, const std::array<double, 3>& d) {
                           if (t != current) {
                             current = t;
                             shade = lambert_shade(triangle_normal(mesh, t));
                             for (int k = 0; k < 3; ++k) v[k] = values[mesh.triangles(t, k)];
                           }
                           const double z = w[0] * d[0] + w[1] * d[1] + w[2] * d[2];
                           if (z <= depth.at(x, y)) return;
                           depth.at(x, y) = z;
                           image.set(x, y,
                                     shaded(colormap(range.fraction(w[0] * v[0] + w[1] * v[1] + w[2] * v[2])), shade));
                         });
}

/// Draws the marks (lines, rings, labels) over one view's surface, each only where it is in sight.
class MarkPainter {
 public:
  MarkPainter(Image& image, DepthBuffer& depth, const SurfaceView& view, double tolerance_mm)
      : image_(image), depth_(depth), view_(view), tolerance_mm_(tolerance_mm) {}

  /// Whether a point of the surface at this pixel and depth is in sight: where the surface covers
  /// the pixel, when it is not behind it; where not (past a silhouette, on a rim seen edge on),
  /// unless all of the surface within uncovered_window_px is in front of it (the near side hiding
  /// the far side's rim, as a sleeve's top hides its bottom's rims in the top view).
  bool in_sight(int x, int y, double depth_mm) const {
    if (x < 0 || y < 0 || x >= image_.width() || y >= image_.height()) return false;
    constexpr double none = -std::numeric_limits<double>::infinity();
    if (depth_.at(x, y) != none) return depth_mm >= depth_.at(x, y) - tolerance_mm_;
    bool covered = false;
    for (int j = std::max(0, y - uncovered_window_px); j <= std::min(image_.height() - 1, y + uncovered_window_px); ++j)
      for (int i = std::max(0, x - uncovered_window_px); i <= std::min(image_.width() - 1, x + uncovered_window_px);
           ++i) {
        if (depth_.at(i, j) == none) continue;
        if (depth_mm >= depth_.at(i, j) - tolerance_mm_) return true;
        covered = true;
      }
    return !covered;
  }

  bool in_sight(const Vector3& point_mm) const {
    return in_sight(view_.pixel_x(point_mm), view_.pixel_y(point_mm), view_.depth_mm(point_mm));
  }

  /// The thick segment ab in 3D: each pixel within half_width_px of it where the surface under
  /// the segment's nearest point is in sight (tested at that surface point's pixel, so that a
  /// hidden line does not show its edge beyond a silhouette, and a line in sight keeps its width
  /// there). The surface under the segment goes from `under_a` to `under_b` (a and b themselves
  /// for a line on the mesh).
  void segment(const Vector3& a, const Vector3& b, const Vector3& under_a, const Vector3& under_b, double half_width_px,
               Rgb colour) {
    const Vector2 pa = view_.to_px(a), pb = view_.to_px(b);
    detail::for_each_segment_pixel(image_, pa, pb, half_width_px, [&](int x, int y, double s) {
      if (in_sight(Vector3(under_a + s * (under_b - under_a)))) image_.set(x, y, colour);
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
  for (const auto& [a, b] : edges) {
    const Vector3 pa = node(mesh, a), pb = node(mesh, b);
    painter.segment(pa, pb, pa, pb, half_width_px, colour);
  }
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
    if (!painter.in_sight(anchor)) continue;
    const Vector2 anchor_px = painter.view().to_px(anchor);
    Vector2 away = anchor_px - centre_px;
    away = away.norm() > 0 ? away.normalized() : Vector2(0, -1);
    detail::draw_electrode_label(painter.image(), e, anchor_px, away);
  }
}

/// The triangle whose centroid is nearest a point: its unit normal (+z for a degenerate one) and
/// that distance.
struct NearestFacet {
  Vector3 normal;
  double distance_mm;
};

NearestFacet facet_near(const Mesh& mesh, const Vector3& point) {
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
  return {n.isZero() ? Vector3(0, 0, 1) : n, std::sqrt(best)};
}

/// The point of triangle abc nearest p (Ericson, Real-Time Collision Detection, 5.1.5).
Vector3 nearest_on_triangle(const Vector3& p, const Vector3& a, const Vector3& b, const Vector3& c) {
  const Vector3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vector3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vector3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double sum = va + vb + vc;
  if (!(sum > 0)) return a;  // a degenerate triangle
  return a + vb / sum * ab + vc / sum * ac;
}

/// The longest edge of any triangle.
double longest_edge_mm(const Mesh& mesh) {
  double longest = 0;
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      longest =
          std::max(longest, (node(mesh, mesh.triangles(t, k)) - node(mesh, mesh.triangles(t, (k + 1) % 3))).norm());
  return longest;
}

/// A circle (or an ellipse) as drawn: its points in the surface's tangent plane at its centre (a
/// polygon's as given), and under each the surface's nearest point, whose visibility decides the
/// mark's.
struct Ring {
  std::vector<Vector3> points, under;  ///< closed: the last point is the first
  Vector3 centre = Vector3::Zero();    ///< the mark's point on the sheet
  std::string label;                   ///< the mark's (Circle::label); empty: none
};

/// The circles' rings (none for a circle with a non-finite centre or radius: nothing sensible to
/// draw).
std::vector<Ring> outline_rings(const Mesh& mesh, const std::vector<Circle>& outlines) {
  std::vector<Ring> rings;
  const double longest_mm = outlines.empty() ? 0 : longest_edge_mm(mesh);
  for (const Circle& circle : outlines) {
    const Vector3 centre(circle.center_mm.x(), circle.center_mm.y(), circle.z_mm);
    if (!centre.allFinite() || !std::isfinite(circle.radius_mm)) continue;
    const NearestFacet facet = facet_near(mesh, centre);
    Ring ring;
    double reach_mm = std::abs(circle.radius_mm);
    if (circle.polygon_mm.size() >= 3) {  // a contact's outline: its points on the sheet, as given
      ring.points.assign(circle.polygon_mm.begin(), circle.polygon_mm.end());
      ring.points.push_back(circle.polygon_mm.front());
      for (const Vector3& p : circle.polygon_mm) reach_mm = std::max(reach_mm, (p - centre).norm());
    }
    Vector3 e1 = facet.normal.unitOrthogonal();
    double minor_mm = circle.radius_mm;
    if (circle.ellipse && std::isfinite(circle.semi_minor_mm) && std::isfinite(circle.orientation_deg)) {
      // The major axis along its direction seen from +z, projected into the tangent plane (where
      // the plane is near vertical and that direction nearly along the normal: any tangent).
      const double angle = circle.orientation_deg * std::numbers::pi / 180;
      const Vector3 major(std::cos(angle), std::sin(angle), 0);
      const Vector3 along = major - major.dot(facet.normal) * facet.normal;
      if (along.norm() > 0.1) e1 = along.normalized();
      minor_mm = circle.semi_minor_mm;
    }
    const Vector3 e2 = facet.normal.cross(e1);
    if (ring.points.empty())
      for (int k = 0; k <= ring_segments; ++k) {
        const double angle = 2 * std::numbers::pi * k / ring_segments;
        ring.points.emplace_back(centre + circle.radius_mm * std::cos(angle) * e1 + minor_mm * std::sin(angle) * e2);
      }
    ring.centre = centre;
    ring.label = circle.label;
    ring.under.resize(ring.points.size());
    // A ring point p is within r of the centre (r: the radius, or a polygon's farthest point),
    // which is within d of a centroid, so p's nearest surface point is within r + d of p, 2r + d
    // of the centre, and its triangle's centroid within a longest edge more.
    const double within_mm = 2 * reach_mm + facet.distance_mm + longest_mm;
    std::vector<Index> candidates;
    for (Index t = 0; t < mesh.triangle_count(); ++t)
      if ((mesh.triangle_centroid_mm(t) - centre).norm() <= within_mm) candidates.push_back(t);
    for (std::size_t k = 0; k < ring.points.size(); ++k) {
      const Vector3& p = ring.points[k];
      Vector3 best = p;
      double best_distance = std::numeric_limits<double>::infinity();
      for (Index t : candidates) {
        const Vector3 q = nearest_on_triangle(p, node(mesh, mesh.triangles(t, 0)), node(mesh, mesh.triangles(t, 1)),
                                              node(mesh, mesh.triangles(t, 2)));
        if (const double d = (q - p).squaredNorm(); d < best_distance) {
          best_distance = d;
          best = q;
        }
      }
      ring.under[k] = best;
    }
    rings.push_back(ring);
  }
  return rings;
}

/// Each ring as render_field draws a circle: white 2 px wide with a dark pixel either side.
void draw_outlines(MarkPainter& painter, const std::vector<Ring>& rings) {
  for (const Ring& ring : rings)
    for (const auto& [half_width, colour] : {std::pair{2.0, detail::outline_shadow}, std::pair{1.0, detail::white}})
      for (std::size_t k = 0; k + 1 < ring.points.size(); ++k)
        painter.segment(ring.points[k], ring.points[k + 1], ring.under[k], ring.under[k + 1], half_width, colour);
}

/// Each ring's label where its point is in sight, up and right of the ring as the view shows it.
void draw_ring_labels(MarkPainter& painter, const std::vector<Ring>& rings) {
  for (const Ring& ring : rings) {
    if (ring.label.empty() || !painter.in_sight(ring.centre)) continue;
    const Vector2 centre = painter.view().to_px(ring.centre);
    double reach = 4;
    for (const Vector3& p : ring.points) reach = std::max(reach, (painter.view().to_px(p) - centre).norm());
    detail::draw_mark_label(painter.image(), centre, reach * std::numbers::sqrt2 / 2 + 3, ring.label);
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

  Image image(plan.width_px, plan.height_px, detail::white);
  DepthBuffer depth(plan.width_px, plan.height_px);
  const std::vector<std::array<int, 2>> border = mesh.border_edges();
  const std::vector<Ring> rings = outline_rings(mesh, outlines);
  std::vector<std::pair<const SurfaceView*, std::string>> panels{{&plan.oblique, oblique_caption()},
                                                                 {&plan.top, top_caption}};
  if (plan.bottom) panels.emplace_back(&*plan.bottom, bottom_caption);
  for (const auto& [view, caption] : panels) {
    fill_surface(image, depth, *view, mesh, nodal_values, range);
    MarkPainter painter(image, depth, *view, mark_depth_tolerance * box_extent_mm(mesh));
    draw_edges(painter, mesh, border, detail::border_half_width_px, detail::border_colour);
    draw_electrodes(painter, mesh);
    draw_outlines(painter, rings);
    draw_ring_labels(painter, rings);
  }
  for (const auto& [view, caption] : panels) draw_caption(image, *view, caption);
  const SurfaceView& last = *panels.back().first;
  const detail::Box bar{last.left_px + last.size_px + detail::label_margin_px, last.top_px, detail::bar_width_px,
                        last.size_px};
  detail::draw_colour_bar(image, bar, range.min, range.max, options.unit);
  // The views are orthographic at one scale: lengths across the line of sight read off it.
  detail::draw_scale_bar(image, bar.x, bar.y + bar.height + detail::label_margin_px / 3, last.scale_px_per_mm,
                         plan.width_px - bar.x - detail::padding_px);
  detail::draw_title(image, title_lines(options));
  if (layout) *layout = plan;
  return image;
}

}  // namespace emit
