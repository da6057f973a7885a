#pragma once
/// \file image.hpp
/// An 8-bit RGB raster and PNG output (libpng), written atomically.
#include <cstdint>
#include <string>
#include <vector>

namespace emit {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

class Image {
 public:
  Image(int width_px, int height_px, Rgb background = {255, 255, 255});
  int width() const { return width_; }
  int height() const { return height_; }
  /// Pixel (x right, y down from the top-left). Writes outside the image are ignored.
  void set(int x, int y, Rgb colour);
  Rgb get(int x, int y) const;
  const std::vector<std::uint8_t>& rgb() const { return rgb_; }

 private:
  int width_, height_;
  std::vector<std::uint8_t> rgb_;  ///< row-major, 3 bytes per pixel
};

/// Write as PNG via a temporary file renamed into place. \throw IoError.
void write_png(const Image& image, const std::string& path);
/// Read a PNG (RGB or RGBA, 8 bit) back, for tests and tools. \throw IoError.
Image read_png(const std::string& path);

}  // namespace emit
