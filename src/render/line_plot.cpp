#include "emit/render/line_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "text.hpp"

namespace emit {

namespace {

constexpr Rgb white{255, 255, 255};
constexpr Rgb text_colour{20, 20, 20};
constexpr Rgb frame_colour{40, 40, 40};
constexpr Rgb grid_colour{228, 228, 228};

constexpr int font_scale = 2;        ///< title, axis labels, tick labels, legend
constexpr int point_font_scale = 1;  ///< point labels: small, as there may be many
constexpr int padding_px = 8;
constexpr int tick_length_px = 5;
constexpr int tick_gap_px = 4;  ///< between a tick's end and its label
constexpr int min_plot_side_px = 40;
constexpr int max_ticks = 10;
constexpr int marker_radius_px = 3;
constexpr int legend_line_px = 24;  ///< the sample line in front of each legend entry

/// One point that will be drawn, in data units. `index` is its position in the series (for its
/// label); `joins_previous` is false where a skipped point (or the series' start) breaks the line.
struct DataPoint {
  double x = 0, y = 0;
  std::size_t index = 0;
  bool joins_previous = false;
};

/// One axis' extent in axis space: the value itself, or its log10 on a log axis.
struct AxisRange {
  double lo = 0, hi = 1;
  bool log = false;
  double to_data(double t) const { return log ? std::pow(10.0, t) : t; }
};

struct Tick {
  double value = 0;  ///< data units
  std::string label;
};

/// Where every part of the picture goes.
struct Canvas {
  PlotLayout layout;
  std::vector<Tick> x_ticks, y_ticks;
  int title_y = 0, y_label_y = 0, x_label_y = 0;
};

/// The pixel a continuous position falls in, clamped in double first so that far-off values cannot
/// overflow an int (UB); ±1e6 px is far outside any image, and so is where NaN goes (e.g. the
/// position of a negative value on a log axis).
int to_pixel(double position) {
  if (std::isnan(position)) return -1'000'000;
  return static_cast<int>(std::floor(std::clamp(position, -1e6, 1e6)));
}

/// Fraction of the way from `lo` to `hi` that `value` lies, in axis space.
double axis_fraction(double value, double lo, double hi, bool log) {
  if (log) {
    value = std::log10(value);
    lo = std::log10(lo);
    hi = std::log10(hi);
  }
  return (value - lo) / (hi - lo);
}

}  // namespace

// The axis ends map to the centres of the plot area's first and last pixels, so every drawn point
// (which lies inside the padded range) lands inside the area.
int PlotLayout::pixel_x(double x) const {
  return to_pixel(left_px + 0.5 + axis_fraction(x, x_min, x_max, log_x) * (width_px - 1));
}

int PlotLayout::pixel_y(double y) const {
  return to_pixel(top_px + 0.5 + (1.0 - axis_fraction(y, y_min, y_max, log_y)) * (height_px - 1));
}

Rgb series_colour(int i) {
  // Tableau 10 (matplotlib's default cycle): distinct hues, all dark enough to read on white.
  static constexpr std::array<Rgb, 10> palette = {{{31, 119, 180},
                                                   {255, 127, 14},
                                                   {44, 160, 44},
                                                   {214, 39, 40},
                                                   {148, 103, 189},
                                                   {140, 86, 75},
                                                   {227, 119, 194},
                                                   {127, 127, 127},
                                                   {188, 189, 34},
                                                   {23, 190, 207}}};
  const int n = static_cast<int>(palette.size());
  return palette[static_cast<std::size_t>(((i % n) + n) % n)];
}

namespace {

// ---- Data -------------------------------------------------------------------------------------

bool drawable(double value, bool log) { return std::isfinite(value) && (!log || value > 0); }

void check_series(const PlotSeries& s, std::size_t i) {
  const std::string which = "render_line_plot: series " + std::to_string(i) + " (\"" + s.label + "\")";
  if (s.x.size() != s.y.size())
    throw InvalidInput(which + " has " + std::to_string(s.x.size()) + " x but " + std::to_string(s.y.size()) +
                       " y values");
  if (!s.point_labels.empty() && s.point_labels.size() != s.x.size())
    throw InvalidInput(which + " has " + std::to_string(s.point_labels.size()) + " point labels for " +
                       std::to_string(s.x.size()) + " points");
}

std::vector<DataPoint> drawable_points(const PlotSeries& s, const PlotOptions& options) {
  std::vector<DataPoint> points;
  bool previous_drawn = false;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const bool drawn = drawable(s.x[i], options.log_x) && drawable(s.y[i], options.log_y);
    if (drawn) points.push_back({s.x[i], s.y[i], i, previous_drawn});
    previous_drawn = drawn;
  }
  return points;
}

/// The smallest and largest axis-space coordinate of the points (`of_x` picks x or y).
AxisRange data_extent(const std::vector<std::vector<DataPoint>>& points, bool of_x, bool log) {
  AxisRange r{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), log};
  for (const auto& series : points)
    for (const DataPoint& p : series) {
      const double v = of_x ? p.x : p.y;
      const double t = log ? std::log10(v) : v;
      r.lo = std::min(r.lo, t);
      r.hi = std::max(r.hi, t);
    }
  return r;
}

