#include "emit/mesh/stl_file_check.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <vector>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/core/types.hpp"
#include "file_bytes.hpp"
#include "sheet_file_access.hpp"
#include "triangle_limit.hpp"
#include "zero_area_triangles.hpp"

namespace emit {

namespace {

using detail::FileBytes;
using Corners = std::array<std::array<double, 3>, 3>;

/// Gmsh reads an ASCII STL a line at a time into 256 bytes: a longer line would be read as two.
constexpr std::size_t max_line_bytes = 254;
/// A binary STL's header and count, and each triangle's bytes: normal, three corners, attribute.
constexpr std::uint64_t binary_header_bytes = 84, binary_triangle_bytes = 50;
/// Gmsh takes a binary count above this for one of the other byte order, and swaps it.
constexpr std::uint64_t gmsh_binary_count_limit = 100000000;

bool starts_with(const std::string& text, const char* prefix) {
  return text.compare(0, std::strlen(prefix), prefix) == 0;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '\n'; }

std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> words;
  for (std::size_t i = 0; i < line.size();) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

bool same_word(const std::string& word, const char* keyword) {
  if (word.size() != std::strlen(keyword)) return false;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(word[i])) != keyword[i]) return false;
  return true;
}

std::string corner_text(const std::array<double, 3>& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p[0], p[1], p[2]);
  return text;
}

/// Checks one triangle: finite corners, not of zero area. `where` names it ("triangle 5 (line 37)").
void check_triangle(const Corners& c, const std::string& file, const std::string& where) {
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d)
      if (!std::isfinite(c[k][d]))
        throw InvalidInput(file + ": " + where + ": corner " + std::to_string(k) + " is " + corner_text(c[k]) +
                           ", not finite numbers");
  const Vector3 a(c[0][0], c[0][1], c[0][2]), b(c[1][0], c[1][1], c[1][2]), d(c[2][0], c[2][1], c[2][2]);
  if (detail::has_zero_area(a, b, d))
    throw InvalidInput(file + ": " + where + " has zero area: its corners " + detail::zero_area_corners_text(a, b, d));
}

[[noreturn]] void beyond_limit(const std::string& file, const std::string& what, double max_triangles) {
  throw InvalidInput(file + ": " + what + ", " + detail::beyond_triangle_limit(max_triangles, "use a coarser mesh"));
}

/// The ASCII reading: a syntax error (the file may then still be a binary STL whose header begins
/// with "solid") comes back as its message; a bad triangle or the limit is thrown.
struct AsciiResult {
  std::int64_t triangles = 0;
  std::optional<std::string> syntax_error;
};

/// A line that is not what Gmsh's reader expects there: its message, thrown inside read_ascii.
struct SyntaxError {
  std::string message;
};

/// The ASCII file's lines, one keyword each, as Gmsh's reader takes them.
class AsciiLines {
 public:
  AsciiLines(const std::string& path, const std::string& file) : in_(path, file), file_(file) {}

  /// The next line: false at the end of the file. \throw SyntaxError for one longer than Gmsh reads.
  bool next() {
    bool too_long = false;
    if (!in_.line(line_, max_line_bytes, too_long)) return false;
    if (too_long) fail("a line longer than 254 bytes (Gmsh's reader would split it)");
    words_ = words_of(line_);
    return true;
  }
  /// The next line, which must be there: `expected` says what it should be.
  void expect_next(const char* expected) {
    if (!next()) fail(std::string("the file ends where ") + expected + " should be");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw SyntaxError{file_ + ": line " + std::to_string(in_.line_number()) + ": " + what + ", got " +
                      quote_input(line_, 40)};
  }
  /// Whether the line is exactly these keywords (any case).
  bool is(std::initializer_list<const char*> keywords) const {
    if (words_.size() != keywords.size()) return false;
    std::size_t k = 0;
    for (const char* keyword : keywords)
      if (!same_word(words_[k++], keyword)) return false;
    return true;
  }
  const std::string& line() const { return line_; }
  const std::vector<std::string>& words() const { return words_; }
  std::int64_t number() const { return in_.line_number(); }

 private:
  FileBytes in_;
  std::string file_, line_;
  std::vector<std::string> words_;
};

