#include "emit/mesh/step_file_check.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "file_bytes.hpp"
#include "sheet_file_access.hpp"

namespace emit {

namespace {

/// A word of STEP is short: a longer one is not a number, a name or a keyword (strings may be
/// long; they are read through, not kept).
constexpr std::size_t max_word_bytes = 256;

/// The file's characters, one at a time, with the line each is on.
class StepText {
 public:
  StepText(const std::string& path, std::string file) : in_(path, file), file_(std::move(file)) {}

  /// The next character, or -1 at the end of the file.
  int next() {
    if (peeked_ >= 0) {
      const int c = peeked_;
      peeked_ = -1;
      return c;
    }
    char c = 0;
    if (!in_.read(&c, 1)) return -1;
    if (c == '\n') ++line_;
    return static_cast<unsigned char>(c);
  }
  int peek() {
    if (peeked_ < 0) peeked_ = next();
    return peeked_;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidInput(file_ + ": line " + std::to_string(line_) + ": " + what + " (not a STEP file, ISO 10303-21)");
  }

 private:
  detail::FileBytes in_;
  std::string file_;
  int peeked_ = -1;
  std::int64_t line_ = 1;
};

bool is_keyword_char(int c) { return std::isalnum(c) || c == '_' || c == '-'; }

}  // namespace

void check_step_file(const std::string& path) {
  detail::check_sheet_file_access(path, "CAD file");
  const std::string file = quote_input(path, 120);
  StepText text(path, file);
  const std::string magic = "ISO-10303-21;";
  for (const char expected : magic)
    if (text.next() != static_cast<unsigned char>(expected))
      throw InvalidInput(file + ": not a STEP file (its first line is not \"ISO-10303-21;\")");
  std::string word;
  const auto skip_space = [&] {
    while (text.peek() >= 0 && std::isspace(text.peek())) text.next();
  };
  for (int c = text.next(); c >= 0; c = text.next()) {
    if (std::isspace(c) || c == '=' || c == '(' || c == ')' || c == ',' || c == ';' || c == '$' || c == '*') continue;
    if (c == '\'') {  // a string: '' is a quote inside it
      while (true) {
        const int d = text.next();
        if (d < 0) text.fail("the file ends inside a string");
        if (d == '\'' && text.peek() != '\'') break;
        if (d == '\'') text.next();
      }
      continue;
    }
    if (c == '/' && text.peek() == '*') {  // a comment
      text.next();
      for (int d = text.next(), previous = 0; !(previous == '*' && d == '/'); previous = d, d = text.next())
        if (d < 0) text.fail("the file ends inside a comment");
      continue;
    }
    word.assign(1, static_cast<char>(c));
    const auto take = [&](auto&& belongs) {
      while (text.peek() >= 0 && belongs(text.peek())) {
        word += static_cast<char>(text.next());
        if (word.size() > max_word_bytes) text.fail(quote_input(word, 40) + " is too long for a word of STEP");
      }
    };
    if (c == '#') {  // an entity's name
      take([](int d) { return std::isdigit(d) != 0; });
      if (word.size() == 1) text.fail("\"#\" without an entity number");
    } else if (c == '.') {  // an enumeration (.T.) or a number (.5 is not STEP, but harmless)
      take([](int d) { return std::isupper(d) || std::isdigit(d) || d == '_'; });
      if (text.next() != '.') text.fail(quote_input(word, 40) + " is not an enumeration such as .T.");
    } else if (c == '"') {  // a binary: "0F0"
      take([](int d) { return std::isxdigit(d) != 0; });
      if (text.next() != '"') text.fail(quote_input(word, 40) + " is not a binary value");
    } else if (std::isdigit(c) || c == '+' || c == '-') {  // a number
      take([](int d) { return std::isdigit(d) || d == '.' || d == 'E' || d == 'e' || d == '+' || d == '-'; });
      char* end = nullptr;
      const double value = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0') text.fail(quote_input(word, 40) + " is not a number");
      if (!std::isfinite(value)) text.fail("the number " + quote_input(word, 40) + " is not finite");
    } else if (std::isalpha(c) || c == '!') {  // a keyword: an entity or type, or a section's word
      take(is_keyword_char);
      skip_space();
      const bool section = word == "HEADER" || word == "DATA" || word == "ENDSEC" || word == "END-ISO-10303-21";
      if (section ? text.peek() != ';' : text.peek() != '(')
        text.fail(quote_input(word, 40) + " stands where a value should be (a keyword is followed by \"(\")");
    } else {
      text.fail("the character " + quote_input(std::string(1, static_cast<char>(c)), 8) + " is not STEP");
    }
  }
}

}  // namespace emit
