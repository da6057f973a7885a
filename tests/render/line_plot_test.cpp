// Line plots: the axis mapping (linear and log) puts each curve where its data say, points that
// cannot be drawn are skipped, bad input is refused, and the picture survives a PNG round trip.
#include "emit/render/line_plot.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/render/image.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

/// Whether `colour` appears in the (2 radius + 1)² square of pixels centred on (x, y).
testing::AssertionResult colour_near(const Image& image, int x, int y, Rgb colour, int radius) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const int px = x + dx, py = y + dy;
      if (px >= 0 && py >= 0 && px < image.width() && py < image.height() && image.get(px, py) == colour)
        return testing::AssertionSuccess() << "found at (" << px << ", " << py << ")";
    }
  return testing::AssertionFailure() << "no pixel of colour (" << int(colour.r) << ", " << int(colour.g) << ", "
                                     << int(colour.b) << ") within " << radius << " px of (" << x << ", " << y << ")";
}

/// A series without a label (so no legend is drawn over it) and without markers (so the line
/// itself is what the tests see).
PlotSeries bare_series(std::vector<double> x, std::vector<double> y) {
  PlotSeries s;
  s.x = std::move(x);
  s.y = std::move(y);
  s.colour = series_colour(3);
  s.markers = false;
  return s;
}

TEST(LinePlot, StraightLineOnLinearAxesRunsAlongTheDiagonal) {
  const PlotSeries line = bare_series({0, 10}, {0, 10});
  PlotLayout layout;
  const Image image = render_line_plot({line}, PlotOptions{}, &layout);
  ASSERT_EQ(image.width(), 640);
  ASSERT_EQ(image.height(), 480);

  // The mapping is linear: 5 lies halfway between 0 and 10 (up to rounding to whole pixels).
  EXPECT_NEAR(layout.pixel_x(5), 0.5 * (layout.pixel_x(0) + layout.pixel_x(10)), 1.0);
  EXPECT_NEAR(layout.pixel_y(5), 0.5 * (layout.pixel_y(0) + layout.pixel_y(10)), 1.0);
  EXPECT_LT(layout.pixel_y(10), layout.pixel_y(0)) << "larger y must be higher up in the image";
  // 5 % padding keeps the ends off the frame.
  EXPECT_NEAR(layout.x_min, -0.5, 1e-9);
  EXPECT_NEAR(layout.x_max, 10.5, 1e-9);
  EXPECT_GT(layout.pixel_x(0), layout.left_px);
  EXPECT_LT(layout.pixel_y(0), layout.top_px + layout.height_px - 1);

  // Bresenham joins the two end pixels, so the drawn line is within 1 px of where each point of
  // y = x maps exactly...
  for (double t : {0.0, 1.0, 2.5, 5.0, 7.5, 9.0, 10.0})
    EXPECT_TRUE(colour_near(image, layout.pixel_x(t), layout.pixel_y(t), line.colour, 1)) << "at x = y = " << t;
  // ...and nowhere near points off the diagonal.
  EXPECT_FALSE(colour_near(image, layout.pixel_x(2), layout.pixel_y(8), line.colour, 5));
  EXPECT_FALSE(colour_near(image, layout.pixel_x(8), layout.pixel_y(2), line.colour, 5));
}

TEST(LinePlot, PowerLawIsAStraightLineOnLogAxes) {
  std::vector<double> x, y;
  for (int i = 1; i <= 100; ++i) {
    x.push_back(i);
    y.push_back(double(i) * i);
  }
  const PlotSeries parabola = bare_series(x, y);
  PlotOptions options;
  options.log_x = options.log_y = true;
  PlotLayout layout;
  const Image image = render_line_plot({parabola}, options, &layout);

  // log10(10) lies halfway between log10(1) and log10(100) (on a linear axis, 10 would be only 9 %
  // of the way), and log10(10²) halfway between log10(1²) and log10(100²).
  const double mid_x = 0.5 * (layout.pixel_x(1) + layout.pixel_x(100));
  const double mid_y = 0.5 * (layout.pixel_y(1) + layout.pixel_y(1e4));
  EXPECT_NEAR(layout.pixel_x(10), mid_x, 2.0);
  EXPECT_NEAR(layout.pixel_y(100), mid_y, 2.0);
  // So the drawn curve, straight in log-log, passes through the midpoint of its ends.
  EXPECT_TRUE(colour_near(image, int(std::lround(mid_x)), int(std::lround(mid_y)), parabola.colour, 2));
  EXPECT_FALSE(colour_near(image, int(std::lround(mid_x)), layout.pixel_y(10), parabola.colour, 5))
      << "where a linear y axis would put x = 10";
}