/// Widens a range with no extent (one value, or values equal to within rounding) so that it can be
/// mapped, then pads it by 5 % either side so that no point sits on the frame.
AxisRange padded(AxisRange r, const char* axis_name) {
  const double centre = 0.5 * (r.lo + r.hi);
  if (r.hi - r.lo <= 1e-12 * std::max(std::abs(r.lo), std::abs(r.hi))) {
    const double half = r.log ? 0.5 : (centre == 0 ? 1.0 : 0.1 * std::abs(centre));
    r.lo = centre - half;
    r.hi = centre + half;
  }
  const double span = r.hi - r.lo;
  if (!std::isfinite(span))
    throw InvalidInput(std::string("render_line_plot: the ") + axis_name + " values span too wide a range to plot");
  r.lo -= 0.05 * span;
  r.hi += 0.05 * span;
  if (r.log) {  // keep both ends representable as doubles (10^t neither 0 nor infinite)
    r.lo = std::max(r.lo, -307.0);
    r.hi = std::min(r.hi, 308.0);
  }
  return r;
}

// ---- Ticks ------------------------------------------------------------------------------------

/// printf's %g with `significant` digits, its exponent shortened: 1e+06 → 1e6, 1e-05 → 1e-5.
std::string compact_number(double value, int significant) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  std::string text = buffer;
  const std::size_t e = text.find('e');
  if (e == std::string::npos) return text;
  std::string mantissa = text.substr(0, e), exponent = text.substr(e + 1);
  const bool negative = exponent.front() == '-';
  exponent.erase(0, exponent.find_first_not_of("+-0"));
  return mantissa + "e" + (negative ? "-" : "") + (exponent.empty() ? "0" : exponent);
}

/// The smallest 1, 2 or 5 × 10^k at least span / (most - 1) apart, so that at most `most` ticks
/// fit in `span`.
double nice_step(double span, int most) {
  const double raw = span / std::max(1, most - 1);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double mantissa : {1.0, 2.0, 5.0})
    if (mantissa * decade >= raw * (1 - 1e-12)) return mantissa * decade;
  return 10 * decade;
}

/// Multiples of a nice step in [lo, hi], labelled with just enough digits to tell them apart.
std::vector<Tick> linear_ticks(double lo, double hi, int most) {
  const double step = nice_step(hi - lo, most);
  const auto first = static_cast<long long>(std::ceil(lo / step));
  const auto last = static_cast<long long>(std::floor(hi / step));
  const double largest = std::max(std::abs(lo), std::abs(hi));
  // Digits from the largest value's leading one down to the step's (steps are m × 10^k, m < 10).
  const int significant =
      std::clamp(static_cast<int>(std::floor(std::log10(largest)) - std::floor(std::log10(step) + 1e-9)) + 1, 1, 15);
  std::vector<Tick> ticks;
  for (long long i = first; i <= last && ticks.size() <= static_cast<std::size_t>(most); ++i) {
    const double value = static_cast<double>(i) * step;
    ticks.push_back({value, compact_number(value, significant)});
  }
  return ticks;
}

