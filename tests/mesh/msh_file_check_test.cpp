// A .msh file as emit checks it before Gmsh reads it (mesh/msh_file_check.hpp): versions 4.1 and
// 2.2, ASCII and binary, read alike by the check and by Gmsh; counts checked against the triangle
// limit from the headers, before the elements are read; coordinates that are not numbers, and
// triangles of zero area, refused in one line naming the file and the place.
#include "emit/mesh/msh_file_check.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// A 3 × 3 grid of 1 mm squares: 16 nodes (tags from 1), 18 triangles.
struct Grid {
  std::vector<std::array<double, 3>> nodes;
  std::vector<std::array<int, 3>> triangles;
};

Grid grid() {
  Grid g;
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i) g.nodes.push_back({double(i), double(j), 0});
  const auto at = [](int i, int j) { return j * 4 + i + 1; };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      g.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      g.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return g;
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

std::string msh41_ascii(const Grid& g) {
  const std::string n = std::to_string(g.nodes.size()), t = std::to_string(g.triangles.size());
  std::string text = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 " + n + " 1 " + n + "\n2 1 0 " + n + "\n";
  for (std::size_t k = 0; k < g.nodes.size(); ++k) text += std::to_string(k + 1) + "\n";
  for (const auto& p : g.nodes) text += number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + "\n";
  text += "$EndNodes\n$Elements\n1 " + t + " 1 " + t + "\n2 1 2 " + t + "\n";
  for (std::size_t k = 0; k < g.triangles.size(); ++k) {
    text += std::to_string(k + 1);
    for (int v : g.triangles[k]) text.append(" ").append(std::to_string(v));
    text += "\n";
  }
  return text + "$EndElements\n";
}

