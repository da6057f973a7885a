#pragma once
// The labels of rendered images, in a real font: DejaVu Sans (Debian's fonts-dejavu-core) drawn
// anti-aliased by FreeType. Where the font file is missing the built-in bitmap font draws instead
// (bitmap_font.hpp), so a picture is never lost for want of a font. The same metrics either way:
// a line `scale` × 8 pixels tall, its text's top at the given y.
#include <string_view>

#include "emit/render/image.hpp"

namespace emit::detail {

/// Width in pixels of `utf8` drawn at `scale`.
int text_width_px(std::string_view utf8, int scale);

/// Height in pixels of a line of text drawn at `scale`.
inline int text_height_px(int scale) { return 8 * scale; }

/// Draws `utf8` with its line's top-left corner at (x, y), blended over what is there. Parts
/// outside the image are clipped.
void draw_text(Image& image, int x, int y, std::string_view utf8, Rgb colour, int scale);

/// Whether the real font is drawn (its file was found and FreeType read it).
bool real_font();

}  // namespace emit::detail
