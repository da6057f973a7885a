#include "emit/render/field_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "field_drawing.hpp"
#include "text.hpp"

namespace emit {

namespace {

constexpr int min_bar_height_px = 120;  ///< so a flat sheet still gets a readable colour bar
constexpr double max_aspect = 4;        ///< the picture is at most this many widths tall

/// The sheet's extent in mm.
struct Bounds {
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  double width() const { return max_x - min_x; }
  double height() const { return max_y - min_y; }
};

/// Where every part of the picture goes.
struct Canvas {
  int width = 0, height = 0;
  FieldLayout layout;
  detail::Box bar;
  detail::MmAxes axes;
  std::vector<std::string> title_lines;
  std::string min_label, max_label;
};

}  // namespace

Rgb colormap(double t) {
  // Matplotlib's viridis sampled at t = 0, 0.1, …, 1 and interpolated linearly: perceptually
  // ordered, luminance rising monotonically from dark purple through blue and green to yellow.
  static constexpr std::array<std::array<double, 3>, 11> stops = {{{68, 1, 84},
                                                                   {72, 36, 117},
                                                                   {65, 68, 135},
                                                                   {53, 95, 141},
                                                                   {42, 120, 142},
                                                                   {33, 145, 140},
                                                                   {34, 168, 132},
                                                                   {68, 191, 112},
                                                                   {122, 209, 81},
                                                                   {189, 223, 38},
                                                                   {253, 231, 37}}};
  if (!(t > 0)) t = 0;  // also catches NaN
  if (t > 1) t = 1;
  const double position = t * (stops.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(position), stops.size() - 2);
  const double f = position - static_cast<double>(i);
  auto channel = [&](int c) {
    return static_cast<std::uint8_t>(std::lround(stops[i][c] + f * (stops[i + 1][c] - stops[i][c])));
  };
  return {channel(0), channel(1), channel(2)};
}

// Pixel (i, j) covers [i, i+1) × [j, j+1) in picture coordinates, so a point lands in the pixel
// given by rounding down.
int FieldLayout::pixel_x(double x_mm) const {
  return static_cast<int>(std::floor(origin_x_px + (x_mm - min_x_mm) * scale_px_per_mm));
}

int FieldLayout::pixel_y(double y_mm) const {
  return static_cast<int>(std::floor(origin_y_px + (max_y_mm - y_mm) * scale_px_per_mm));
}

namespace {

/// A sheet point in continuous picture coordinates (pixel centres at half-integers).
Vector2 to_px(const FieldLayout& layout, double x_mm, double y_mm) {
  return {layout.origin_x_px + (x_mm - layout.min_x_mm) * layout.scale_px_per_mm,
          layout.origin_y_px + (layout.max_y_mm - y_mm) * layout.scale_px_per_mm};
}

Vector2 node_px(const FieldLayout& layout, const Mesh& mesh, Index node) {
  return to_px(layout, mesh.nodes_mm(node, 0), mesh.nodes_mm(node, 1));
}

Bounds sheet_bounds(const Mesh& mesh) {
  Bounds b{mesh.nodes_mm.col(0).minCoeff(), mesh.nodes_mm.col(0).maxCoeff(), mesh.nodes_mm.col(1).minCoeff(),
           mesh.nodes_mm.col(1).maxCoeff()};
  if (!(b.width() > 0) || !(b.height() > 0) || !std::isfinite(b.width()) || !std::isfinite(b.height()))
    throw InvalidInput("render_field: the mesh has no extent in x or y");
  return b;
}

Canvas plan_canvas(const Bounds& sheet, const detail::ValueRange& range, const FieldImageOptions& options) {
  using detail::label_margin_px;
  Canvas c;
  c.width = options.width_px;
  c.title_lines = detail::wrap_text(options.title, c.width - 2 * detail::padding_px);
  c.min_label = detail::value_label(range.min, options.unit);
  c.max_label = detail::value_label(range.max, options.unit);
  const int title_height = detail::title_height_px(c.title_lines);
  const int label_width = std::max(detail::text_width_px(c.min_label, detail::font_scale),
                                   detail::text_width_px(c.max_label, detail::font_scale));
  const int right_width =
      label_margin_px + detail::bar_width_px + detail::bar_label_gap_px + label_width + detail::padding_px;
  const int sheet_width_px = c.width - detail::y_axis_width_px - label_margin_px - right_width;
  if (sheet_width_px < 40)
    throw InvalidInput("render_field: width_px " + std::to_string(c.width) + " leaves no room for the sheet");

  const double scale = std::min(sheet_width_px / sheet.width(), max_aspect * c.width / sheet.height());
  const int sheet_height_px = static_cast<int>(std::ceil(scale * sheet.height()));
  const int left = detail::y_axis_width_px + label_margin_px;  // the y axis, then the electrode numbers
  c.layout = {scale, double(left), double(title_height + label_margin_px), sheet.min_x, sheet.max_y};
  const int bar_height = std::max(sheet_height_px, min_bar_height_px);
  c.bar = {static_cast<int>(std::ceil(left + scale * sheet.width())) + label_margin_px, title_height + label_margin_px,
           detail::bar_width_px, bar_height};
  c.height = title_height + label_margin_px + bar_height + label_margin_px + detail::x_axis_height_px;
  // The axes outside the electrode numbers' margin.
  c.axes = {sheet.min_x,
            sheet.max_x,
            sheet.min_y,
            sheet.max_y,
            double(left),
            double(title_height + label_margin_px),
            scale,
            title_height + label_margin_px + sheet_height_px + label_margin_px - 4,
            detail::y_axis_width_px};
  return c;
}

void fill_field(Image& image, const FieldLayout& layout, const Mesh& mesh, const Vector& values,
                const detail::ValueRange& range) {
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    std::array<Vector2, 3> p;
    std::array<double, 3> v{};
    for (int k = 0; k < 3; ++k) {
      p[k] = node_px(layout, mesh, mesh.triangles(t, k));
      v[k] = values[mesh.triangles(t, k)];
    }
    detail::for_each_triangle_pixel(image, p, [&](int x, int y, const std::array<double, 3>& weight) {
      image.set(x, y, colormap(range.fraction(weight[0] * v[0] + weight[1] * v[1] + weight[2] * v[2])));
    });
  }
}

void draw_edges(Image& image, const FieldLayout& layout, const Mesh& mesh, const std::vector<std::array<int, 2>>& edges,
                double half_width, Rgb colour) {
  for (const auto& [a, b] : edges)
    detail::draw_segment(image, node_px(layout, mesh, a), node_px(layout, mesh, b), half_width, colour);
}

/// Numbers electrode e from its middle, away from the sheet's centre.
void draw_electrode_label(Image& image, const FieldLayout& layout, const Mesh& mesh, const Bounds& sheet, int e) {
  Vector2 middle(0, 0);
  for (int node : mesh.electrode_nodes[e]) middle += node_px(layout, mesh, node);
  middle /= static_cast<double>(mesh.electrode_nodes[e].size());
  Vector2 away = middle - to_px(layout, 0.5 * (sheet.min_x + sheet.max_x), 0.5 * (sheet.min_y + sheet.max_y));
  away = away.norm() > 0 ? away.normalized() : Vector2(0, 1);
  detail::draw_electrode_label(image, e, middle, away);
}

void draw_electrodes(Image& image, const FieldLayout& layout, const Mesh& mesh, const Bounds& sheet) {
  for (int e = 0; e < mesh.electrode_count(); ++e) {
    if (mesh.electrode_nodes[e].empty()) continue;
    draw_edges(image, layout, mesh, mesh.electrode_edges(e), detail::electrode_half_width_px, detail::electrode_colour);
    draw_electrode_label(image, layout, mesh, sheet, e);
  }
}

/// An ellipse's outline as a closed polygon of detail::ellipse_segments sides, in pixels.
void draw_ellipse(Image& image, const FieldLayout& layout, const Circle& ellipse, double half_width, Rgb colour) {
  const double angle = ellipse.orientation_deg * std::numbers::pi / 180;
  const Vector2 major(std::cos(angle), std::sin(angle)), minor(-major.y(), major.x());
  const auto point = [&](int k) {
    const double phi = 2 * std::numbers::pi * k / detail::ellipse_segments;
    const Vector2 p =
        ellipse.center_mm + ellipse.radius_mm * std::cos(phi) * major + ellipse.semi_minor_mm * std::sin(phi) * minor;
    return to_px(layout, p.x(), p.y());
  };
  for (int k = 0; k < detail::ellipse_segments; ++k)
    detail::draw_segment(image, point(k), point(k + 1), half_width, colour);
}

/// White rings 2 px wide, with a 1 px dark ring either side so they show on the bright end of the
/// map as well as on the dark one; an ellipse the same way.
/// A mark's label, up and right of its circle (its semi-major axis on the diagonal), white with a
/// dark edge so that it reads on every colour of the map.
void draw_label(Image& image, const FieldLayout& layout, const Circle& circle) {
  const double reach = std::max(circle.radius_mm * layout.scale_px_per_mm, 4.0) * std::numbers::sqrt2 / 2 + 3;
  const Vector2 centre = to_px(layout, circle.center_mm.x(), circle.center_mm.y());
  detail::draw_mark_label(image, centre, reach, circle.label);
}

void draw_outlines(Image& image, const FieldLayout& layout, const std::vector<Circle>& outlines) {
  for (const Circle& circle : outlines) {
    if (!circle.center_mm.allFinite() || !std::isfinite(circle.radius_mm)) continue;  // nothing sensible to draw
    if (const std::size_t n = circle.polygon_mm.size(); n >= 3) {
      for (const auto& [half_width, colour] : {std::pair{2.0, detail::outline_shadow}, std::pair{1.0, detail::white}})
        for (std::size_t k = 0; k < n; ++k) {
          const Vector3& a = circle.polygon_mm[k];
          const Vector3& b = circle.polygon_mm[(k + 1) % n];
          detail::draw_segment(image, to_px(layout, a.x(), a.y()), to_px(layout, b.x(), b.y()), half_width, colour);
        }
      continue;
    }
    if (circle.ellipse) {
      if (!std::isfinite(circle.semi_minor_mm) || !std::isfinite(circle.orientation_deg)) continue;
      draw_ellipse(image, layout, circle, 2.0, detail::outline_shadow);
      draw_ellipse(image, layout, circle, 1.0, detail::white);
      continue;
    }
    const Vector2 centre = to_px(layout, circle.center_mm.x(), circle.center_mm.y());
    const double radius = circle.radius_mm * layout.scale_px_per_mm;
    detail::draw_ring(image, centre, radius, 2.0, detail::outline_shadow);
    detail::draw_ring(image, centre, radius, 1.0, detail::white);
  }
  for (const Circle& circle : outlines)  // over every mark
    if (!circle.label.empty() && circle.center_mm.allFinite() && std::isfinite(circle.radius_mm))
      draw_label(image, layout, circle);
}

}  // namespace

