#pragma once
/// \file progress.hpp
/// What long work tells its caller as it goes (the CLI prints it on stderr). Every member may be
/// left empty: nothing is told then.
#include <functional>
#include <string>

namespace emit {

struct Progress {
  /// A stage begins ("meshing", "computing the Jacobian").
  std::function<void(const std::string& stage)> stage;
  /// `done` of `total` items of `what` ("reconstructing frame", 120, 500).
  std::function<void(const std::string& what, long done, long total)> count;
  /// Something the user should know that does not stop the work (a dead electrode left out).
  std::function<void(const std::string& message)> warning;

  void say(const std::string& text) const {
    if (stage) stage(text);
  }
  void step(const std::string& what, long done, long total) const {
    if (count) count(what, done, total);
  }
  void warn(const std::string& message) const {
    if (warning) warning(message);
  }
};

}  // namespace emit