/// Every m × 10^k in [10^lo, 10^hi] for the given mantissas m (1 alone: the powers of ten).
std::vector<Tick> mantissa_ticks(double lo, double hi, std::initializer_list<double> mantissas) {
  std::vector<Tick> ticks;
  for (auto k = static_cast<long long>(std::floor(lo)); k <= static_cast<long long>(std::ceil(hi)); ++k)
    for (double m : mantissas) {
      const double t = static_cast<double>(k) + std::log10(m);
      if (t >= lo && t <= hi) ticks.push_back({m * std::pow(10.0, static_cast<double>(k)), {}});
    }
  return ticks;
}

/// Every stride-th power of ten in [10^lo, 10^hi], the stride the smallest that leaves at most
/// `most`; multiples of the stride, so that 10^0 stays a tick.
std::vector<Tick> decade_ticks(double lo, double hi, int most) {
  const auto first = static_cast<long long>(std::ceil(lo)), last = static_cast<long long>(std::floor(hi));
  const long long stride = std::max(1LL, (last - first + most - 2) / std::max(1, most - 1));  // ceil division
  std::vector<Tick> ticks;
  for (long long k = first; k <= last; ++k)
    if (((k % stride) + stride) % stride == 0) ticks.push_back({std::pow(10.0, static_cast<double>(k)), {}});
  return ticks;
}

/// Ticks for a log axis over [10^lo, 10^hi]: powers of ten when the range holds at least two, else
/// 1, 2, 5 × 10^k, else 1 … 9 × 10^k, else (a range narrower than from one digit to the next)
/// nice linear ticks, whose positions still follow the log mapping. Labels are %g with six digits,
/// so 10 reads "10", not "1e1", and only very large or small values use an exponent.
std::vector<Tick> log_ticks(double lo, double hi, int most) {
  std::vector<Tick> ticks = decade_ticks(lo, hi, most);
  if (ticks.size() < 2) ticks = mantissa_ticks(lo, hi, {1, 2, 5});
  if (ticks.size() < 2) ticks = mantissa_ticks(lo, hi, {1, 2, 3, 4, 5, 6, 7, 8, 9});
  if (ticks.size() < 2 || ticks.size() > static_cast<std::size_t>(most))
    return linear_ticks(std::pow(10.0, lo), std::pow(10.0, hi), most);
  for (Tick& t : ticks) t.label = compact_number(t.value, 4);  // 1000, then 1e4: no six-digit labels
  return ticks;
}

std::vector<Tick> axis_ticks(const AxisRange& r, int most) {
  return r.log ? log_ticks(r.lo, r.hi, most) : linear_ticks(r.lo, r.hi, most);
}

/// The most ticks (up to max_ticks) whose labels do not collide, as judged by `fits`.
template <typename Fits>
std::vector<Tick> fitting_ticks(const AxisRange& r, Fits fits) {
  std::vector<Tick> ticks;
  for (int most = max_ticks; most >= 2; --most) {
    ticks = axis_ticks(r, most);
    if (fits(ticks)) break;
  }
  return ticks;
}

int widest_label_px(const std::vector<Tick>& ticks) {
  int widest = 0;
  for (const Tick& t : ticks) widest = std::max(widest, detail::text_width_px(t.label, font_scale));
  return widest;
}

// ---- Layout -----------------------------------------------------------------------------------

int line_height_px() { return detail::text_height_px(font_scale); }

/// Height of capitals and digits (the font's descender row left out), for centring labels.
int cap_height_px(int scale) { return 7 * scale; }  // text.hpp: capitals end 7 × scale below a line's top

void check_room(int plot_side_px, const PlotOptions& options) {
  if (plot_side_px < min_plot_side_px)
    throw InvalidInput("render_line_plot: " + std::to_string(options.width_px) + "x" +
                       std::to_string(options.height_px) + " px leaves no room for the plot area");
}

