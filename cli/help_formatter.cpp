// Help as a user reads it (commands.hpp help_formatter).
#include <sstream>

#include "commands.hpp"

namespace emit::cli {

namespace {

/// CLI11's formatter, an option's line shortened: its value's kind without the checks' names
/// ("INT", not "INT:PRESSES"; an existing file's "FILE"; a set of choices as the set), its default, and no "Needs:" or
/// "Excludes:" (each option's text says what it goes with, "With --real: ...").
class HelpFormatter : public CLI::Formatter {
 public:
  /// The names without a flag's stored value ("--no-mismatches", not "--no-mismatches{false}").
  std::string make_option_name(const CLI::Option* option, bool positional) const override {
    std::string name = CLI::Formatter::make_option_name(option, positional);
    for (std::size_t open = name.find('{'); open != std::string::npos; open = name.find('{', open))
      name.erase(open, name.find('}', open) - open + 1);
    return name;
  }
  std::string make_option_opts(const CLI::Option* option) const override {
    if (!option->get_option_text().empty()) return " " + option->get_option_text();
    std::ostringstream out;
    if (option->get_type_size() != 0) {
      std::string type = option->get_type_name();
      if (const std::size_t set = type.find(":{"); set != std::string::npos) type = type.substr(set + 1);
      else if (type.ends_with(":FILE") || type.ends_with(":DIR")) type = type.substr(type.rfind(':') + 1);
      else if (const std::size_t check = type.find(':'); check != std::string::npos) type.resize(check);
      if (!type.empty()) out << " " << type;
      if (!option->get_default_str().empty()) out << "=" << option->get_default_str();
      if (option->get_expected_max() == CLI::detail::expected_max_vector_size) out << " ...";
      if (option->get_required()) out << " (required)";
    }
    return out.str();
  }
};

}  // namespace

std::shared_ptr<CLI::Formatter> help_formatter() {
  auto formatter = std::make_shared<HelpFormatter>();
  formatter->column_width(32);
  return formatter;
}

}  // namespace emit::cli
