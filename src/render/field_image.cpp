#include "emit/render/field_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "bitmap_font.hpp"
#include "emit/core/errors.hpp"

namespace emit {

namespace {

constexpr Rgb white{255, 255, 255};
constexpr Rgb text_colour{20, 20, 20};
constexpr Rgb border_colour{40, 40, 40};
constexpr Rgb electrode_colour{215, 95, 0};  // dark orange: stands out against every colour of the map
constexpr Rgb outline_shadow{25, 25, 25};

constexpr int font_scale = 2;
constexpr int padding_px = 8;
constexpr int label_margin_px = 40;  ///< room around the sheet for the electrode numbers
constexpr int bar_width_px = 18;
constexpr int min_bar_height_px = 120;  ///< so a flat sheet still gets a readable colour bar
constexpr double max_aspect = 4;        ///< the picture is at most this many widths tall

/// A rectangle of pixels, x right and y down.
struct Box {
  int x = 0, y = 0, width = 0, height = 0;
};

/// The sheet's extent in mm.
struct Bounds {
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  double width() const { return max_x - min_x; }
  double height() const { return max_y - min_y; }
};

/// The values that map to the two ends of the colour map.
struct ValueRange {
  double min = 0, max = 0;
  /// Position of `value` in the map; a single-valued range maps to its middle (no division by 0).
  double fraction(double value) const { return max > min ? (value - min) / (max - min) : 0.5; }
};

/// Where every part of the picture goes.
struct Canvas {
  int width = 0, height = 0;
  FieldLayout layout;
  Box bar;
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

/// The options' range, each NaN end replaced by the field's extreme (non-finite values ignored).
ValueRange value_range(const Vector& values, const FieldImageOptions& options) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (Index i = 0; i < values.size(); ++i)
    if (std::isfinite(values[i])) {
      low = std::min(low, values[i]);
      high = std::max(high, values[i]);
    }
  if (low > high) low = high = 0;  // no finite value at all
  ValueRange range{std::isnan(options.min_value) ? low : options.min_value,
                   std::isnan(options.max_value) ? high : options.max_value};
  if (!(range.min <= range.max) || !std::isfinite(range.min) || !std::isfinite(range.max))
    throw InvalidInput("render_field: colour range [" + std::to_string(range.min) + ", " + std::to_string(range.max) +
                       "] is not an interval");
  return range;
}

std::string value_label(double value, const std::string& unit) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return unit.empty() ? text : std::string(text) + " " + unit;
}

/// Splits `text` at spaces into lines no wider than `max_width_px` (a single long word overflows).
std::vector<std::string> wrap_text(const std::string& text, int max_width_px) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    if (!lines.empty() && detail::text_width_px(lines.back() + " " + word, font_scale) <= max_width_px)
      lines.back() += " " + word;
    else lines.push_back(word);
  }
  return lines;
}

Canvas plan_canvas(const Bounds& sheet, const ValueRange& range, const FieldImageOptions& options) {
  Canvas c;
  c.width = options.width_px;
  c.title_lines = wrap_text(options.title, c.width - 2 * padding_px);
  c.min_label = value_label(range.min, options.unit);
  c.max_label = value_label(range.max, options.unit);
  const int line_height = detail::text_height_px(font_scale) + 4;
  const int title_lines = static_cast<int>(c.title_lines.size());
  const int title_height = title_lines == 0 ? 0 : padding_px + line_height * title_lines;
  const int label_width =
      std::max(detail::text_width_px(c.min_label, font_scale), detail::text_width_px(c.max_label, font_scale));
  const int right_width = label_margin_px + bar_width_px + 6 + label_width + padding_px;
  const int sheet_width_px = c.width - label_margin_px - right_width;
  if (sheet_width_px < 40)
    throw InvalidInput("render_field: width_px " + std::to_string(c.width) + " leaves no room for the sheet");

  const double scale = std::min(sheet_width_px / sheet.width(), max_aspect * c.width / sheet.height());
  const int sheet_height_px = static_cast<int>(std::ceil(scale * sheet.height()));
  c.layout = {scale, double(label_margin_px), double(title_height + label_margin_px), sheet.min_x, sheet.max_y};
  const int bar_height = std::max(sheet_height_px, min_bar_height_px);
  c.bar = {static_cast<int>(std::ceil(label_margin_px + scale * sheet.width())) + label_margin_px,
           title_height + label_margin_px, bar_width_px, bar_height};
  c.height = title_height + label_margin_px + bar_height + label_margin_px;
  return c;
}

/// The pixels (inclusive bounds) whose centres may lie in [x_min, x_max] × [y_min, y_max],
/// clipped to the image. Clamping happens in double so far-off shapes cannot overflow an int.
struct PixelRange {
  int x0, x1, y0, y1;
};