/// Plans the picture: the vertical layout first (it needs no ticks), then the y ticks (which need
/// the plot's height), the left margin (which needs their labels), and last the x ticks.
Canvas plan_canvas(const AxisRange& x, const AxisRange& y, const PlotOptions& options) {
  Canvas c;
  PlotLayout& l = c.layout;
  l.log_x = x.log;
  l.log_y = y.log;
  l.x_min = x.to_data(x.lo);
  l.x_max = x.to_data(x.hi);
  l.y_min = y.to_data(y.lo);
  l.y_max = y.to_data(y.hi);

  const int line = line_height_px();
  c.title_y = padding_px;
  c.y_label_y = c.title_y + (options.title.empty() ? 0 : line + padding_px);
  l.top_px = c.y_label_y + (options.y_label.empty() ? 0 : line + 6) + line / 2;  // half a line: top tick label
  const int bottom_margin = tick_length_px + tick_gap_px + line + (options.x_label.empty() ? 0 : 6 + line) + padding_px;
  l.height_px = options.height_px - l.top_px - bottom_margin;
  c.x_label_y = l.top_px + l.height_px + tick_length_px + tick_gap_px + line + 6;
  check_room(l.height_px, options);

  c.y_ticks = fitting_ticks(y, [&](const std::vector<Tick>& ticks) {
    for (std::size_t i = 1; i < ticks.size(); ++i)
      if (std::abs(l.pixel_y(ticks[i].value) - l.pixel_y(ticks[i - 1].value)) < line + 4) return false;
    return true;
  });
  l.left_px = padding_px + widest_label_px(c.y_ticks) + tick_gap_px + tick_length_px;
  l.width_px = options.width_px - l.left_px - 2 * padding_px;  // the last x label may overhang a little
  check_room(l.width_px, options);

  c.x_ticks = fitting_ticks(x, [&](const std::vector<Tick>& ticks) {
    for (std::size_t i = 1; i < ticks.size(); ++i) {
      const int needed =
          (detail::text_width_px(ticks[i].label, font_scale) + detail::text_width_px(ticks[i - 1].label, font_scale)) /
              2 +
          12;
      if (std::abs(l.pixel_x(ticks[i].value) - l.pixel_x(ticks[i - 1].value)) < needed) return false;
    }
    return true;
  });
  return c;
}

// ---- Drawing primitives -----------------------------------------------------------------------

/// Bresenham's line, 2 px thick: each step also paints the next pixel across the line's main
/// direction (below for flat lines, to the right for steep ones).
void draw_line(Image& image, int x0, int y0, int x1, int y1, Rgb colour) {
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  const bool flat = dx >= -dy;
  int error = dx + dy;
  for (;;) {
    image.set(x0, y0, colour);
    image.set(flat ? x0 : x0 + 1, flat ? y0 + 1 : y0, colour);
    if (x0 == x1 && y0 == y1) return;
    const int twice = 2 * error;
    if (twice >= dy) {
      error += dy;
      x0 += sx;
    }
    if (twice <= dx) {
      error += dx;
      y0 += sy;
    }
  }
}

void fill_rect(Image& image, int x, int y, int width, int height, Rgb colour) {
  for (int row = y; row < y + height; ++row)
    for (int col = x; col < x + width; ++col) image.set(col, row, colour);
}

/// A 1 px outline just outside the rectangle [x, x + width) × [y, y + height).
void outline_rect(Image& image, int x, int y, int width, int height, Rgb colour) {
  for (int col = x - 1; col <= x + width; ++col) {
    image.set(col, y - 1, colour);
    image.set(col, y + height, colour);
  }
  for (int row = y; row < y + height; ++row) {
    image.set(x - 1, row, colour);
    image.set(x + width, row, colour);
  }
}

void draw_marker(Image& image, int x, int y, Rgb colour) {
  // r² + 1 rather than r²: a rounder disc, without the lone pixels at the four extremes.
  constexpr int reach = marker_radius_px * marker_radius_px + 1;
  for (int dy = -marker_radius_px; dy <= marker_radius_px; ++dy)
    for (int dx = -marker_radius_px; dx <= marker_radius_px; ++dx)
      if (dx * dx + dy * dy <= reach) image.set(x + dx, y + dy, colour);
}

/// Text centred on column `centre_x`, shifted sideways as needed to stay inside the image.
void draw_text_centred(Image& image, int centre_x, int y, const std::string& text, Rgb colour) {
  const int width = detail::text_width_px(text, font_scale);
  const int x = std::clamp(centre_x - width / 2, 0, std::max(0, image.width() - width));
  detail::draw_text(image, x, y, text, colour, font_scale);
}

