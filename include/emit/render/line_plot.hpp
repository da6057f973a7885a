#pragma once
/// \file line_plot.hpp
/// A small line-plot renderer for evaluation plots (an L-curve, an error against the
/// regularisation parameter): a framed plot area with grid, ticks and tick labels, linear or
/// logarithmic axes, one polyline (and optional markers and point labels) per series, a legend,
/// a title and axis labels. Text uses emit's built-in bitmap font (ASCII plus a few unit symbols).
#include <string>
#include <vector>

#include "emit/render/image.hpp"

namespace emit {

/// One curve: the points (x[i], y[i]) joined in the given order (not sorted by x, so a
/// parametric curve such as an L-curve draws as it should).
struct PlotSeries {
  std::string label;                      ///< its legend entry; empty: not in the legend
  std::vector<double> x, y;               ///< equal sizes
  Rgb colour{31, 119, 180};               ///< see series_colour() for a palette
  bool markers = true;                    ///< a filled dot on every drawn point
  std::vector<std::string> point_labels;  ///< empty, or one per point, drawn next to it
};

struct PlotOptions {
  int width_px = 640, height_px = 480;  ///< the whole image
  std::string title;                    ///< drawn at the top, centred
  std::string x_label;                  ///< drawn under the x axis' tick labels
  std::string y_label;                  ///< drawn above the y axis (the font cannot rotate)
  bool log_x = false, log_y = false;    ///< logarithmic axes, with decade ticks
  void validate() const;                ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// Where a data point (x, y) lands in the picture, for tests that check colours. The plot area is
/// the pixels [left_px, left_px + width_px) × [top_px, top_px + height_px); the axis ends
/// (x_min … x_max, y_min … y_max, in data units) map to the centres of its first and last pixels.
struct PlotLayout {
  int left_px = 0, top_px = 0, width_px = 1, height_px = 1;
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;
  bool log_x = false, log_y = false;
  /// The column / row of the pixel that a data coordinate falls in (x right, y up in the data,
  /// down in the image). Far-off values are clamped to ±1e6 px, NaN (e.g. log of a negative) to -1e6.
  int pixel_x(double x) const;
  int pixel_y(double y) const;
};

/// The i-th colour of a qualitative palette (Tableau 10), cycling after ten; any int is valid.
Rgb series_colour(int i);

/// Renders `series` into an options.width_px × options.height_px image.
///
/// Points with a non-finite coordinate, or (on a log axis) a coordinate ≤ 0, are skipped and break
/// their polyline there. The axis ranges span every drawn point with 5 % padding either side (of
/// the log10 range on log axes); a range with no extent is widened (by ±10 % of the value, ±1 at
/// 0, ±½ decade on log axes). Linear axes get "nice" ticks (1, 2 or 5 × 10^k apart), log axes
/// ticks at powers of ten (when the range holds fewer than two: at 1, 2, 5 × 10^k, then at
/// 1 … 9 × 10^k, then nice linear ones); fewer ticks are used if their labels would collide. Tick
/// labels are printf's %g with the exponent shortened (1e-05 → 1e-5). The legend (labelled series only) goes in
/// the plot area's corner where it hides the fewest drawn pixels. `layout`, if given, receives
/// the mapping from data to pixels.
///
/// \throw InvalidInput if a series' x and y (or non-empty point_labels) differ in size, if no
/// series has a drawable point, or if the image is too small to hold a plot area.
Image render_line_plot(const std::vector<PlotSeries>& series, const PlotOptions& options, PlotLayout* layout = nullptr);

}  // namespace emit