PixelRange pixels_within(const Image& image, double x_min, double x_max, double y_min, double y_max) {
  auto clamp_to = [](double v, int last) { return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(last))); };
  return {clamp_to(std::floor(x_min), image.width() - 1), clamp_to(std::ceil(x_max), image.width() - 1),
          clamp_to(std::floor(y_min), image.height() - 1), clamp_to(std::ceil(y_max), image.height() - 1)};
}

/// Fills one triangle, colouring each pixel whose centre lies inside (edges included, so
/// neighbouring triangles leave no cracks) by the linearly interpolated value. Plain doubles rather
/// than Eigen vectors: this loop runs for every pixel of the sheet.
void fill_triangle(Image& image, const std::array<Vector2, 3>& corners, const std::array<double, 3>& value,
                   const ValueRange& range) {
  const double px[3] = {corners[0].x(), corners[1].x(), corners[2].x()};
  const double py[3] = {corners[0].y(), corners[1].y(), corners[2].y()};
  const double area = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]);  // doubled, signed
  if (area == 0) return;
  const PixelRange r = pixels_within(image, std::min({px[0], px[1], px[2]}), std::max({px[0], px[1], px[2]}),
                                     std::min({py[0], py[1], py[2]}), std::max({py[0], py[1], py[2]}));
  constexpr double edge_tolerance = 1e-9;  // barycentric weights are relative, so this is scale-free
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) {
      const double qx = x + 0.5, qy = y + 0.5;
      double weight[3];  // barycentric: each corner's share is the sub-triangle opposite it
      for (int k = 0; k < 3; ++k) {
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        weight[k] = ((px[a] - qx) * (py[b] - qy) - (py[a] - qy) * (px[b] - qx)) / area;
      }
      if (weight[0] < -edge_tolerance || weight[1] < -edge_tolerance || weight[2] < -edge_tolerance) continue;
      const double v = weight[0] * value[0] + weight[1] * value[1] + weight[2] * value[2];
      image.set(x, y, colormap(range.fraction(v)));
    }
}

void fill_field(Image& image, const FieldLayout& layout, const Mesh& mesh, const Vector& values,
                const ValueRange& range) {
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    std::array<Vector2, 3> p;
    std::array<double, 3> v{};
    for (int k = 0; k < 3; ++k) {
      p[k] = node_px(layout, mesh, mesh.triangles(t, k));
      v[k] = values[mesh.triangles(t, k)];
    }
    fill_triangle(image, p, v, range);
  }
}

/// Paints every pixel whose centre lies within `half_width` of segment ab (round caps).
void draw_segment(Image& image, const Vector2& a, const Vector2& b, double half_width, Rgb colour) {
  const PixelRange r = pixels_within(image, std::min(a.x(), b.x()) - half_width, std::max(a.x(), b.x()) + half_width,
                                     std::min(a.y(), b.y()) - half_width, std::max(a.y(), b.y()) + half_width);
  const Vector2 ab = b - a;
  const double length2 = ab.squaredNorm();
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) {
      const Vector2 q(x + 0.5, y + 0.5);
      const double s = length2 > 0 ? std::clamp((q - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
      if ((a + s * ab - q).norm() <= half_width) image.set(x, y, colour);
    }
}

/// Paints every pixel whose centre lies within `half_width` of the circle.
void draw_ring(Image& image, const Vector2& centre, double radius, double half_width, Rgb colour) {
  const double reach = radius + half_width;
  const PixelRange r =
      pixels_within(image, centre.x() - reach, centre.x() + reach, centre.y() - reach, centre.y() + reach);
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x)
      if (std::abs((Vector2(x + 0.5, y + 0.5) - centre).norm() - radius) <= half_width) image.set(x, y, colour);
}

void draw_edges(Image& image, const FieldLayout& layout, const Mesh& mesh, const std::vector<std::array<int, 2>>& edges,
                double half_width, Rgb colour) {
  for (const auto& [a, b] : edges)
    draw_segment(image, node_px(layout, mesh, a), node_px(layout, mesh, b), half_width, colour);
}

/// Writes electrode e's number just outside the sheet: from the electrode's middle, away from the
/// sheet's centre, far enough that the label's box clears the electrode line.
void draw_electrode_label(Image& image, const FieldLayout& layout, const Mesh& mesh, const Bounds& sheet, int e) {
  Vector2 middle(0, 0);
  for (int node : mesh.electrode_nodes[e]) middle += node_px(layout, mesh, node);
  middle /= static_cast<double>(mesh.electrode_nodes[e].size());
  Vector2 away = middle - to_px(layout, 0.5 * (sheet.min_x + sheet.max_x), 0.5 * (sheet.min_y + sheet.max_y));
  away = away.norm() > 0 ? away.normalized() : Vector2(0, 1);
  const std::string text = std::to_string(e);
  const double w = detail::text_width_px(text, font_scale), h = detail::text_height_px(font_scale);
  // Distance from the box's centre to its edge along `away` (the box's support function).
  const double clearance = 0.5 * (std::abs(away.x()) * w + std::abs(away.y()) * h);
  const Vector2 centre = middle + away * (clearance + 6);
  detail::draw_text(image, int(std::lround(centre.x() - 0.5 * w)), int(std::lround(centre.y() - 0.5 * h)), text,
                    text_colour, font_scale);
}