Image render_field(const Mesh& mesh, const Vector& nodal_values, const std::vector<Circle>& outlines,
                   const FieldImageOptions& options, FieldLayout* layout) {
  options.validate();
  detail::check_field_inputs(mesh, nodal_values, /*check_z=*/false, "render_field");
  const Bounds sheet = sheet_bounds(mesh);
  const detail::ValueRange range = detail::value_range(nodal_values, options, "render_field");
  const Canvas canvas = plan_canvas(sheet, range, options);

  Image image(canvas.width, canvas.height, detail::white);
  fill_field(image, canvas.layout, mesh, nodal_values, range);
  draw_edges(image, canvas.layout, mesh, mesh.border_edges(), detail::border_half_width_px, detail::border_colour);
  draw_electrodes(image, canvas.layout, mesh, sheet);
  draw_outlines(image, canvas.layout, outlines);
  detail::draw_colour_bar(image, canvas.bar, range.min, range.max, options.unit);
  detail::draw_mm_axes(image, canvas.axes);
  // Below the colour bar, in the bottom margin the electrode numbers leave it.
  detail::draw_scale_bar(image, canvas.bar.x, canvas.bar.y + canvas.bar.height + detail::label_margin_px / 3,
                         canvas.layout.scale_px_per_mm, canvas.width - canvas.bar.x - detail::padding_px);
  detail::draw_title(image, canvas.title_lines);
  if (layout) *layout = canvas.layout;
  return image;
}

void FieldImageOptions::validate() const {
  option_check::within("FieldImageOptions", "width_px", width_px, 1, 16384);
  // NaN: the field's own; a value given is a number, and the range is not empty.
  if (std::isinf(min_value)) option_check::fail("FieldImageOptions", "min_value", "finite or NaN", "inf");
  if (std::isinf(max_value)) option_check::fail("FieldImageOptions", "max_value", "finite or NaN", "inf");
  if (min_value >= max_value)
    option_check::fail("FieldImageOptions", "max_value", "above min_value (" + std::to_string(min_value) + ")",
                       std::to_string(max_value));
}
}  // namespace emit
