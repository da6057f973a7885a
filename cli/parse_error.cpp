// The one-line message for a command line CLI11 refused (commands.hpp parse_error_message).
#include <algorithm>
#include <vector>

#include "commands.hpp"
#include "emit/core/quote_input.hpp"

namespace emit::cli {

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv) {
  if (app.get_subcommands().empty()) {
    // The first word that is not an option or an option's value: the command the user meant.
    for (int i = 1; i < argc; ++i) {
      const std::string word = argv[i];
      if (word == "--threads") {
        ++i;
        continue;
      }
      if (word.rfind('-', 0) == 0) continue;
      std::string nearest;
      std::size_t best = 3;  // at most two edits away
      for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
        if (word == command->get_name()) return error.what();  // a command: the error is another
        if (const std::size_t d = edit_distance(word, command->get_name()); d < best)
          best = d, nearest = command->get_name();
      }
      return "unknown command " + quote_input(word) + (nearest.empty() ? "" : " (did you mean \"" + nearest + "\"?)");
    }
    return "no command given: try 'emit demo'";
  }
  return error.what();
}

}  // namespace emit::cli