template <class T>
void put(std::string& bytes, T value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

std::string msh41_binary(const Grid& g) {
  const auto n = static_cast<std::uint64_t>(g.nodes.size()), t = static_cast<std::uint64_t>(g.triangles.size());
  std::string bytes = "$MeshFormat\n4.1 1 8\n";
  put(bytes, std::int32_t{1});
  bytes += "\n$EndMeshFormat\n$Nodes\n";
  for (std::uint64_t v : {std::uint64_t{1}, n, std::uint64_t{1}, n}) put(bytes, v);
  for (std::int32_t v : {2, 1, 0}) put(bytes, v);
  put(bytes, n);
  for (std::uint64_t k = 1; k <= n; ++k) put(bytes, k);
  for (const auto& p : g.nodes)
    for (double c : p) put(bytes, c);
  bytes += "\n$EndNodes\n$Elements\n";
  for (std::uint64_t v : {std::uint64_t{1}, t, std::uint64_t{1}, t}) put(bytes, v);
  for (std::int32_t v : {2, 1, 2}) put(bytes, v);
  put(bytes, t);
  for (std::uint64_t k = 0; k < t; ++k) {
    put(bytes, k + 1);
    for (int v : g.triangles[k]) put(bytes, static_cast<std::uint64_t>(v));
  }
  return bytes + "\n$EndElements\n";
}

std::string msh22(const Grid& g, bool binary) {
  std::string text = std::string("$MeshFormat\n2.2 ") + (binary ? "1" : "0") + " 8\n";
  if (binary) put(text, std::int32_t{1}), text += "\n";
  text += "$EndMeshFormat\n$Nodes\n" + std::to_string(g.nodes.size()) + "\n";
  for (std::size_t k = 0; k < g.nodes.size(); ++k) {
    if (!binary) {
      text += std::to_string(k + 1) + " " + number(g.nodes[k][0]) + " " + number(g.nodes[k][1]) + " 0\n";
      continue;
    }
    put(text, static_cast<std::int32_t>(k + 1));
    for (double c : g.nodes[k]) put(text, c);
  }
  text += std::string(binary ? "\n" : "") + "$EndNodes\n$Elements\n" + std::to_string(g.triangles.size()) + "\n";
  if (binary) {
    for (std::int32_t v : {2, static_cast<std::int32_t>(g.triangles.size()), 2}) put(text, v);
  }
  for (std::size_t k = 0; k < g.triangles.size(); ++k) {
    if (!binary) {
      text += std::to_string(k + 1) + " 2 2 1 1";
      for (int v : g.triangles[k]) text.append(" ").append(std::to_string(v));
      text += "\n";
      continue;
    }
    for (std::int32_t v : {static_cast<std::int32_t>(k + 1), 1, 1}) put(text, v);
    for (int v : g.triangles[k]) put(text, static_cast<std::int32_t>(v));
  }
  return text + (binary ? "\n" : "") + "$EndElements\n";
}

std::string write(const std::string& dir, const std::string& name, const std::string& bytes) {
  std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(MshFileCheck, VersionsAndEncodingsGmshWritesAreRead) {
  const std::string dir = test::temp_folder("msh_check_good");
  const Grid g = grid();
  const std::vector<std::pair<std::string, std::string>> files = {{"a41.msh", msh41_ascii(g)},
                                                                  {"b41.msh", msh41_binary(g)},
                                                                  {"a22.msh", msh22(g, false)},
                                                                  {"b22.msh", msh22(g, true)}};
  for (const auto& file : files) {
    const std::string path = write(dir, file.first, file.second);
    const MshFileSummary msh = check_msh_file(path, 1e6);
    EXPECT_EQ(msh.node_count, 16) << file.first;
    EXPECT_EQ(msh.triangle_count, 18) << file.first;
    // Gmsh reads the same files: it finds their triangles, and no electrode curves (they have none).
    EXPECT_NE(test::error_of([&] { read_msh(path); }).find("no physical curves named \"electrode 0\""),
              std::string::npos)
        << file.first;
  }
  // emit's own .msh (Gmsh's writer, 4.1 with entities and physical names) reads back whole.
  const Sensor sensor = default_sensor();
  write_msh(generate_mesh(sensor, reconstruction_mesh_options(sensor)), dir + "/default.msh");
  const MshFileSummary own = check_msh_file(dir + "/default.msh", 1e6);
  EXPECT_EQ(own.triangle_count, read_msh(dir + "/default.msh").triangle_count());
}

// A coordinate that is not a number reached the sheet's chart, which said it was "seen edge-on".
TEST(MshFileCheck, ACoordinateThatIsNotANumberIsRefusedNamingTheNode) {
  const std::string dir = test::temp_folder("msh_check_nan");
  Grid g = grid();
  g.nodes[5][0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(test::error_of([&] { check_msh_file(write(dir, "nan.msh", msh41_ascii(g)), 1e6); }),
            "\"" + dir + "/nan.msh\": line 28, $Nodes: node 6 is at (nan, 1, 0), not finite numbers");
  EXPECT_NE(test::error_of([&] {
              check_msh_file(write(dir, "nan22.msh", msh22(g, true)), 1e6);
            }).find("$Nodes: node 6 is at (nan, 1, 0), not finite numbers"),
            std::string::npos);
}

// A .msh of 1.2 M triangles was read whole (909 MB), mesh.max_triangles and --max-triangles
// ignored for a file's sheet. The count is taken from an element block's header, before its
// elements: a file that only claims them is refused as one that has them.
TEST(MshFileCheck, BeyondTheTriangleLimitIsRefusedFromTheHeaders) {
  const std::string dir = test::temp_folder("msh_check_big");
  std::string claim = msh41_ascii(grid());
  claim.replace(claim.find("1 18 1 18\n2 1 2 18\n"), 19, "1 1200000 1 1200000\n2 1 2 1200000\n");
  claim.resize(claim.find("$EndElements"));  // cut short: the elements are never reached
  EXPECT_EQ(test::error_of([&] { check_msh_file(write(dir, "claim.msh", claim), 1e6); }),
            "\"" + dir +
                "/claim.msh\": line 42, $Elements: 1200000 triangles or more (an element block's header), beyond the "
                "limit of 1e+06 triangles: use a coarser mesh, or raise the limit (sensor \"mesh\": "
                "{\"max_triangles\": N}, or emit mesh --max-triangles N)");
  std::string nodes = msh41_ascii(grid());
  nodes.replace(nodes.find("1 16 1 16\n"), 10, "1 1000000000000 1 16\n");
  EXPECT_NE(test::error_of([&] { check_msh_file(write(dir, "nodes.msh", nodes), 1e6); })
                .find("line 5, $Nodes: 1000000000000 nodes (its header), more than 3 per triangle allowed, beyond "
                      "the limit of 1e+06 triangles"),
            std::string::npos);
  // A real file beyond a lower limit: the sensor's mesh.max_triangles and generate_mesh's options
  // hold for a file's sheet as for a drawn one.
  const Sensor drawn = default_sensor();
  write_msh(generate_mesh(drawn, reconstruction_mesh_options(drawn)), dir + "/sheet.msh");
  EXPECT_NE(test::error_of([&] { read_msh(dir + "/sheet.msh", 1000); }).find("beyond the limit of 1e+03 triangles"),
            std::string::npos);
  const nlohmann::json description = {{"shape", {{"type", "mesh"}, {"file", dir + "/sheet.msh"}}},
                                      {"mesh", {{"max_triangles", 1000}}}};
  Sensor file = parse_sensor(description);
  EXPECT_NE(test::error_of([&] { with_sheet_surface(file); }).find("beyond the limit of 1e+03 triangles"),
            std::string::npos);
  file.mesh.max_triangles = 1e6;
  const Sensor read = with_sheet_surface(file);
  MeshOptions options = reconstruction_mesh_options(read);
  options.max_triangles = 1000;
  EXPECT_NE(test::error_of([&] { generate_mesh(read, options); }).find("beyond the limit of 1e+03 triangles"),
            std::string::npos);
}

TEST(MshFileCheck, MalformedFilesAreNamedWithThePlace) {
  const std::string dir = test::temp_folder("msh_check_bad");
  const auto error = [&](const std::string& bytes) {
    return test::error_of([&] { check_msh_file(write(dir, "x.msh", bytes), 1e6); });
  };
  const std::string good = msh41_ascii(grid());
  std::string v40 = good;
  v40.replace(v40.find("4.1 0 8"), 7, "4 0 8");
  EXPECT_NE(error(v40).find("line 2, $MeshFormat: version \"4\": emit reads .msh 4.1 and 2.2"), std::string::npos)
      << error(v40);
  EXPECT_NE(error(good.substr(0, good.size() - 40)).find("$Elements: the file ends before"), std::string::npos)
      << error(good.substr(0, good.size() - 40));
  std::string type = good;
  type.replace(type.find("2 1 2 18"), 8, "2 1 99 18");
  EXPECT_NE(error(type).find("line 42, $Elements: an element of type 99, which the MSH format does not list"),
            std::string::npos)
      << error(type);
  std::string text = good;
  text.replace(text.find("\n0 0 0\n") + 1, 5, "0 x 0");
  EXPECT_NE(error(text).find("line 23, $Nodes: y must be a number, got \"x\""), std::string::npos) << error(text);
  EXPECT_NE(error("solid x\n").find("not a Gmsh .msh file: it does not begin with \"$MeshFormat\""), std::string::npos);
  std::string no_triangles = good;
  no_triangles.replace(no_triangles.find("2 1 2 18"), 8, "2 1 3 18");  // quadrangles: 4 nodes each
  EXPECT_NE(error(no_triangles).find("must be a whole number, got \"$EndElements\""), std::string::npos)
      << error(no_triangles);
}

// A triangle of zero area in a .msh was read into the sheet (its stiffness divides by its area).
TEST(MshFileCheck, ATriangleOfZeroAreaIsRefusedOnceRead) {
  const std::string dir = test::temp_folder("msh_check_zero");
  Mesh mesh = test::strip_mesh(2, 1, 2, 1);
  mesh.nodes_mm.row(1) = mesh.nodes_mm.row(0);  // the bottom's middle node onto its corner
  write_msh(mesh, dir + "/zero.msh");
  const std::string error = test::error_of([&] { read_msh(dir + "/zero.msh"); });
  EXPECT_NE(error.find("zero.msh\": a triangle of zero area: its corners ("), std::string::npos) << error;
  EXPECT_NE(error.find(" repeat a point"), std::string::npos) << error;
}

}  // namespace
}  // namespace emit
