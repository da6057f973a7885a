#include "emit/core/option_check.hpp"

#include <cmath>
#include <cstdio>

#include "emit/core/errors.hpp"

namespace emit::option_check {

namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace

void fail(const char* owner, const char* field, const std::string& what, const std::string& value) {
  throw InvalidInput(std::string(owner) + "::" + field + " must be " + what + ", got " + value);
}

void positive(const char* owner, const char* field, double value) {
  if (!(value > 0) || !std::isfinite(value)) fail(owner, field, "positive", number(value));
}

void zero_or_positive(const char* owner, const char* field, double value, const char* zero_means) {
  if (!(value == 0 || (value > 0 && std::isfinite(value))))
    fail(owner, field, std::string("0 (") + zero_means + ") or positive", number(value));
}

void non_negative(const char* owner, const char* field, double value) {
  if (!(value >= 0) || !std::isfinite(value)) fail(owner, field, "0 or more", number(value));
}

void within(const char* owner, const char* field, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi)) fail(owner, field, "in [" + number(lo) + ", " + number(hi) + "]", number(value));
}

void at_least(const char* owner, const char* field, std::int64_t value, std::int64_t least) {
  if (value < least) fail(owner, field, "at least " + std::to_string(least), std::to_string(value));
}

}  // namespace emit::option_check