// ---- Axes -------------------------------------------------------------------------------------

void draw_grid(Image& image, const Canvas& c) {
  const PlotLayout& l = c.layout;
  for (const Tick& t : c.x_ticks) fill_rect(image, l.pixel_x(t.value), l.top_px, 1, l.height_px, grid_colour);
  for (const Tick& t : c.y_ticks) fill_rect(image, l.left_px, l.pixel_y(t.value), l.width_px, 1, grid_colour);
}

void draw_x_axis(Image& image, const Canvas& c) {
  const PlotLayout& l = c.layout;
  const int bottom = l.top_px + l.height_px;  // the frame's row
  for (const Tick& t : c.x_ticks) {
    const int x = l.pixel_x(t.value);
    fill_rect(image, x, bottom + 1, 1, tick_length_px, frame_colour);
    draw_text_centred(image, x, bottom + 1 + tick_length_px + tick_gap_px, t.label, text_colour);
  }
}

void draw_y_axis(Image& image, const Canvas& c) {
  const PlotLayout& l = c.layout;
  const int left = l.left_px - 1;  // the frame's column
  for (const Tick& t : c.y_ticks) {
    const int y = l.pixel_y(t.value);
    fill_rect(image, left - tick_length_px, y, tick_length_px, 1, frame_colour);
    const int width = detail::text_width_px(t.label, font_scale);
    detail::draw_text(image, left - tick_length_px - tick_gap_px - width, y - cap_height_px(font_scale) / 2, t.label,
                      text_colour, font_scale);
  }
}

void draw_axes(Image& image, const Canvas& c) {
  const PlotLayout& l = c.layout;
  draw_grid(image, c);
  outline_rect(image, l.left_px, l.top_px, l.width_px, l.height_px, frame_colour);
  draw_x_axis(image, c);
  draw_y_axis(image, c);
}

void draw_labels(Image& image, const Canvas& c, const PlotOptions& options) {
  const PlotLayout& l = c.layout;
  if (!options.title.empty()) draw_text_centred(image, image.width() / 2, c.title_y, options.title, text_colour);
  if (!options.y_label.empty())
    detail::draw_text(image, padding_px, c.y_label_y, options.y_label, text_colour, font_scale);
  if (!options.x_label.empty())
    draw_text_centred(image, l.left_px + l.width_px / 2, c.x_label_y, options.x_label, text_colour);
}

// ---- Series -----------------------------------------------------------------------------------

void draw_polyline(Image& image, const PlotLayout& l, const std::vector<DataPoint>& points, Rgb colour) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const DataPoint& to = points[i];
    // A point joined to nothing is drawn as a zero-length line, so it shows even without markers.
    const DataPoint& from = to.joins_previous ? points[i - 1] : to;
    draw_line(image, l.pixel_x(from.x), l.pixel_y(from.y), l.pixel_x(to.x), l.pixel_y(to.y), colour);
  }
}

void draw_point_labels(Image& image, const PlotLayout& l, const PlotSeries& s, const std::vector<DataPoint>& points) {
  if (s.point_labels.empty()) return;
  for (const DataPoint& p : points)  // above and to the right, clear of the marker
    detail::draw_text(image, l.pixel_x(p.x) + marker_radius_px + 2,
                      l.pixel_y(p.y) - marker_radius_px - 1 - cap_height_px(point_font_scale), s.point_labels[p.index],
                      s.colour, point_font_scale);
}

void draw_series(Image& image, const PlotLayout& l, const PlotSeries& s, const std::vector<DataPoint>& points) {
  draw_polyline(image, l, points, s.colour);
  if (s.markers)
    for (const DataPoint& p : points) draw_marker(image, l.pixel_x(p.x), l.pixel_y(p.y), s.colour);
  draw_point_labels(image, l, s, points);
}

// ---- Legend -----------------------------------------------------------------------------------

struct Box {
  int x = 0, y = 0, width = 0, height = 0;
};

constexpr int legend_inset_px = 6;  ///< between the legend's edge and its content, and the frame

int legend_row_px() { return line_height_px() + 4; }

