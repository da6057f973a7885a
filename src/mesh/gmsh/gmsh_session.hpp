#pragma once
// Private: a scoped Gmsh API session. Gmsh keeps global state, so sessions are serialised by a
// mutex; its console output is silenced and its errors are turned into emit's exceptions.
#include <functional>
#include <mutex>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit::detail {

class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /// Run a Gmsh call; if it fails, throw E("<context>: <Gmsh's last error>"); emit's own errors
  /// thrown from inside it pass unchanged.
  template <class E>
  void run(const std::string& context, const std::function<void()>& call) {
    try {
      call();
    } catch (const Error&) {
      throw;  // emit's own, from inside the call: already says what is wrong
    } catch (...) {
      throw E(context + ": " + last_error());
    }
    const std::string error = last_error();
    if (!error.empty()) throw E(context + ": " + error);
  }

  /// The current Gmsh model's triangles, nodes and "electrode <i>" curve groups as a Mesh.
  /// Unreferenced nodes (e.g. a circle's centre point) are dropped; flat meshes are oriented
  /// counter-clockwise; numbered for locality (sort_for_locality.hpp). Without electrodes_required
  /// a model with no electrode groups (an STL surface) gives a mesh without electrodes.
  /// \throw InvalidInput (prefixed with `context`).
  Mesh extract_mesh(const std::string& context, bool electrodes_required = true);

 private:
  Mesh extract_mesh_unchecked(const std::string& context, bool electrodes_required);
  std::string last_error();
  static std::mutex& mutex();
  std::lock_guard<std::mutex> lock_;
};

}  // namespace emit::detail
