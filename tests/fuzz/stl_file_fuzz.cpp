// libFuzzer target for STL files as emit checks them before Gmsh reads them
// (mesh/stl_file_check.hpp): any bytes as a .stl file. The check must return or throw an
// emit::Error (fuzz_support.hpp); no Gmsh here, only emit's own reading. A file it accepts has
// at least one triangle and no more than the limit, and a binary one exactly the triangles its
// size holds.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "emit/mesh/stl_file_check.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr double max_triangles = 1000;
  const std::string& path = emit::fuzz::input_file(data, size, ".stl");
  emit::fuzz::expect_only_emit_errors([&] {
    const emit::StlFileSummary stl = emit::check_stl_file(path, max_triangles);
    if (stl.triangle_count < 1 || static_cast<double>(stl.triangle_count) > max_triangles) std::abort();
    if (stl.binary && static_cast<std::size_t>(stl.triangle_count) * 50 + 84 != size) std::abort();
  });
  return 0;
}
