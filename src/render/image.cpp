#include "emit/render/image.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "emit/core/errors.hpp"
#include "emit/core/output_file.hpp"

namespace emit {
namespace {

/// Index of pixel (x, y)'s red byte in a row-major RGB buffer `width` pixels wide.
std::size_t rgb_offset(int x, int y, int width) {
  return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
}

}  // namespace

Image::Image(int width_px, int height_px, Rgb background) : width_(width_px), height_(height_px) {
  if (width_px <= 0 || height_px <= 0)
    throw InvalidInput("image size " + std::to_string(width_px) + "x" + std::to_string(height_px) +
                       " px: both sides must be positive");
  rgb_.resize(static_cast<std::size_t>(width_px) * static_cast<std::size_t>(height_px) * 3);
  for (std::size_t i = 0; i < rgb_.size(); i += 3) {
    rgb_[i] = background.r;
    rgb_[i + 1] = background.g;
    rgb_[i + 2] = background.b;
  }
}

void Image::set(int x, int y, Rgb colour) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  const std::size_t i = rgb_offset(x, y, width_);
  rgb_[i] = colour.r;
  rgb_[i + 1] = colour.g;
  rgb_[i + 2] = colour.b;
}

Rgb Image::get(int x, int y) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_)
    throw std::out_of_range("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                            std::to_string(width_) + "x" + std::to_string(height_) + " image");
  const std::size_t i = rgb_offset(x, y, width_);
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

namespace {

// libpng reports errors by calling an error function that must not return. We record the message
// and longjmp back to the setjmp in the encode/decode functions below. A longjmp skips C++
// destructors, so every function that calls setjmp owns no object with a destructor: memory the
// caller needs (pixel rows, the libpng structs' owner) lives in the caller's frame, which longjmp
// never crosses.
struct PngError {
  char message[256] = "unknown libpng error";
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngError*>(png_get_error_ptr(png));
  std::snprintf(error->message, sizeof error->message, "%s", message);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}  // warnings (e.g. odd chunks) are not failures

/// Encodes `image` into `file`; false (with `error` set) if libpng fails. No destructors here.
bool encode_png(std::FILE* file, const Image& image, PngError& error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  if (!png) {
    std::snprintf(error.message, sizeof error.message, "out of memory");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(error.message, sizeof error.message, "out of memory");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width()), static_cast<png_uint_32>(image.height()), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  const std::size_t stride = static_cast<std::size_t>(image.width()) * 3;
  for (int y = 0; y < image.height(); ++y)
    png_write_row(png, image.rgb().data() + stride * static_cast<std::size_t>(y));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

/// Owns the reading side's FILE and libpng structs, so they are released on every path.
struct PngReader {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngError error;
  PngReader() = default;
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;
  ~PngReader() {
    if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    if (file) std::fclose(file);
  }
};

/// Reads the header and asks libpng to deliver 8-bit RGB whatever the stored format (palette,
/// grey, 16 bit, alpha, interlaced). No destructors here.
bool decode_png_header(PngReader& reader, png_uint_32& width, png_uint_32& height) {
  if (setjmp(png_jmpbuf(reader.png))) return false;
  png_init_io(reader.png, reader.file);
  png_read_info(reader.png, reader.info);
  png_set_expand(reader.png);
  png_set_strip_16(reader.png);
  png_set_strip_alpha(reader.png);
  png_set_gray_to_rgb(reader.png);
  png_set_interlace_handling(reader.png);
  png_read_update_info(reader.png, reader.info);
  width = png_get_image_width(reader.png, reader.info);
  height = png_get_image_height(reader.png, reader.info);
  return true;
}

/// Reads all rows into the caller's buffers. No destructors here.
bool decode_png_rows(PngReader& reader, png_bytepp rows) {
  if (setjmp(png_jmpbuf(reader.png))) return false;
  png_read_image(reader.png, rows);
  png_read_end(reader.png, nullptr);
  return true;
}

void open_png_reader(PngReader& reader, const std::string& path) {
  reader.file = std::fopen(path.c_str(), "rb");
  if (!reader.file) throw IoError(path + ": cannot open PNG (" + std::strerror(errno) + ")");
  reader.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reader.error, on_png_error, on_png_warning);
  if (reader.png) reader.info = png_create_info_struct(reader.png);
  if (!reader.png || !reader.info) throw IoError(path + ": cannot read PNG (out of memory)");
}

}  // namespace

void write_png(const Image& image, const std::string& path) {
  OutputFile file({"", path}, {.stream = false});  // throws IoError if the folder is missing
  std::FILE* out = std::fopen(file.write_path().c_str(), "wb");
  if (!out) throw IoError(path + ": cannot write (" + std::strerror(errno) + ")");
  PngError error;
  const bool encoded = encode_png(out, image, error);
  const bool flushed = std::fflush(out) == 0 && !std::ferror(out);
  const bool closed = std::fclose(out) == 0;  // a full disk may only show here
  if (!encoded) throw IoError(path + ": cannot write PNG (" + error.message + ")");
  if (!flushed || !closed) throw IoError(path + ": write failed (disk full?)");
  file.commit();
}

Image read_png(const std::string& path) {
  PngReader reader;
  open_png_reader(reader, path);
  png_uint_32 width = 0, height = 0;
  if (!decode_png_header(reader, width, height))
    throw IoError(path + ": not a readable PNG (" + reader.error.message + ")");
  // libpng's own limits (1e6 per side) still allow images far beyond what a tool should load.
  constexpr unsigned long long max_pixels = 100'000'000ULL;
  if (static_cast<unsigned long long>(width) * height > max_pixels)
    throw IoError(path + ": PNG of " + std::to_string(width) + "x" + std::to_string(height) + " px is too large");
  const std::size_t stride = static_cast<std::size_t>(width) * 3;
  std::vector<png_byte> pixels(stride * height);
  std::vector<png_bytep> rows(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = pixels.data() + stride * y;
  if (!decode_png_rows(reader, rows.data()))
    throw IoError(path + ": not a readable PNG (" + reader.error.message + ")");

  Image image(static_cast<int>(width), static_cast<int>(height));
  for (png_uint_32 y = 0; y < height; ++y)
    for (png_uint_32 x = 0; x < width; ++x) {
      const png_byte* p = rows[y] + 3 * std::size_t{x};
      image.set(static_cast<int>(x), static_cast<int>(y), {p[0], p[1], p[2]});
    }
  return image;
}

}  // namespace emit
