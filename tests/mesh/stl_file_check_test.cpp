// An STL file as emit checks it before Gmsh reads it (mesh/stl_file_check.hpp): ASCII and binary
// (a binary header may begin with "solid"), the triangle limit taken from a binary header before
// anything else is read, and the mistakes Gmsh's reader would trust (a NaN corner failed an
// assertion inside it and aborted the process) refused in one line naming the triangle.
#include "emit/mesh/stl_file_check.hpp"

#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

using Triangle = std::array<std::array<std::string, 3>, 3>;

/// n × n squares of 1 mm, two triangles each, as text.
std::vector<Triangle> grid(int n) {
  std::vector<Triangle> triangles;
  const auto p = [](int i, int j) { return std::array<std::string, 3>{std::to_string(i), std::to_string(j), "0"}; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      triangles.push_back({p(i, j), p(i + 1, j), p(i + 1, j + 1)});
      triangles.push_back({p(i, j), p(i + 1, j + 1), p(i, j + 1)});
    }
  return triangles;
}

std::string ascii(const std::vector<Triangle>& triangles) {
  std::string text = "solid sheet\n";
  for (const Triangle& t : triangles) {
    text += " facet normal 0 0 1\n  outer loop\n";
    for (const auto& v : t) text += "   vertex " + v[0] + " " + v[1] + " " + v[2] + "\n";
    text += "  endloop\n endfacet\n";
  }
  return text + "endsolid sheet\n";
}

std::string binary(const std::vector<Triangle>& triangles, const std::string& header = "binary") {
  std::string bytes = header;
  bytes.resize(80, ' ');
  const auto put = [&](const void* data, std::size_t size) { bytes.append(static_cast<const char*>(data), size); };
  const auto count = static_cast<std::uint32_t>(triangles.size());
  put(&count, 4);
  for (const Triangle& t : triangles) {
    const float normal[3] = {0, 0, 1};
    put(normal, sizeof normal);
    for (const auto& v : t)
      for (const auto& c : v) {
        const float x = std::strtof(c.c_str(), nullptr);
        put(&x, 4);
      }
    bytes += std::string(2, '\0');
  }
  return bytes;
}

