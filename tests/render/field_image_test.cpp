// Rendering: PNG input/output (exact, atomic), the colour map, and pictures of fields on a mesh.
#include "emit/render/field_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/render/image.hpp"
#include "picture_checks.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace fs = std::filesystem;

double luminance(Rgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

testing::AssertionResult colours_near(Rgb actual, Rgb expected, int tolerance) {
  const int worst =
      std::max({std::abs(actual.r - expected.r), std::abs(actual.g - expected.g), std::abs(actual.b - expected.b)});
  if (worst <= tolerance) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "colour (" << int(actual.r) << ", " << int(actual.g) << ", " << int(actual.b)
                                     << ") differs from (" << int(expected.r) << ", " << int(expected.g) << ", "
                                     << int(expected.b) << ") by " << worst << " > " << tolerance;
}

/// Every pixel a different colour, so a swapped channel, row or stride would show.
Image test_pattern(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.set(x, y, {std::uint8_t(x * 37 + y), std::uint8_t(y * 53 + 7), std::uint8_t((x * y * 11) ^ 0xA5)});
  return image;
}

std::size_t files_in(const std::string& folder) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

/// A 10 mm × 10 mm sheet of 4×4 cells with one electrode in the middle of each side (the middle
/// three nodes of the side): bottom, right, top, left.
Mesh square_sheet() {
  Mesh mesh = test::strip_mesh(10, 10, 4, 4);  // node (i, j) is j * 5 + i
  mesh.electrode_nodes = {{1, 2, 3}, {9, 14, 19}, {21, 22, 23}, {5, 10, 15}};
  return mesh;
}

Rgb pixel_at(const Image& image, const FieldLayout& layout, double x_mm, double y_mm) {
  return image.get(layout.pixel_x(x_mm), layout.pixel_y(y_mm));
}

// The picture samples the field at pixel centres, which lie within half a pixel (≈ 0.013 mm at
// this size, i.e. a t error ≈ 0.0013) of the requested point; the map's steepest channel changes
// by < 700 units per unit t, so that is < 1 unit, plus 0.5 for rounding each colour to 8 bits.
constexpr int pixel_quantisation_tolerance = 2;

TEST(Png, RoundTripIsExact) {
  const std::string folder = test::temp_folder("png_round_trip");
  const Image original = test_pattern(7, 5);  // odd width: rows are not 4-byte aligned
  write_png(original, folder + "/pattern.png");
  const Image back = read_png(folder + "/pattern.png");
  EXPECT_EQ(back.width(), 7);
  EXPECT_EQ(back.height(), 5);
  EXPECT_EQ(back.rgb(), original.rgb());
  fs::remove_all(folder);
}

TEST(Png, WritingIntoAMissingFolderThrowsAndCreatesNothing) {
  const std::string folder = test::temp_folder("png_missing_folder");
  const std::string path = folder + "/no_such_folder/out.png";
  try {
    write_png(test_pattern(4, 4), path);
    FAIL() << "expected IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(folder + "/no_such_folder"));
  EXPECT_EQ(files_in(folder), 0u);
  fs::remove_all(folder);
}

// libpng refuses images wider than 1,000,000 px, so this write fails inside the encoder, after
// the temporary file was opened: the old file must survive and the temporary file must go.
TEST(Png, AFailedWriteLeavesTheOldFileIntact) {
  const std::string folder = test::temp_folder("png_failed_write");
  const std::string path = folder + "/frame.png";
  const Image good = test_pattern(6, 3);
  write_png(good, path);
  try {
    write_png(Image(1'000'001, 1), path);
    FAIL() << "expected IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_png(path).rgb(), good.rgb());
  EXPECT_EQ(files_in(folder), 1u);
  fs::remove_all(folder);
}

TEST(Png, ReadingAMissingOrNonPngFileThrowsNamingIt) {
  const std::string folder = test::temp_folder("png_bad_read");
  const std::string missing = folder + "/missing.png", text = folder + "/text.png";
  std::ofstream(text) << "this is not a PNG file\n";
  for (const std::string& path : {missing, text}) {
    try {
      read_png(path);
      ADD_FAILURE() << "expected IoError for " << path;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
  fs::remove_all(folder);
}

TEST(RenderImage, WritesOutsideTheImageAreIgnored) {
  Image image(3, 2, {1, 2, 3});
  image.set(-1, 0, {9, 9, 9});
  image.set(3, 0, {9, 9, 9});
  image.set(0, 2, {9, 9, 9});
  for (std::size_t i = 0; i < image.rgb().size(); ++i) EXPECT_EQ(image.rgb()[i], 1 + i % 3);
  EXPECT_THROW(Image(0, 5), InvalidInput);
}

TEST(Colormap, LuminanceRisesStrictlyFromDarkToBright) {
  double previous = luminance(colormap(0.0));
  for (int i = 1; i <= 50; ++i) {
    const double current = luminance(colormap(i / 50.0));
    EXPECT_GT(current, previous) << "t = " << i / 50.0;
    previous = current;
  }
  EXPECT_NE(colormap(0.0), colormap(1.0));
}

TEST(Colormap, RunsFromDarkPurpleToYellowAndClamps) {
  const Rgb low = colormap(0.0), high = colormap(1.0);
  EXPECT_GT(low.b, low.g);  // purple: blue and red over green
  EXPECT_GT(low.r, low.g);
  EXPECT_LT(luminance(low), 40);
  EXPECT_GT(high.r, 200);  // yellow: red and green over blue
  EXPECT_GT(high.g, 200);
  EXPECT_LT(high.b, 80);
  EXPECT_EQ(colormap(-3), low);
  EXPECT_EQ(colormap(7), high);
}

// u = x is linear, and so is the picture's interpolation inside each triangle: the colour at x is
// the map at (x − min)/(max − min), up to where the pixel centre falls.
TEST(RenderField, LinearFieldFollowsTheColourMap) {
  const Mesh mesh = square_sheet();
  const Vector u = mesh.nodes_mm.col(0);
  FieldImageOptions options;
  options.title = "u = x";
  options.unit = "mm";
  FieldLayout layout;
  const Image image = render_field(mesh, u, {}, options, &layout);
  EXPECT_EQ(image.width(), options.width_px);
  const Rgb left = pixel_at(image, layout, 2, 5), right = pixel_at(image, layout, 8, 5);
  EXPECT_TRUE(colours_near(left, colormap(0.2), pixel_quantisation_tolerance));
  EXPECT_TRUE(colours_near(right, colormap(0.8), pixel_quantisation_tolerance));
  EXPECT_TRUE(colours_near(pixel_at(image, layout, 4.4, 3.3), colormap(0.44), pixel_quantisation_tolerance));
  EXPECT_LT(luminance(left), luminance(right));
}

// The colour bar reads as a scale: besides its ends (with the unit), ticks at round values between
// them, each labelled (a field 0 to 1: 0.25, 0.5 and 0.75, whose text's dark pixels lie right of
// the bar at the rows those values take); and a scale bar below it: a dark horizontal line of a
// round length in mm (1, 2 or 5 × 10^k: 0.5 mm, 23 px, on this 10 mm sheet drawn 45 px/mm),
// labelled beside it.
TEST(RenderField, TheColourBarHasLabelledTicksAndAScaleBarIsBelow) {
  const Mesh mesh = square_sheet();
  FieldImageOptions options;
  options.min_value = 0;
  options.max_value = 1;
  options.unit = "N/mm2";
  FieldLayout layout;
  const Image image = render_field(mesh, mesh.nodes_mm.col(0) / 10, {}, options, &layout);
  const int labels_from = layout.pixel_x(10) + 40 + 18 + 6;  // the sheet, the margin, the bar, the gap
  const auto dark_in = [&](int x0, int x1, int y0, int y1) {
    int n = 0;
    for (int y = std::max(y0, 0); y <= std::min(y1, image.height() - 1); ++y)
      for (int x = std::max(x0, 0); x <= std::min(x1, image.width() - 1); ++x) n += luminance(image.get(x, y)) < 100;
    return n;
  };
  for (const double value : {0.25, 0.5, 0.75}) {
    const int row = layout.pixel_y(10 * value);  // the bar spans the sheet's height, its top the maximum
    EXPECT_GT(dark_in(labels_from, image.width() - 1, row - 6, row + 6), 15) << value << "'s label";
  }
  // No label between the ticks (0.375 lies halfway between two).
  const int between = layout.pixel_y(3.75);
  EXPECT_EQ(dark_in(labels_from, image.width() - 1, between - 2, between + 2), 0);
  // The scale bar: a row below the colour bar with a dark run of at least 40 pixels.
  int longest = 0;
  for (int y = layout.pixel_y(0) + 1; y < image.height(); ++y) {
    int run = 0;
    for (int x = labels_from - 24; x < image.width(); ++x) {
      run = luminance(image.get(x, y)) < 100 ? run + 1 : 0;
      longest = std::max(longest, run);
    }
  }
  // Its length, in mm at the picture's scale, is a round one (within its two end pixels).
  EXPECT_LE(test::px_from_round_length(longest, layout.scale_px_per_mm), 2.0 + 1e-9) << longest << " px";
  EXPECT_GE(longest, 20);
}

// Axes in mm along the sheet (10 × 10 mm: ticks 2.5 mm apart): under it a dark line as long as
// the sheet with a value under its ticks at 0, 5 and 10 mm and "mm" after the last; left of it
// another as tall, values beside its ticks; none between two ticks.
TEST(RenderField, MmAxesAreTickedAndLabelled) {
  const Mesh mesh = square_sheet();
  FieldLayout layout;
  const Image image = render_field(mesh, mesh.nodes_mm.col(0) / 10, {}, FieldImageOptions{}, &layout);
  const auto dark = [&](int x, int y) { return luminance(image.get(x, y)) < 100; };
  const auto dark_in = [&](int x0, int x1, int y0, int y1) {
    int n = 0;
    for (int y = std::max(y0, 0); y <= std::min(y1, image.height() - 1); ++y)
      for (int x = std::max(x0, 0); x <= std::min(x1, image.width() - 1); ++x) n += dark(x, y);
    return n;
  };
  const int x0 = layout.pixel_x(0), x10 = layout.pixel_x(10), y0 = layout.pixel_y(0), y10 = layout.pixel_y(10);
  int axis_row = -1;  // below the electrode numbers' margin
  for (int y = y0 + 20; y < image.height() && axis_row < 0; ++y)
    if (dark_in(x0 + 1, x10 - 1, y, y) >= x10 - x0 - 1) axis_row = y;
  ASSERT_GE(axis_row, 0) << "no x axis under the sheet";
  for (const double v : {0.0, 5.0, 10.0})
    EXPECT_GT(dark_in(layout.pixel_x(v) - 8, layout.pixel_x(v) + 8, axis_row + 6, axis_row + 20), 5)
        << v << " mm's label";
  EXPECT_EQ(dark_in(layout.pixel_x(3.75) - 1, layout.pixel_x(3.75) + 1, axis_row + 6, axis_row + 20), 0);
  EXPECT_GT(dark_in(x10 + 12, x10 + 40, axis_row + 6, axis_row + 20), 10) << "the unit after the last value";
  int axis_column = -1;  // left of the electrode numbers' margin
  for (int x = x0 - 20; x >= 0 && axis_column < 0; --x)
    if (dark_in(x, x, y10 + 1, y0 - 1) >= y0 - y10 - 1) axis_column = x;
  ASSERT_GE(axis_column, 0) << "no y axis left of the sheet";
  for (const double v : {0.0, 5.0, 10.0})
    EXPECT_GT(dark_in(0, axis_column - 5, layout.pixel_y(v) - 6, layout.pixel_y(v) + 6), 5) << v << " mm's label";
  EXPECT_EQ(dark_in(0, axis_column - 5, layout.pixel_y(3.75) - 1, layout.pixel_y(3.75) + 1), 0);
}

// A mark's label (a contact's id and force) is written up and right of it, white on a dark edge
// over the field: white pixels there with the label, none without; the mark's other sides clear.
TEST(RenderField, AMarksLabelIsWrittenBesideIt) {
  const Mesh mesh = square_sheet();
  FieldLayout layout;
  Circle mark{Vector2(3, 3), 1.0};
  const auto white_in = [&](const Image& image, double x0_mm, double x1_mm, double y0_mm, double y1_mm) {
    int n = 0;
    for (int y = layout.pixel_y(y1_mm); y <= layout.pixel_y(y0_mm); ++y)
      for (int x = layout.pixel_x(x0_mm); x <= layout.pixel_x(x1_mm); ++x) {
        const Rgb p = image.get(x, y);
        n += p.r > 230 && p.g > 230 && p.b > 230 ? 1 : 0;
      }
    return n;
  };
  const Vector field = Vector::Zero(mesh.node_count());  // the map's darkest colour everywhere
  const Image plain = render_field(mesh, field, {mark}, {}, &layout);
  mark.label = "#7  12.5 N";
  const Image labelled = render_field(mesh, field, {mark}, {}, &layout);
  EXPECT_EQ(white_in(plain, 3.9, 9.5, 3.75, 4.5), 0);
  EXPECT_GT(white_in(labelled, 3.9, 9.5, 3.75, 4.5), 100) << "the label's white text";
  EXPECT_EQ(white_in(labelled, 0.2, 1.6, 0.2, 1.6), 0) << "down and left of the mark: nothing";
}

TEST(RenderField, ExplicitRangeIsUsedAndUniformFieldsAreOneColour) {
  const Mesh mesh = square_sheet();
  FieldLayout layout;
  const Image uniform = render_field(mesh, Vector::Constant(mesh.node_count(), 1.5), {}, {}, &layout);
  for (double x : {1.0, 5.0, 9.0})
    for (double y : {1.0, 5.0, 9.0}) EXPECT_EQ(pixel_at(uniform, layout, x, y), colormap(0.5)) << x << ", " << y;

  FieldImageOptions options;
  options.min_value = 0;
  options.max_value = 20;
  const Image ranged = render_field(mesh, mesh.nodes_mm.col(0), {}, options, &layout);
  EXPECT_TRUE(colours_near(pixel_at(ranged, layout, 8, 5), colormap(0.4), pixel_quantisation_tolerance));
}

TEST(RenderField, CircleOutlineIsWhiteAroundTheFieldColour) {
  const Mesh mesh = square_sheet();
  FieldLayout layout;
  const Image image = render_field(mesh, mesh.nodes_mm.col(0), {{Vector2(5, 5), 2.0}}, {}, &layout);
  for (const Rgb edge : {pixel_at(image, layout, 7, 5), pixel_at(image, layout, 5, 3), pixel_at(image, layout, 3, 5)}) {
    EXPECT_GE(edge.r, 230);
    EXPECT_GE(edge.g, 230);
    EXPECT_GE(edge.b, 230);
  }
  EXPECT_TRUE(colours_near(pixel_at(image, layout, 5, 5), colormap(0.5), pixel_quantisation_tolerance));
  // An outline, not a disc: halfway to the edge the field shows through.
  EXPECT_TRUE(colours_near(pixel_at(image, layout, 6, 5), colormap(0.6), pixel_quantisation_tolerance));
}

TEST(RenderField, ElectrodesAreThickOrangeLinesWithNumbersOutside) {
  const Mesh mesh = square_sheet();
  FieldLayout layout;
  const Image image = render_field(mesh, mesh.nodes_mm.col(0), {}, {}, &layout);
  auto orange = [](Rgb c) { return c.r > 150 && c.g > 50 && c.g < 150 && c.b < 60; };
  // Across the right-hand electrode (at x = 10 mm), along the row through its middle.
  const int row = layout.pixel_y(5), column = layout.pixel_x(10);
  EXPECT_TRUE(orange(image.get(column, row)));
  int thickness = 0;
  for (int x = column - 6; x <= column + 6; ++x) thickness += orange(image.get(x, row));
  EXPECT_GE(thickness, 3);
  EXPECT_LE(thickness, 4);
  // Its number "1" sits in the margin to the right: some dark text pixels there, none orange.
  int dark = 0;
  for (int y = row - 12; y <= row + 12; ++y)
    for (int x = column + 4; x <= column + 36; ++x) dark += luminance(image.get(x, y)) < 60;
  EXPECT_GT(dark, 10);
}

TEST(RenderField, HeightFollowsTheSheetsAspect) {
  const Vector3 stretch_y(1, 3, 1);
  Mesh tall = square_sheet();
  tall.nodes_mm = tall.nodes_mm * stretch_y.asDiagonal();
  const Image square_image = render_field(square_sheet(), Vector::Zero(25), {}, {});
  const Image tall_image = render_field(tall, Vector::Zero(25), {}, {});
  EXPECT_EQ(tall_image.width(), square_image.width());
  EXPECT_GT(tall_image.height(), 2 * square_image.height() - 100);  // margins do not scale
}

TEST(RenderField, RejectsValuesThatDoNotMatchTheMesh) {
  EXPECT_THROW(render_field(square_sheet(), Vector::Zero(7), {}, {}), InvalidInput);
}

}  // namespace
}  // namespace emit