AsciiResult read_ascii(const std::string& path, const std::string& file, double max_triangles) {
  AsciiLines lines(path, file);
  AsciiResult result;
  try {
    lines.next();  // "solid …": the caller has seen it begin so
    std::int64_t in_solid = 0;
    while (true) {
      if (!lines.next()) {
        if (in_solid == 0) lines.fail("a solid without triangles");
        return result;  // the end without "endsolid": Gmsh reads what came before
      }
      if (!lines.words().empty() && same_word(lines.words()[0], "endsolid")) {
        if (in_solid == 0) lines.fail("a solid without triangles");
        // Gmsh sees "endsolid" (or "ENDSOLID") only at the line's start; then another "solid" may begin.
        const bool seen = starts_with(lines.line(), "endsolid") || starts_with(lines.line(), "ENDSOLID");
        if (!lines.next()) return result;
        if (seen && (starts_with(lines.line(), "solid") || starts_with(lines.line(), "SOLID"))) {
          in_solid = 0;
          continue;
        }
        do {
          if (!lines.words().empty()) lines.fail("nothing but the end of the file after \"endsolid\"");
        } while (lines.next());
        return result;
      }
      if (lines.words().empty() || !same_word(lines.words()[0], "facet"))
        lines.fail("expected \"facet normal nx ny nz\"");
      const std::int64_t triangle = result.triangles;
      const std::int64_t facet_line = lines.number();
      lines.expect_next("\"outer loop\"");
      if (!lines.is({"outer", "loop"})) lines.fail("expected \"outer loop\"");
      Corners corners{};
      for (int k = 0; k < 3; ++k) {
        lines.expect_next("\"vertex x y z\"");
        if (lines.words().size() != 4 || !same_word(lines.words()[0], "vertex"))
          lines.fail("expected \"vertex x y z\"");
        for (int d = 0; d < 3; ++d) {
          const char* text = lines.words()[1 + d].c_str();
          char* end = nullptr;
          corners[k][d] = std::strtod(text, &end);
          if (end == text || *end != '\0')
            lines.fail("expected \"vertex x y z\", three numbers (" + quote_input(lines.words()[1 + d], 40) +
                       " is not a number)");
        }
      }
      lines.expect_next("\"endloop\"");
      if (!lines.is({"endloop"})) lines.fail("expected \"endloop\"");
      lines.expect_next("\"endfacet\"");
      if (!lines.is({"endfacet"})) lines.fail("expected \"endfacet\"");
      const std::string where = " (line " + std::to_string(facet_line) + ")";
      if (static_cast<double>(triangle + 1) > max_triangles)
        beyond_limit(file, "more than " + std::to_string(triangle) + " triangles" + where, max_triangles);
      check_triangle(corners, file, "triangle " + std::to_string(triangle) + where);
      ++result.triangles;
      ++in_solid;
    }
  } catch (const SyntaxError& error) {
    result.syntax_error = error.message;
    return result;
  }
}

/// Whether Gmsh's text reading of a file that begins with "solid" could take a vertex from it: it
/// reads it in pieces of at most 255 bytes ending at '\n' (fgets), and takes three numbers from a
/// piece that is a word then three numbers (sscanf "%s %lf %lf %lf"). Any piece after the first
/// counts, wherever it falls, so the answer errs towards "could".
bool gmsh_could_read_text_vertex(const std::string& path, const std::string& file) {
  FileBytes in(path, file);
  std::string piece;
  char c = 0;
  bool first = true;
  const auto check = [&]() {
    if (first) {
      first = false;
      return false;
    }
    const char* p = piece.c_str();  // sscanf stops at a NUL byte
    while (*p != '\0' && is_space(*p)) ++p;
    if (*p == '\0') return false;
    while (*p != '\0' && !is_space(*p)) ++p;
    for (int k = 0; k < 3; ++k) {
      char* end = nullptr;
      std::strtod(p, &end);
      if (end == p) return false;
      p = end;
    }
    return true;
  };
  while (in.read(&c, 1)) {
    piece += c;
    if (c == '\n' || piece.size() == 255) {
      if (check()) return true;
      piece.clear();
    }
  }
  return !piece.empty() && check();
}

