// The labels' font (text.hpp): DejaVu Sans through FreeType, or the bitmap font without it.
#include "text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

#include <ft2build.h>
#include FT_FREETYPE_H

#include "bitmap_font.hpp"

namespace emit::detail {

namespace {

/// fonts-dejavu-core's file (a dependency of emit's package and of scripts/install-deps.sh).
constexpr const char* font_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// Capitals stand 6 × scale tall (DejaVu's cap height is 0.729 em) on a baseline 7 × scale below
/// the line's top, as the bitmap font's do within its 8-row line.
constexpr double em_per_scale = 6.0 / 0.729;
constexpr int baseline_per_scale = 7;

/// FreeType and the face, opened once; FreeType's objects are not thread-safe, so every use holds
/// the lock.
class Font {
 public:
  Font() {
    if (FT_Init_FreeType(&library_) != 0) return;
    if (FT_New_Face(library_, font_path, 0, &face_) != 0) face_ = nullptr;
  }
  ~Font() {
    if (face_ != nullptr) FT_Done_Face(face_);
    if (library_ != nullptr) FT_Done_FreeType(library_);
  }
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  bool usable() const { return face_ != nullptr; }

  using Draw = std::function<void(const FT_Bitmap&, int, int)>;

  /// Lays out `utf8` at `scale`, calling draw(glyph's bitmap, its left x, its top y) per glyph
  /// (nothing drawn when `draw` is empty); \return the advance in pixels.
  int lay_out(std::string_view utf8, int scale, const Draw& draw) {
    const std::lock_guard<std::mutex> lock(mutex_);
    FT_Set_Pixel_Sizes(face_, 0, static_cast<FT_UInt>(std::lround(em_per_scale * scale)));
    long pen_26_6 = 0;  // FreeType's 1/64 pixels
    FT_UInt previous = 0;
    for (const char32_t code : decode_utf8(utf8)) {
      const FT_UInt index = FT_Get_Char_Index(face_, code);
      if (previous != 0 && index != 0 && FT_HAS_KERNING(face_)) {
        FT_Vector kerning;
        if (FT_Get_Kerning(face_, previous, index, FT_KERNING_DEFAULT, &kerning) == 0) pen_26_6 += kerning.x;
      }
      if (FT_Load_Glyph(face_, index, draw ? FT_LOAD_RENDER : FT_LOAD_DEFAULT) != 0) continue;
      const FT_GlyphSlotRec* g = face_->glyph;
      if (draw)
        draw(g->bitmap, static_cast<int>((pen_26_6 + 32) >> 6) + g->bitmap_left,
             baseline_per_scale * scale - g->bitmap_top);
      pen_26_6 += g->advance.x;
      previous = index;
    }
    return static_cast<int>((pen_26_6 + 32) >> 6);
  }

 private:
  FT_Library library_ = nullptr;
  FT_Face face_ = nullptr;
  std::mutex mutex_;
};

Font& font() {
  static Font instance;
  return instance;
}

std::uint8_t blend(std::uint8_t under, std::uint8_t over, int alpha) {
  return static_cast<std::uint8_t>((under * (255 - alpha) + over * alpha + 127) / 255);
}

}  // namespace

bool real_font() { return font().usable(); }

int text_width_px(std::string_view utf8, int scale) {
  if (!font().usable()) return bitmap_text_width_px(utf8, scale);
  return font().lay_out(utf8, scale, {});
}

void draw_text(Image& image, int x, int y, std::string_view utf8, Rgb colour, int scale) {
  if (!font().usable()) return draw_bitmap_text(image, x, y, utf8, colour, scale);
  font().lay_out(utf8, scale, [&](const FT_Bitmap& bitmap, int left, int top) {
    for (unsigned row = 0; row < bitmap.rows; ++row)
      for (unsigned column = 0; column < bitmap.width; ++column) {
        const int alpha = bitmap.buffer[row * static_cast<unsigned>(bitmap.pitch) + column];
        if (alpha == 0) continue;
        const int px = x + left + static_cast<int>(column), py = y + top + static_cast<int>(row);
        if (px < 0 || py < 0 || px >= image.width() || py >= image.height()) continue;
        const Rgb under = image.get(px, py);
        image.set(px, py,
                  {blend(under.r, colour.r, alpha), blend(under.g, colour.g, alpha), blend(under.b, colour.b, alpha)});
      }
  });
}

}  // namespace emit::detail