TEST(LinePlot, SkipsPointsItCannotDraw) {
  // On log axes: 0, a negative value, NaN and infinity cannot be placed, so the range comes from
  // 1 … 100 alone: 5 % of two decades either side.
  const PlotSeries s = bare_series({0, 1, -3, nan, 10, inf, 100}, {1, 1, 1, 1, 10, 1, 100});
  PlotOptions options;
  options.log_x = options.log_y = true;
  PlotLayout layout;
  EXPECT_NO_THROW(render_line_plot({s}, options, &layout));
  EXPECT_NEAR(std::log10(layout.x_min), -0.1, 1e-9);
  EXPECT_NEAR(std::log10(layout.x_max), 2.1, 1e-9);
}

TEST(LinePlot, SinglePointRangeIsWidenedAroundIt) {
  const PlotSeries s = bare_series({5}, {-2});
  PlotLayout layout;
  const Image image = render_line_plot({s}, PlotOptions{}, &layout);
  EXPECT_LT(layout.x_min, 5);
  EXPECT_GT(layout.x_max, 5);
  // Widened symmetrically, so the point sits in the middle of the plot area.
  EXPECT_NEAR(layout.pixel_x(5), layout.left_px + 0.5 * layout.width_px, 1.0);
  EXPECT_NEAR(layout.pixel_y(-2), layout.top_px + 0.5 * layout.height_px, 1.0);
  EXPECT_TRUE(colour_near(image, layout.pixel_x(5), layout.pixel_y(-2), s.colour, 0)) << "a lone point is drawn";
}

TEST(LinePlot, RefusesInvalidInput) {
  const PlotOptions linear;
  PlotOptions log = linear;
  log.log_y = true;
  EXPECT_THROW(render_line_plot({bare_series({1, 2, 3}, {1, 2})}, linear), InvalidInput) << "x and y sizes differ";
  EXPECT_THROW(render_line_plot({}, linear), InvalidInput) << "no series";
  EXPECT_THROW(render_line_plot({bare_series({}, {})}, linear), InvalidInput) << "no points";
  EXPECT_THROW(render_line_plot({bare_series({nan, 1, inf}, {1, nan, 2})}, linear), InvalidInput) << "no finite point";
  EXPECT_THROW(render_line_plot({bare_series({1, 2}, {0, -1})}, log), InvalidInput) << "nothing positive on a log axis";
  PlotSeries labelled = bare_series({1, 2}, {1, 2});
  labelled.point_labels = {"only one"};
  EXPECT_THROW(render_line_plot({labelled}, linear), InvalidInput) << "point labels do not match the points";
  PlotOptions tiny;
  tiny.width_px = 60;
  tiny.height_px = 40;
  EXPECT_THROW(render_line_plot({bare_series({1, 2}, {1, 2})}, tiny), InvalidInput) << "no room for a plot";
}

TEST(LinePlot, WritesAPngOfTheRequestedSize) {
  PlotSeries l_curve;
  l_curve.label = "L-curve";
  l_curve.colour = series_colour(0);
  l_curve.x = {0.02, 0.05, 0.1, 0.3, 1.0, 3.0};
  l_curve.y = {300, 40, 8, 4, 3, 2.5};
  l_curve.point_labels = {"1e-4", "1e-3", "1e-2", "1e-1", "1", "10"};
  PlotSeries other = bare_series({0.03, 2}, {100, 3});
  other.label = "other";
  PlotOptions options;
  options.width_px = 500;
  options.height_px = 300;
  options.title = "L-curve";
  options.x_label = "residual norm";
  options.y_label = "solution norm";
  options.log_x = options.log_y = true;
  const Image image = render_line_plot({l_curve, other}, options);

  const std::string folder = test::temp_folder("line_plot_png");
  write_png(image, folder + "/plot.png");
  const Image back = read_png(folder + "/plot.png");
  EXPECT_EQ(back.width(), 500);
  EXPECT_EQ(back.height(), 300);
  EXPECT_EQ(back.rgb(), image.rgb());
  std::filesystem::remove_all(folder);
}

TEST(LinePlot, PaletteCyclesAndAcceptsAnyIndex) {
  EXPECT_NE(series_colour(0), series_colour(1));
  EXPECT_EQ(series_colour(0), series_colour(10));
  EXPECT_EQ(series_colour(-1), series_colour(9));
}

}  // namespace
}  // namespace emit
