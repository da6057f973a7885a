#include "field_drawing.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "emit/core/errors.hpp"
#include "text.hpp"

namespace emit::detail {

void check_field_inputs(const Mesh& mesh, const Vector& nodal_values, bool check_z, const std::string& who) {
  if (mesh.node_count() == 0 || mesh.triangle_count() == 0) throw InvalidInput(who + ": the mesh is empty");
  if (!(check_z ? mesh.nodes_mm.allFinite() : mesh.nodes_mm.leftCols(2).allFinite()))
    throw InvalidInput(who + ": a mesh node is not finite");
  auto valid = [&](Index node) { return node >= 0 && node < mesh.node_count(); };
  if (!valid(mesh.triangles.minCoeff()) || !valid(mesh.triangles.maxCoeff()))
    throw InvalidInput(who + ": a triangle refers to a node the mesh does not have");
  for (const auto& nodes : mesh.electrode_nodes)
    if (!nodes.empty() && (!valid(nodes.front()) || !valid(nodes.back())))  // sorted: the ends suffice
      throw InvalidInput(who + ": an electrode refers to a node the mesh does not have");
  if (nodal_values.size() != mesh.node_count())
    throw InvalidInput(who + ": " + std::to_string(nodal_values.size()) + " nodal values for a mesh of " +
                       std::to_string(mesh.node_count()) + " nodes");
}

ValueRange value_range(const Vector& values, const FieldImageOptions& options, const std::string& who) {
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
    throw InvalidInput(who + ": colour range [" + std::to_string(range.min) + ", " + std::to_string(range.max) +
                       "] is not an interval");
  return range;
}

std::string value_label(double value, const std::string& unit) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return unit.empty() ? text : std::string(text) + " " + unit;
}

std::vector<std::string> wrap_text(const std::string& text, int max_width_px) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    if (!lines.empty() && text_width_px(lines.back() + " " + word, font_scale) <= max_width_px)
      lines.back() += " " + word;
    else lines.push_back(word);
  }
  return lines;
}

namespace {

int line_height_px() { return text_height_px(font_scale) + 4; }

}  // namespace

int title_height_px(const std::vector<std::string>& title_lines) {
  return title_lines.empty() ? 0 : padding_px + line_height_px() * static_cast<int>(title_lines.size());
}

void draw_title(Image& image, const std::vector<std::string>& title_lines) {
  for (std::size_t i = 0; i < title_lines.size(); ++i)
    draw_text(image, padding_px, padding_px + static_cast<int>(i) * line_height_px(), title_lines[i], text_colour,
              font_scale);
}

void draw_mark_label(Image& image, const Vector2& centre_px, double reach_px, const std::string& label) {
  const int x = static_cast<int>(std::lround(centre_px.x() + reach_px)),
            y = static_cast<int>(std::lround(centre_px.y() - reach_px)) - text_height_px(font_scale);
  for (const auto& [dx, dy] : {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}})
    draw_text(image, x + dx, y + dy, label, outline_shadow, font_scale);
  draw_text(image, x, y, label, white, font_scale);
}

double round_step(double span) {
  const double raw = span / 4, decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 2.5, 5.0})
    if (m * decade >= raw) return m * decade;
  return 10 * decade;
}

namespace {

/// `f(value)` for each multiple of `step` in [min, max], in order.
template <typename F>
void for_each_multiple(double min, double max, double step, F&& f) {
  for (auto k = static_cast<long>(std::ceil(min / step)); static_cast<double>(k) * step <= max + 1e-9 * step; ++k)
    f(static_cast<double>(k) * step);
}

}  // namespace

void draw_mm_axes(Image& image, const MmAxes& axes) {
  const double step = round_step(std::max(axes.max_x_mm - axes.min_x_mm, axes.max_y_mm - axes.min_y_mm));
  const int text_height = text_height_px(font_scale);
  // Along x: the line under the sheet, its ticks down, each value centred under its tick; "mm" after the last.
  draw_segment(image, {axes.x_px(axes.min_x_mm), axes.x_axis_y_px + 0.5},
               {axes.x_px(axes.max_x_mm), axes.x_axis_y_px + 0.5}, 0.5, border_colour);
  int after_last = 0;
  for_each_multiple(axes.min_x_mm, axes.max_x_mm, step, [&](double value) {
    const double x = axes.x_px(value);
    draw_segment(image, {x, axes.x_axis_y_px + 0.5}, {x, axes.x_axis_y_px + 4.5}, 0.5, border_colour);
    const std::string label = value_label(value, "");
    const int left = static_cast<int>(std::lround(x)) - text_width_px(label, font_scale) / 2;
    draw_text(image, left, axes.x_axis_y_px + 6, label, text_colour, font_scale);
    after_last = left + text_width_px(label, font_scale);
  });
  draw_text(image, after_last + bar_label_gap_px, axes.x_axis_y_px + 6, "mm", text_colour, font_scale);
  // Along y: the line left of the sheet, its ticks left, each value right-aligned before its tick.
  draw_segment(image, {axes.y_axis_x_px + 0.5, axes.y_px(axes.min_y_mm)},
               {axes.y_axis_x_px + 0.5, axes.y_px(axes.max_y_mm)}, 0.5, border_colour);
  for_each_multiple(axes.min_y_mm, axes.max_y_mm, step, [&](double value) {
    const double y = axes.y_px(value);
    draw_segment(image, {axes.y_axis_x_px - 3.5, y}, {axes.y_axis_x_px + 0.5, y}, 0.5, border_colour);
    const std::string label = value_label(value, "");
    draw_text(image, axes.y_axis_x_px - 6 - text_width_px(label, font_scale),
              static_cast<int>(std::lround(y)) - text_height / 2, label, text_colour, font_scale);
  });
}

