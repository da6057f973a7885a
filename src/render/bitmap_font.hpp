#pragma once
// A tiny built-in 5×7 bitmap font (plus a descender row): the labels' font where DejaVu Sans is
// missing (text.hpp), needing no font files or libraries. Covers digits, upper- and lower-case letters (both, since
// units such as mV and MV differ only in case), space, . - + , : ( ) / = % · ? _ and ² µ Ω for units; anything else
// draws as '?'.
#include <string>
#include <string_view>

#include "emit/render/image.hpp"

namespace emit::detail {

inline constexpr int glyph_width = 5;
inline constexpr int glyph_height = 8;  ///< 7 rows for capitals and digits, 1 for descenders

/// Width in pixels of `utf8` drawn at `scale` (glyphs one blank font column apart).
int bitmap_text_width_px(std::string_view utf8, int scale);

/// Draws `utf8` with its top-left corner at (x, y), each font pixel a scale×scale block. Parts
/// outside the image are clipped.
void draw_bitmap_text(Image& image, int x, int y, std::string_view utf8, Rgb colour, int scale);

/// Code points of a UTF-8 string; malformed bytes become U+FFFD.
std::u32string decode_utf8(std::string_view text);

}  // namespace emit::detail
