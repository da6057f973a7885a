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

double position_error_mm(const Vector3& point_mm, const Press& press) {
  return (point_mm - Vector3(press.x_mm, press.y_mm, press.z_mm)).norm();
}

double position_error_mm(const Contact& contact, const Press& press) {
  return position_error_mm(Vector3(contact.x_mm, contact.y_mm, contact.z_mm), press);
}

double single_press_error_mm(const std::vector<Contact>& contacts, const Press& truth) {
  if (contacts.empty()) return -1.0;
  return position_error_mm(contacts.front(), truth);
}

}  // namespace emit
