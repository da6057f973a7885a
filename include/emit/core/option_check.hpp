#pragma once
/// \file option_check.hpp
/// What an options struct's validate() says when a field is wrong, in one form, as Ceres's
/// Solver::Options do: "<Struct>::<field> must be <what>, got <value>", an InvalidInput (and so one
/// line from the CLI). Each check passes its value through when it holds.
#include <cstdint>
#include <string>

namespace emit::option_check {

/// \throw InvalidInput "<owner>::<field> must be <what>, got <value>".
[[noreturn]] void fail(const char* owner, const char* field, const std::string& what, const std::string& value);

/// value > 0 and finite.
void positive(const char* owner, const char* field, double value);
/// 0 (`zero_means`, the default it stands for) or positive and finite.
void zero_or_positive(const char* owner, const char* field, double value, const char* zero_means);
/// value ≥ 0 and finite.
void non_negative(const char* owner, const char* field, double value);
/// lo ≤ value ≤ hi (and not NaN).
void within(const char* owner, const char* field, double value, double lo, double hi);
/// value ≥ least.
void at_least(const char* owner, const char* field, std::int64_t value, std::int64_t least);

}  // namespace emit::option_check
