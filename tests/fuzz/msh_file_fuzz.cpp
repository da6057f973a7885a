// libFuzzer target for Gmsh .msh files as emit checks them before Gmsh reads them
// (mesh/msh_file_check.hpp): any bytes as a .msh file. The check must return or throw an
// emit::Error (fuzz_support.hpp); no Gmsh here, only emit's own reading. A file it accepts has
// between 1 and the limit of triangles, on at most 3 nodes per triangle of the limit and one more.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "emit/mesh/msh_file_check.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr double max_triangles = 1000;
  const std::string& path = emit::fuzz::input_file(data, size, ".msh");
  emit::fuzz::expect_only_emit_errors([&] {
    const emit::MshFileSummary msh = emit::check_msh_file(path, max_triangles);
    if (msh.triangle_count < 1 || static_cast<double>(msh.triangle_count) > max_triangles) std::abort();
    if (msh.node_count < 0 || static_cast<double>(msh.node_count) > 3 * (max_triangles + 1)) std::abort();
  });
  return 0;
}
