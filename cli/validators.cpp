// What the commands' options must be (commands.hpp): number validators, seeds, ranges.
#include <cmath>
#include <cstdlib>
#include <exception>
#include <functional>

#include "commands.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/limits.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/io/real_dataset.hpp"

namespace emit::cli {

namespace {

/// A validator accepting a whole number (integer) or any number, and `rule` holding for it.
CLI::Validator number_validator(const std::string& name, bool integer, bool (*rule)(double), const std::string& what) {
  return CLI::Validator(
      [=](const std::string& text) -> std::string {
        double value = 0;
        char* end = nullptr;
        value = std::strtod(text.c_str(), &end);
        const bool whole = end != text.c_str() && *end == '\0' && std::isfinite(value);
        if (whole && (!integer || value == std::floor(value)) && rule(value)) return {};
        return "must be " + what + ", got " + quote_input(text);
      },
      name);
}

}  // namespace

const CLI::Validator& positive_number() {
  static const CLI::Validator v = number_validator(
      "POSITIVE", false, [](double x) { return x > 0; }, "a positive number");
  return v;
}

const CLI::Validator& non_negative_number() {
  static const CLI::Validator v = number_validator(
      "NONNEGATIVE", false, [](double x) { return x >= 0; }, "a number 0 or larger");
  return v;
}

const CLI::Validator& fraction_below_one() {
  static const CLI::Validator v = number_validator(
      "FRACTION", false, [](double x) { return x >= 0 && x < 1; }, "a fraction from 0 up to (not including) 1");
  return v;
}

const CLI::Validator& positive_integer() {
  static const CLI::Validator v = number_validator(
      "POSITIVE", true, [](double x) { return x > 0; }, "a whole number 1 or larger");
  return v;
}

const CLI::Validator& non_negative_integer() {
  static const CLI::Validator v = number_validator(
      "NONNEGATIVE", true, [](double x) { return x >= 0; }, "a whole number 0 or larger");
  return v;
}

const CLI::Validator& threads_within_limit() {
  static const CLI::Validator v = number_validator(
      "THREADS", true, [](double x) { return x >= 1 && x <= limits::max_threads; }, limits::thread_count_rule());
  return v;
}

const CLI::Validator& press_count() {
  static const CLI::Validator v = number_validator(
      "PRESSES", true, [](double x) { return x >= 1 && x <= static_cast<double>(max_real_dataset_values); },
      "a whole number of presses from 1 to " + std::to_string(max_real_dataset_values) + " (the most a folder holds)");
  return v;
}

CLI::Validator checked_by(const std::string& name, const std::function<void(double)>& check) {
  return CLI::Validator(
      [check](const std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0') return "must be a number, got " + quote_input(text);
        try {
          check(value);
        } catch (const InvalidInput& e) {
          // The library names its field ("PipelineOptions::lambda2 must be ..."); the option's
          // name stands before the message already.
          std::string message = e.what();
          if (const std::size_t scope = message.find("::"); scope != std::string::npos)
            if (const std::size_t space = message.find(' ', scope);
                space != std::string::npos && message.find(' ') == space)
              message.erase(0, space + 1);
          return message;
        }
        return {};
      },
      name);
}

std::uint64_t parse_seed(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  std::uint64_t seed = 0;
  try {
    seed = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || text[0] == '-')
    throw InvalidInput(option + ": the seed must be a whole number 0 or larger, got " + quote_input(text));
  return seed;
}

std::array<double, 2> pair_or_single(const std::vector<double>& values, const std::string& option) {
  if (values.size() == 1) return {values[0], values[0]};
  if (values.size() == 2) return {values[0], values[1]};
  throw InvalidInput(option + ": give one value or two (a range)");
}

}  // namespace emit::cli