float float_at(const unsigned char* bytes) {
  // Little-endian, as STL is written; the host is too (Gmsh reads it the same way).
  float value = 0;
  std::memcpy(&value, bytes, sizeof value);
  return value;
}

std::int64_t read_binary(const std::string& path, const std::string& file, double max_triangles) {
  FileBytes in(path, file);
  unsigned char header[binary_header_bytes];
  if (!in.read(header, sizeof header))
    throw InvalidInput(file +
                       ": not an STL file: it does not begin with \"solid\" (ASCII) and is shorter than a "
                       "binary STL's 84-byte header (" +
                       std::to_string(in.size()) + " bytes)");
  const std::uint64_t count = static_cast<std::uint64_t>(header[80]) | static_cast<std::uint64_t>(header[81]) << 8 |
                              static_cast<std::uint64_t>(header[82]) << 16 |
                              static_cast<std::uint64_t>(header[83]) << 24;
  const std::string claimed = "a binary STL of " + std::to_string(count) + " triangles (its header says)";
  if (static_cast<double>(count) > max_triangles) beyond_limit(file, claimed, max_triangles);
  if (count > gmsh_binary_count_limit)
    throw InvalidInput(file + ": " + claimed + ", more than Gmsh reads from a binary STL (" +
                       std::to_string(gmsh_binary_count_limit) + ")");
  if (count == 0) throw InvalidInput(file + ": a binary STL without triangles (its header's count is 0)");
  const std::uint64_t expected = binary_header_bytes + binary_triangle_bytes * count;
  if (in.size() != expected)
    throw InvalidInput(file + ": " + claimed + ", which take " + std::to_string(expected) + " bytes; the file has " +
                       std::to_string(in.size()) + " (not an STL file, or cut short)");
  unsigned char record[binary_triangle_bytes];
  for (std::uint64_t t = 0; t < count; ++t) {
    if (!in.read(record, sizeof record)) throw InvalidInput(file + ": cut short in triangle " + std::to_string(t));
    Corners corners{};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) corners[k][d] = float_at(record + static_cast<std::size_t>(12 + 12 * k + 4 * d));
    check_triangle(corners, file, "triangle " + std::to_string(t));
  }
  return static_cast<std::int64_t>(count);
}

}  // namespace

StlFileSummary check_stl_file(const std::string& path, double max_triangles) {
  detail::check_sheet_file_access(path, "STL file");
  const std::string file = quote_input(path, 120);
  std::string first;
  {
    FileBytes in(path, file);
    bool too_long = false;
    in.line(first, 5, too_long);
  }
  StlFileSummary summary;
  // Gmsh reads a file that begins with "solid" (or "SOLID") as text, any other as binary.
  if (!starts_with(first, "solid") && !starts_with(first, "SOLID")) {
    summary.binary = true;
    summary.triangle_count = read_binary(path, file, max_triangles);
    return summary;
  }
  const AsciiResult ascii = read_ascii(path, file, max_triangles);
  if (!ascii.syntax_error) {
    summary.triangle_count = ascii.triangles;
    return summary;
  }
  // Not ASCII: binary, if it has a binary STL's size and Gmsh's text reading finds nothing in it
  // (it then reads it as binary); else the text's first mistake is the one to fix.
  {
    FileBytes in(path, file);
    unsigned char header[binary_header_bytes];
    if (!in.read(header, sizeof header)) throw InvalidInput(*ascii.syntax_error);
    const std::uint64_t count = static_cast<std::uint64_t>(header[80]) | static_cast<std::uint64_t>(header[81]) << 8 |
                                static_cast<std::uint64_t>(header[82]) << 16 |
                                static_cast<std::uint64_t>(header[83]) << 24;
    if (count == 0 || in.size() != binary_header_bytes + binary_triangle_bytes * count)
      throw InvalidInput(*ascii.syntax_error);
  }
  if (gmsh_could_read_text_vertex(path, file))
    throw InvalidInput(*ascii.syntax_error + " (a binary STL must not begin with \"solid\": Gmsh reads it as text)");
  summary.binary = true;
  summary.triangle_count = read_binary(path, file, max_triangles);
  return summary;
}

}  // namespace emit
