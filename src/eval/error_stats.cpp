#include "emit/eval/error_stats.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace emit {

ErrorStats summarize_errors(std::vector<double> errors_mm, int missed) {
  ErrorStats s;
  s.count = static_cast<int>(errors_mm.size());
  s.missed = missed;
  if (errors_mm.empty()) return s;
  std::sort(errors_mm.begin(), errors_mm.end());
  s.mean = std::accumulate(errors_mm.begin(), errors_mm.end(), 0.0) / s.count;
  double squares = 0;
  for (double e : errors_mm) squares += (e - s.mean) * (e - s.mean);
  s.std = s.count > 1 ? std::sqrt(squares / static_cast<double>(s.count - 1)) : 0.0;
  auto quantile = [&](double q) {  // linear interpolation between order statistics
    const double position = q * static_cast<double>(s.count - 1);
    const auto lower = static_cast<std::size_t>(std::floor(position));
    const auto upper = std::min(lower + 1, errors_mm.size() - 1);
    return errors_mm[lower] + (position - static_cast<double>(lower)) * (errors_mm[upper] - errors_mm[lower]);
  };
  s.median = quantile(0.5);
  s.p95 = quantile(0.95);
  return s;
}

double single_press_error_mm(const std::vector<Contact>& contacts, const Press& truth) {
  if (contacts.empty()) return -1.0;
  return std::hypot(contacts.front().x_mm - truth.x_mm, contacts.front().y_mm - truth.y_mm);
}

}  // namespace emit
