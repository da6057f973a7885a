// The built-in font (src/render/bitmap_font.hpp, a detail of render/): widths, UTF-8 decoding,
// and anything it has no glyph for, or cannot decode, drawn as '?'.
#include "../../src/render/bitmap_font.hpp"

#include <gtest/gtest.h>

namespace emit {
namespace {

using detail::bitmap_text_width_px;
using detail::draw_bitmap_text;

/// The pixels of `text` drawn black at scale 2 on a white 80 × 20 image.
std::vector<std::uint8_t> drawn(std::string_view text) {
  Image image(80, 20);
  draw_bitmap_text(image, 1, 1, text, {0, 0, 0}, 2);
  return image.rgb();
}

// Glyphs are 5 columns with one blank column between them: n glyphs are 6n − 1 font pixels wide.
TEST(BitmapFont, WidthIsSixColumnsAGlyphLessTheLastGap) {
  EXPECT_EQ(bitmap_text_width_px("", 3), 0);
  EXPECT_EQ(bitmap_text_width_px("ab", 1), 11);
  EXPECT_EQ(bitmap_text_width_px("ab", 3), 33);
  EXPECT_EQ(bitmap_text_width_px("\xC2\xB5V", 1), 11);  // µV: a two-byte character is one glyph
}

TEST(BitmapFont, UnknownAndMalformedCharactersDrawAsAQuestionMark) {
  const auto question = drawn("?");
  EXPECT_NE(drawn("A"), question);
  EXPECT_NE(drawn("\xC2\xB5"), question);          // µ has a glyph of its own
  EXPECT_EQ(drawn("\xE2\x82\xAC"), question);      // € (three bytes): no glyph
  EXPECT_EQ(drawn("\xF0\x9F\x98\x80"), question);  // an emoji (four bytes): no glyph
  EXPECT_EQ(drawn("\xFF"), question);              // a byte that starts no sequence
  EXPECT_EQ(drawn("\xC3"), question);              // a sequence cut short by the end
  EXPECT_EQ(drawn("\xC3"
                  "A"),
            drawn("?A"));  // or by a byte that does not continue it
  EXPECT_EQ(bitmap_text_width_px("\xC3"
                                 "A",
                                 1),
            11);
}

// Drawing past the image's edges clips: what is inside is drawn, nothing else changes.
TEST(BitmapFont, ClipsAtTheImageEdges) {
  Image image(4, 4);
  draw_bitmap_text(image, -2, -3, "WW", {0, 0, 0}, 1);
  int black = 0;
  for (std::uint8_t v : image.rgb()) black += v == 0;
  EXPECT_GT(black, 0);
  EXPECT_EQ(image.rgb().size(), 4u * 4 * 3);
}

}  // namespace
}  // namespace emit