void draw_electrodes(Image& image, const FieldLayout& layout, const Mesh& mesh, const Bounds& sheet) {
  for (int e = 0; e < mesh.electrode_count(); ++e) {
    if (mesh.electrode_nodes[e].empty()) continue;
    draw_edges(image, layout, mesh, mesh.electrode_edges(e), 1.75, electrode_colour);  // 3–4 px
    draw_electrode_label(image, layout, mesh, sheet, e);
  }
}

/// White rings 2 px wide, with a 1 px dark ring either side so they show on the bright end of the
/// map as well as on the dark one.
void draw_outlines(Image& image, const FieldLayout& layout, const std::vector<Circle>& outlines) {
  for (const Circle& circle : outlines) {
    if (!circle.center_mm.allFinite() || !std::isfinite(circle.radius_mm)) continue;  // nothing sensible to draw
    const Vector2 centre = to_px(layout, circle.center_mm.x(), circle.center_mm.y());
    const double radius = circle.radius_mm * layout.scale_px_per_mm;
    draw_ring(image, centre, radius, 2.0, outline_shadow);
    draw_ring(image, centre, radius, 1.0, white);
  }
}

void draw_colour_bar(Image& image, const Canvas& c) {
  const Box& bar = c.bar;
  for (int row = 0; row < bar.height; ++row) {
    const Rgb colour = colormap(1.0 - (row + 0.5) / bar.height);  // top is the maximum
    for (int x = bar.x; x < bar.x + bar.width; ++x) image.set(x, bar.y + row, colour);
  }
  const Vector2 corner[4] = {{bar.x - 0.5, bar.y - 0.5},
                             {bar.x + bar.width + 0.5, bar.y - 0.5},
                             {bar.x + bar.width + 0.5, bar.y + bar.height + 0.5},
                             {bar.x - 0.5, bar.y + bar.height + 0.5}};
  for (int k = 0; k < 4; ++k) draw_segment(image, corner[k], corner[(k + 1) % 4], 0.5, border_colour);
  const int text_x = bar.x + bar.width + 6;
  detail::draw_text(image, text_x, bar.y, c.max_label, text_colour, font_scale);
  detail::draw_text(image, text_x, bar.y + bar.height - detail::text_height_px(font_scale), c.min_label, text_colour,
                    font_scale);
}

void draw_title(Image& image, const Canvas& c) {
  const int line_height = detail::text_height_px(font_scale) + 4;
  for (std::size_t i = 0; i < c.title_lines.size(); ++i)
    detail::draw_text(image, padding_px, padding_px + static_cast<int>(i) * line_height, c.title_lines[i], text_colour,
                      font_scale);
}

void check_inputs(const Mesh& mesh, const Vector& nodal_values) {
  if (mesh.node_count() == 0 || mesh.triangle_count() == 0) throw InvalidInput("render_field: the mesh is empty");
  if (!mesh.nodes_mm.leftCols(2).allFinite()) throw InvalidInput("render_field: a mesh node is not finite");
  auto valid = [&](Index node) { return node >= 0 && node < mesh.node_count(); };
  if (!valid(mesh.triangles.minCoeff()) || !valid(mesh.triangles.maxCoeff()))
    throw InvalidInput("render_field: a triangle refers to a node the mesh does not have");
  for (const auto& nodes : mesh.electrode_nodes)
    if (!nodes.empty() && (!valid(nodes.front()) || !valid(nodes.back())))  // sorted: the ends suffice
      throw InvalidInput("render_field: an electrode refers to a node the mesh does not have");
  if (nodal_values.size() != mesh.node_count())
    throw InvalidInput("render_field: " + std::to_string(nodal_values.size()) + " nodal values for a mesh of " +
                       std::to_string(mesh.node_count()) + " nodes");
}

}  // namespace

Image render_field(const Mesh& mesh, const Vector& nodal_values, const std::vector<Circle>& outlines,
                   const FieldImageOptions& options, FieldLayout* layout) {
  check_inputs(mesh, nodal_values);
  const Bounds sheet = sheet_bounds(mesh);
  const ValueRange range = value_range(nodal_values, options);
  const Canvas canvas = plan_canvas(sheet, range, options);

  Image image(canvas.width, canvas.height, white);
  fill_field(image, canvas.layout, mesh, nodal_values, range);
  draw_edges(image, canvas.layout, mesh, mesh.border_edges(), 0.75, border_colour);
  draw_electrodes(image, canvas.layout, mesh, sheet);
  draw_outlines(image, canvas.layout, outlines);
  draw_colour_bar(image, canvas);
  draw_title(image, canvas);
  if (layout) *layout = canvas.layout;
  return image;
}

}  // namespace emit
