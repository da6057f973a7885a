// The labels' real font (src/render/text.hpp): DejaVu Sans through FreeType, as the pictures and
// plots draw every label. fonts-dejavu-core is one of emit's dependencies (scripts/install-deps.sh,
// the Debian package), so it is there: a picture with the bitmap font here is a fault.
#include "../../src/render/text.hpp"

#include <cstdlib>

#include <gtest/gtest.h>

namespace emit {
namespace {

using detail::draw_text;
using detail::text_width_px;

/// How many pixels of `text` drawn black at `scale` on white are black, and how many grey (the
/// anti-aliased edges a real font has and a bitmap font has not).
std::pair<int, int> black_and_grey(std::string_view text, int scale) {
  Image image(400, 60);
  draw_text(image, 4, 4, text, {0, 0, 0}, scale);
  int black = 0, grey = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const int v = image.get(x, y).r;
      black += v < 40 ? 1 : 0;
      grey += v >= 40 && v < 215 ? 1 : 0;
    }
  return {black, grey};
}

TEST(Text, LabelsAreDrawnInARealFont) {
  ASSERT_TRUE(detail::real_font()) << "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf (fonts-dejavu-core) missing";
  // Anti-aliased: edges of grey beside the black strokes.
  const auto [black, grey] = black_and_grey("0.25 N/mm\xC2\xB2 frame 12", 2);
  EXPECT_GT(black, 50);
  EXPECT_GT(grey, 50);
  // Proportional: an i is narrower than a W (the bitmap font's glyphs are all 6 columns).
  EXPECT_LT(2 * text_width_px("iiii", 2), text_width_px("WWWW", 2));
  // Its size follows the scale, and a line is 8 × scale tall as the layouts take it.
  EXPECT_NEAR(text_width_px("pressure", 4), 2 * text_width_px("pressure", 2), 2);
  EXPECT_EQ(detail::text_height_px(3), 24);
  EXPECT_EQ(text_width_px("", 2), 0);
}

// Drawn text stays within its line: from its top y, capitals and descenders within 8 × scale
// rows (a little more for the descender at most), never above it.
TEST(Text, AlineStaysInItsBox) {
  Image image(200, 60);
  const int top = 20, scale = 2;
  draw_text(image, 4, top, "Hgjpq|", {0, 0, 0}, scale);
  int lowest = -1, highest = image.height();
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (image.get(x, y).r < 215) lowest = std::max(lowest, y), highest = std::min(highest, y);
  EXPECT_GE(highest, top - 1);
  EXPECT_LE(lowest, top + detail::text_height_px(scale) + scale);
}

}  // namespace
}  // namespace emit
