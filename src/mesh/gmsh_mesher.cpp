#include "gmsh_mesher.hpp"

#include <dlfcn.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/mesh/msh_file_check.hpp"
#include "emit/mesh/stl_file_check.hpp"
#include "emit/mesh/stl_sheet.hpp"
#include "zero_area_triangles.hpp"

namespace emit {

namespace detail {

namespace {

using Entry = const GmshMesher* (*)();

/// The module where gmsh_mesher() looks for it, in turn.
const GmshMesher* load_gmsh_mesher() {
  std::vector<std::string> candidates;
  Dl_info self{};
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): dladdr takes an address in this object
  if (dladdr(reinterpret_cast<void*>(&load_gmsh_mesher), &self) != 0 && self.dli_fname != nullptr) {
    const std::filesystem::path folder = std::filesystem::path(self.dli_fname).parent_path();
    candidates.push_back((folder / gmsh_module_folder / gmsh_module).string());
    candidates.push_back((folder / gmsh_module).string());
  }
  candidates.emplace_back(gmsh_module);
  void* module = nullptr;
  std::string errors;
  for (const std::string& candidate : candidates) {
    module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (module != nullptr) break;
    errors += std::string(errors.empty() ? "" : "; ") + dlerror();
  }
  if (module == nullptr) throw IoError("meshing needs emit's Gmsh module, which could not be loaded: " + errors);
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): dlsym's object pointer is the function
  const auto entry = reinterpret_cast<Entry>(dlsym(module, gmsh_module_entry));
  if (entry == nullptr) throw IoError(std::string(gmsh_module) + ": no " + gmsh_module_entry + " in it");
  return entry();
}

}  // namespace

const GmshMesher& gmsh_mesher() {
  static const GmshMesher* const mesher = load_gmsh_mesher();  // once, thread-safe; a failure retries
  return *mesher;
}

}  // namespace detail

// The public entry points of mesh_io.hpp and stl_sheet.hpp, done by the module once emit has read
// the file itself (mesh/msh_file_check.hpp, mesh/stl_file_check.hpp): Gmsh sees no file that
// emit has not checked.
Mesh read_msh(const std::string& path, double max_triangles) {
  check_msh_file(path, max_triangles);
  Mesh mesh = detail::gmsh_mesher().read_msh(path);
  detail::refuse_zero_area_triangles(mesh, quote_input(path, 120));
  return mesh;
}
void write_msh(const Mesh& mesh, OutputFile& out) {
  std::string folder = (std::filesystem::temp_directory_path() / "emit-msh-XXXXXX").string();
  if (::mkdtemp(folder.data()) == nullptr)
    throw IoError("cannot create a scratch folder for Gmsh in " + std::filesystem::temp_directory_path().string() +
                  " (" + std::strerror(errno) + ")");
  const std::string scratch = folder + "/mesh.msh";
  std::error_code ignored;
  try {
    detail::gmsh_mesher().write_msh(mesh, scratch);
    std::ifstream in(scratch, std::ios::binary);
    if (!in) throw IoError(scratch + ": Gmsh wrote no mesh file");
    out.stream() << in.rdbuf();
  } catch (...) {
    std::filesystem::remove_all(folder, ignored);
    throw;
  }
  std::filesystem::remove_all(folder, ignored);
}
void write_msh(const Mesh& mesh, const std::string& path) {
  OutputFile out({"", path});
  write_msh(mesh, out);
  out.commit();
}
Mesh read_stl_sheet(const Sensor& sensor) {
  check_stl_file(sensor.shape.mesh_path, sensor.mesh.max_triangles);
  return detail::gmsh_mesher().read_stl_sheet(sensor);
}

}  // namespace emit