std::string write(const std::string& dir, const std::string& name, const std::string& bytes) {
  std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(StlFileCheck, AsciiAndBinarySheetsAreRead) {
  const std::string dir = test::temp_folder("stl_check_good");
  const StlFileSummary a = check_stl_file(write(dir, "a.stl", ascii(grid(3))), 1e6);
  EXPECT_FALSE(a.binary);
  EXPECT_EQ(a.triangle_count, 18);
  const StlFileSummary b = check_stl_file(write(dir, "b.stl", binary(grid(3))), 1e6);
  EXPECT_TRUE(b.binary);
  EXPECT_EQ(b.triangle_count, 18);
  // A binary header that begins with "solid" (some CAD tools write one): Gmsh reads the text
  // first, finds no vertex in it, and reads it as binary; so does the check.
  const StlFileSummary c = check_stl_file(write(dir, "c.stl", binary(grid(3), "solid from a CAD tool")), 1e6);
  EXPECT_TRUE(c.binary);
  EXPECT_EQ(c.triangle_count, 18);
  // Windows line ends, capitals, no "endsolid" at the end, two solids.
  std::string crlf = ascii(grid(1));
  for (std::size_t at = 0; (at = crlf.find('\n', at)) != std::string::npos; at += 2) crlf.insert(at, 1, '\r');
  EXPECT_EQ(check_stl_file(write(dir, "d.stl", crlf), 1e6).triangle_count, 2);
  std::string two = ascii(grid(1)) + ascii(grid(2));
  EXPECT_EQ(check_stl_file(write(dir, "e.stl", two), 1e6).triangle_count, 10);
  std::string open = ascii(grid(1));
  open.resize(open.find("endsolid"));
  EXPECT_EQ(check_stl_file(write(dir, "f.stl", open), 1e6).triangle_count, 2);
}

// One NaN corner aborted the process inside Gmsh's reader (exit 134; Python died with it).
TEST(StlFileCheck, ACornerThatIsNotANumberIsRefusedNamingTheTriangle) {
  const std::string dir = test::temp_folder("stl_check_nan");
  std::vector<Triangle> triangles = grid(2);
  triangles[3][1] = {"nan", "0", "0"};
  EXPECT_EQ(test::error_of([&] { check_stl_file(write(dir, "nan.stl", ascii(triangles)), 1e6); }),
            "\"" + dir + "/nan.stl\": triangle 3 (line 23): corner 1 is (nan, 0, 0), not finite numbers");
  triangles[3][1] = {"1e999", "0", "0"};
  EXPECT_NE(test::error_of([&] {
              check_stl_file(write(dir, "inf.stl", ascii(triangles)), 1e6);
            }).find("triangle 3 (line 23): corner 1 is (inf, 0, 0), not finite numbers"),
            std::string::npos);
  triangles[3][1] = {"nan", "0", "0"};
  EXPECT_EQ(test::error_of([&] { check_stl_file(write(dir, "nan_binary.stl", binary(triangles)), 1e6); }),
            "\"" + dir + "/nan_binary.stl\": triangle 3: corner 1 is (nan, 0, 0), not finite numbers");
}

TEST(StlFileCheck, ATriangleOfZeroAreaIsRefused) {
  const std::string dir = test::temp_folder("stl_check_zero");
  std::vector<Triangle> triangles = grid(2);
  triangles.push_back({{{"0", "0", "0"}, {"1", "1", "0"}, {"2", "2", "0"}}});
  EXPECT_NE(test::error_of([&] { check_stl_file(write(dir, "line.stl", ascii(triangles)), 1e6); })
                .find("triangle 8 (line 58) has zero area: its corners (0, 0, 0), (1, 1, 0), (2, 2, 0) lie on one "
                      "line"),
            std::string::npos);
  triangles.back() = {{{"0", "0", "0"}, {"1", "1", "0"}, {"0", "0", "0"}}};
  EXPECT_NE(test::error_of([&] {
              check_stl_file(write(dir, "point.stl", binary(triangles)), 1e6);
            }).find("triangle 8 has zero area: its corners (0, 0, 0), (1, 1, 0), (0, 0, 0) repeat a point"),
            std::string::npos);
}

// A binary STL of 1.2 M triangles was read whole (909 MB), mesh.max_triangles and --max-triangles
// ignored for a file's sheet. Its header is read first: a file that only claims them (sparse, 60
// MB of nothing on disk) is refused before a triangle is read.
TEST(StlFileCheck, BeyondTheTriangleLimitIsRefusedFromTheBinaryHeader) {
  const std::string dir = test::temp_folder("stl_check_big");
  const std::string path = write(dir, "big.stl", binary(grid(1)).substr(0, 80));
  {
    std::ofstream out(path, std::ios::binary | std::ios::app);
    const std::uint32_t count = 1200000;
    out.write(reinterpret_cast<const char*>(&count), 4);
  }
  ASSERT_EQ(::truncate(path.c_str(), 84 + 50 * 1200000L), 0);
  EXPECT_EQ(test::error_of([&] { check_stl_file(path, 1e6); }),
            "\"" + path +
                "\": a binary STL of 1200000 triangles (its header says), beyond the limit of 1e+06 triangles: use a "
                "coarser mesh, or raise the limit (sensor \"mesh\": {\"max_triangles\": N}, or emit mesh "
                "--max-triangles N)");
  // ASCII has no count: it is refused as soon as it passes the limit.
  EXPECT_NE(test::error_of([&] {
              check_stl_file(write(dir, "a.stl", ascii(grid(4))), 10);
            }).find("more than 10 triangles (line 72), beyond the limit of 10 triangles"),
            std::string::npos);
  EXPECT_EQ(check_stl_file(write(dir, "b.stl", ascii(grid(4))), 32).triangle_count, 32);
}

TEST(StlFileCheck, WhatGmshWouldReadOtherwiseIsRefused) {
  const std::string dir = test::temp_folder("stl_check_syntax");
  const auto error = [&](const std::string& bytes) {
    return test::error_of([&] { check_stl_file(write(dir, "x.stl", bytes), 1e6); });
  };
  const std::string good = ascii(grid(1));
  // Gmsh reads a line at a time by position: a blank line or a long one shifts every line after.
  std::string blank = good;
  blank.insert(blank.find("endfacet\n") + 9, "\n");
  EXPECT_NE(error(blank).find("line 9: expected \"facet normal nx ny nz\", got \"\""), std::string::npos)
      << error(blank);
  std::string long_line = good;
  long_line.insert(long_line.find("vertex 0") + 8, std::string(300, '0'));
  EXPECT_NE(error(long_line).find("line 4: a line longer than 254 bytes"), std::string::npos) << error(long_line);
  std::string word = good;
  word.replace(word.find("vertex 1 0 0") + 7, 1, "one");
  EXPECT_NE(error(word).find("line 5: expected \"vertex x y z\", three numbers (\"one\" is not a number)"),
            std::string::npos)
      << error(word);
  EXPECT_NE(error("solid empty\nendsolid empty\n").find("line 2: a solid without triangles"), std::string::npos);
  EXPECT_NE(error(good + "garbage\n").find("nothing but the end of the file after \"endsolid\""), std::string::npos);
  // Binary: the size the header's count asks for, exactly.
  EXPECT_NE(error(binary(grid(1)).substr(0, 150))
                .find("a binary STL of 2 triangles (its header says), which take "
                      "184 bytes; the file has 150"),
            std::string::npos);
  EXPECT_NE(error("").find("shorter than a binary STL's 84-byte header (0 bytes)"), std::string::npos);
  EXPECT_NE(error(binary({})).find("a binary STL without triangles"), std::string::npos);
  EXPECT_NE(test::error_of([&] { check_stl_file(dir + "/none.stl", 1e6); }).find("none.stl\": no such STL file"),
            std::string::npos);
}

}  // namespace
}  // namespace emit
