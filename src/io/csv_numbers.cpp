#include "emit/io/csv_numbers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"

namespace emit {

void parse_csv_numbers(const std::string& line, const LineReader& lines, std::vector<double>& values,
                       bool allow_not_finite) {
  values.clear();
  const char* p = line.c_str();
  const char* const line_end = p + line.size();
  while (true) {
    char* end = nullptr;
    const double value = std::strtod(p, &end);
    const char* stop = end;
    while (*stop == ' ' || *stop == '\t') ++stop;
    if (end == p || (*stop != ',' && stop != line_end)) {
      const char* field_end = std::find(p, line_end, ',');
      throw InvalidInput(lines.where() + ": value " + std::to_string(values.size() + 1) + " " +
                         quote_input(std::string_view(p, static_cast<std::size_t>(field_end - p))) +
                         " is not a number");
    }
    if (!allow_not_finite && !std::isfinite(value))
      throw InvalidInput(lines.where() + ": value " + std::to_string(values.size() + 1) + " is " +
                         std::string(p, static_cast<std::size_t>(end - p)));
    values.push_back(value);
    if (stop == line_end) return;
    p = stop + 1;
  }
}

}  // namespace emit