std::vector<const PlotSeries*> legend_entries(const std::vector<PlotSeries>& series) {
  std::vector<const PlotSeries*> entries;
  for (const PlotSeries& s : series)
    if (!s.label.empty()) entries.push_back(&s);
  return entries;
}

/// Pixels in `box` that something has been drawn on (anything but the background and the grid).
int ink_in(const Image& image, const Box& box) {
  int count = 0;
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x = box.x; x < box.x + box.width; ++x) {
      if (x < 0 || y < 0 || x >= image.width() || y >= image.height()) continue;
      const Rgb colour = image.get(x, y);
      if (colour != white && colour != grid_colour) ++count;
    }
  return count;
}

/// The legend's place: the plot area's corner where it would hide the fewest drawn pixels (ties go
/// to the first of top right, top left, bottom right, bottom left). Chosen after the series are
/// drawn, so lines count as well as points.
Box place_legend(const Image& image, const PlotLayout& l, int width, int height) {
  const int left = l.left_px + legend_inset_px, right = l.left_px + l.width_px - legend_inset_px - width;
  const int top = l.top_px + legend_inset_px, bottom = l.top_px + l.height_px - legend_inset_px - height;
  const std::array<Box, 4> corners = {{{right, top, width, height},
                                       {left, top, width, height},
                                       {right, bottom, width, height},
                                       {left, bottom, width, height}}};
  Box best = corners[0];
  int least = ink_in(image, best);
  for (std::size_t i = 1; i < corners.size(); ++i)
    if (const int ink = ink_in(image, corners[i]); ink < least) {
      least = ink;
      best = corners[i];
    }
  return best;
}

void draw_legend(Image& image, const PlotLayout& l, const std::vector<PlotSeries>& series) {
  const std::vector<const PlotSeries*> entries = legend_entries(series);
  if (entries.empty()) return;
  int widest = 0;
  for (const PlotSeries* s : entries) widest = std::max(widest, detail::text_width_px(s->label, font_scale));
  const int width = 2 * legend_inset_px + legend_line_px + 6 + widest;
  const int height = 2 * legend_inset_px + static_cast<int>(entries.size()) * legend_row_px() - 4;
  const Box box = place_legend(image, l, width, height);

  fill_rect(image, box.x, box.y, box.width, box.height, white);
  outline_rect(image, box.x, box.y, box.width, box.height, frame_colour);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const int row_y = box.y + legend_inset_px + static_cast<int>(i) * legend_row_px();
    const int mid_y = row_y + cap_height_px(font_scale) / 2;
    const int line_x = box.x + legend_inset_px;
    draw_line(image, line_x, mid_y, line_x + legend_line_px, mid_y, entries[i]->colour);
    if (entries[i]->markers) draw_marker(image, line_x + legend_line_px / 2, mid_y, entries[i]->colour);
    detail::draw_text(image, line_x + legend_line_px + 6, row_y, entries[i]->label, text_colour, font_scale);
  }
}

}  // namespace

Image render_line_plot(const std::vector<PlotSeries>& series, const PlotOptions& options, PlotLayout* layout) {
  options.validate();
  std::vector<std::vector<DataPoint>> points;
  std::size_t drawn = 0;
  for (std::size_t i = 0; i < series.size(); ++i) {
    check_series(series[i], i);
    points.push_back(drawable_points(series[i], options));
    drawn += points.back().size();
  }
  if (drawn == 0)
    throw InvalidInput("render_line_plot: no series has a point to draw (finite, and positive on a log axis)");
  const AxisRange x = padded(data_extent(points, true, options.log_x), "x");
  const AxisRange y = padded(data_extent(points, false, options.log_y), "y");
  const Canvas canvas = plan_canvas(x, y, options);

  Image image(options.width_px, options.height_px, white);
  draw_axes(image, canvas);
  for (std::size_t i = 0; i < series.size(); ++i) draw_series(image, canvas.layout, series[i], points[i]);
  draw_legend(image, canvas.layout, series);
  draw_labels(image, canvas, options);
  if (layout) *layout = canvas.layout;
  return image;
}

void PlotOptions::validate() const {
  option_check::within("PlotOptions", "width_px", width_px, 1, 16384);
  option_check::within("PlotOptions", "height_px", height_px, 1, 16384);
}
}  // namespace emit