void draw_colour_bar(Image& image, const Box& bar, double min_value, double max_value, const std::string& unit) {
  const std::string min_label = value_label(min_value, unit), max_label = value_label(max_value, unit);
  for (int row = 0; row < bar.height; ++row) {
    const Rgb colour = colormap(1.0 - (row + 0.5) / bar.height);  // top is the maximum
    for (int x = bar.x; x < bar.x + bar.width; ++x) image.set(x, bar.y + row, colour);
  }
  const Vector2 corner[4] = {{bar.x - 0.5, bar.y - 0.5},
                             {bar.x + bar.width + 0.5, bar.y - 0.5},
                             {bar.x + bar.width + 0.5, bar.y + bar.height + 0.5},
                             {bar.x - 0.5, bar.y + bar.height + 0.5}};
  for (int k = 0; k < 4; ++k) draw_segment(image, corner[k], corner[(k + 1) % 4], 0.5, border_colour);
  const int text_x = bar.x + bar.width + bar_label_gap_px;
  draw_text(image, text_x, bar.y, max_label, text_colour, font_scale);
  draw_text(image, text_x, bar.y + bar.height - text_height_px(font_scale), min_label, text_colour, font_scale);
  const double span = max_value - min_value;
  if (!(span > 0) || !std::isfinite(span)) return;
  const double step = round_step(span);
  const auto first = static_cast<long>(std::ceil(min_value / step)),
             last = static_cast<long>(std::floor(max_value / step));
  for (long k = first; k <= last && k - first < 100; ++k) {
    const double value = static_cast<double>(k) * step;
    const int row = bar.y + static_cast<int>(std::lround((max_value - value) / span * bar.height));
    // Clear of the end labels (a line from the top, one from the bottom).
    if (row - text_height_px(font_scale) / 2 < bar.y + line_height_px() ||
        row + text_height_px(font_scale) / 2 > bar.y + bar.height - line_height_px())
      continue;
    draw_segment(image, {bar.x + bar.width - 4.0, row + 0.5}, {bar.x + bar.width + 3.0, row + 0.5}, 0.5, border_colour);
    draw_text(image, text_x, row - text_height_px(font_scale) / 2, value_label(value, ""), text_colour, font_scale);
  }
}

void draw_scale_bar(Image& image, int x, int y, double px_per_mm, int max_width_px) {
  double length_mm = 0;
  for (int power = -3; power <= 4; ++power)
    for (const double m : {1.0, 2.0, 5.0}) {
      const double length = m * std::pow(10.0, power);
      if (length * px_per_mm + bar_label_gap_px + text_width_px(value_label(length, "mm"), font_scale) <= max_width_px)
        length_mm = length;
    }
  if (length_mm == 0) return;
  const double right = x + length_mm * px_per_mm, middle = y + 0.5 * text_height_px(font_scale);
  draw_segment(image, {x + 0.0, middle}, {right, middle}, 1.0, text_colour);
  for (const double end : {x + 0.0, right}) draw_segment(image, {end, middle - 4}, {end, middle + 4}, 0.5, text_colour);
  draw_text(image, static_cast<int>(std::ceil(right)) + bar_label_gap_px, y, value_label(length_mm, "mm"), text_colour,
            font_scale);
}

PixelRange pixels_within(const Image& image, double x_min, double x_max, double y_min, double y_max) {
  auto clamp_to = [](double v, int last) { return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(last))); };
  return {clamp_to(std::floor(x_min), image.width() - 1), clamp_to(std::ceil(x_max), image.width() - 1),
          clamp_to(std::floor(y_min), image.height() - 1), clamp_to(std::ceil(y_max), image.height() - 1)};
}

void draw_segment(Image& image, const Vector2& a, const Vector2& b, double half_width, Rgb colour) {
  for_each_segment_pixel(image, a, b, half_width, [&](int x, int y, double) { image.set(x, y, colour); });
}

void draw_ring(Image& image, const Vector2& centre, double radius, double half_width, Rgb colour) {
  const double reach = radius + half_width;
  const PixelRange r =
      pixels_within(image, centre.x() - reach, centre.x() + reach, centre.y() - reach, centre.y() + reach);
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x)
      if (std::abs((Vector2(x + 0.5, y + 0.5) - centre).norm() - radius) <= half_width) image.set(x, y, colour);
}

void draw_electrode_label(Image& image, int e, const Vector2& middle_px, const Vector2& away) {
  const std::string text = std::to_string(e);
  const double w = text_width_px(text, font_scale), h = text_height_px(font_scale);
  // Distance from the box's centre to its edge along `away` (the box's support function).
  const double clearance = 0.5 * (std::abs(away.x()) * w + std::abs(away.y()) * h);
  const Vector2 centre = middle_px + away * (clearance + 6);
  draw_text(image, int(std::lround(centre.x() - 0.5 * w)), int(std::lround(centre.y() - 0.5 * h)), text, text_colour,
            font_scale);
}

}  // namespace emit::detail
