// Progress on stderr (commands.hpp stderr_progress).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "commands.hpp"

namespace emit::cli {

Progress stderr_progress(long min_count) {
  struct State {
    bool tty = ::isatty(2) != 0;
    long last_percent = -1;
  };
  auto state = std::make_shared<State>();
  Progress progress;
  progress.stage = [](const std::string& stage) { std::fprintf(stderr, "%s ...\n", stage.c_str()); };
  progress.warning = [](const std::string& message) { std::fprintf(stderr, "emit: warning: %s\n", message.c_str()); };
  progress.count = [state, min_count](const std::string& what, long done, long total) {
    if (total < std::max(min_count, 1L)) return;
    const long percent = 100 * done / total;
    if (state->tty)
      std::fprintf(stderr, "\r%s %ld/%ld (%ld%%)%s", what.c_str(), done, total, percent, done == total ? "\n" : "");
    else if (percent / 10 != state->last_percent / 10)
      std::fprintf(stderr, "%s %ld/%ld (%ld%%)\n", what.c_str(), done, total, percent);
    state->last_percent = done == total ? -1 : percent;
  };
  return progress;
}

}  // namespace emit::cli
