// The one-line message for a command line CLI11 refused (commands.hpp parse_error_message).
#include <algorithm>
#include <cctype>
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

/// The name among `names` nearest `word`: at most two edits away (three for a word of 12 letters
/// or more), or the only one it begins; "" if none is.
std::string nearest(const std::string& word, const std::vector<std::string>& names) {
  std::string best_name;
  std::size_t best = word.size() >= 12 ? 4 : 3;
  for (const std::string& name : names)
    if (const std::size_t d = edit_distance(word, name); d < best) best = d, best_name = name;
  if (!best_name.empty()) return best_name;
  std::vector<std::string> extended;
  for (const std::string& name : names)
    if (word.size() >= 3 && name.rfind(word, 0) == 0) extended.push_back(name);
  return extended.size() == 1 ? extended.front() : "";
}

/// A word of the command line that is an option's name rather than a value: "--x", "-x", not
/// "-3", "-.5" or "-".
bool looks_like_an_option(const std::string& word) {
  if (word.size() < 2 || word[0] != '-') return false;
  const char next = word[1] == '-' && word.size() > 2 ? word[2] : word[1];
  return next != '.' && !std::isdigit(static_cast<unsigned char>(next));
}

/// Whether `app` (or, for a command, the top level's --threads, --help, --version) takes `name`.
bool takes(const CLI::App& app, const std::string& name) {
  for (const CLI::App* level = &app; level != nullptr; level = level->get_parent())
    if (level->get_option_no_throw(name) != nullptr) return true;
  return false;
}

/// Every long option `app` takes, with its dashes.
std::vector<std::string> long_options(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* level = &app; level != nullptr; level = level->get_parent())
    for (const CLI::Option* option : level->get_options())
      for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  return names;
}

}  // namespace

std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv) {
  const std::vector<CLI::App*> commands = app.get_subcommands();
  if (commands.empty()) {
    // The first word that is not an option or an option's value: the command the user meant.
    for (int i = 1; i < argc; ++i) {
      const std::string word = argv[i];
      if (word == "--threads") {
        ++i;
        continue;
      }
      if (word.rfind('-', 0) == 0) continue;
      std::vector<std::string> names;
      for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
        if (word == command->get_name()) return std::string(error.what()) + " (see 'emit --help')";
        names.push_back(command->get_name());
      }
      const std::string meant = nearest(word, names);
      return "unknown command " + quote_input(word) + (meant.empty() ? "" : " (did you mean \"" + meant + "\"?)") +
             "; the commands are in 'emit --help'";
    }
    return "no command given: try 'emit demo', or see 'emit --help'";
  }
  const CLI::App& command = *commands.front();
  const std::string help = "'emit " + command.get_name() + " --help'";
  // An option the command does not take is what went wrong, whatever CLI11 says ("--reference is
  // required" of `--referense x`; "arguments were not expected" of `--imagess m2/`).
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--") break;
    if (!looks_like_an_option(word)) continue;
    const std::string name = word.substr(0, word.find('='));
    if (takes(command, name)) continue;
    const std::string meant = name.rfind("--", 0) == 0 ? nearest(name, long_options(command)) : "";
    return "unknown option " + quote_input(name) +
           (meant.empty() ? "; the options of emit " + command.get_name() + " are in " + help
                          : " (did you mean " + meant + "? see " + help + ")");
  }
  std::string what = error.what();
  // CLI11's "--out: 1 required TEXT missing": an option given no value.
  if (const std::size_t colon = what.find(": "); dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr &&
                                                 colon != std::string::npos &&
                                                 what.find(" required ") != std::string::npos)
    what = what.substr(0, colon) + " needs a value";
  return what + " (see " + help + ")";
}

}  // namespace emit::cli
