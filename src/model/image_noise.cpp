#include "emit/model/image_noise.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "emit/core/errors.hpp"

namespace emit {

double difference_noise_V(double reading_noise_V, double reference_frames) {
  return reading_noise_V * std::sqrt(1.0 + 1.0 / std::max(reference_frames, 1.0));
}

double significance_sigmas(Index elements, double false_alarm_rate) {
  if (elements < 1) throw InvalidInput("significance: no image elements");
  if (!(false_alarm_rate > 0 && false_alarm_rate < 1))
    throw InvalidInput("significance: the false-alarm rate must be in (0, 1), got " + std::to_string(false_alarm_rate));
  // The upper tail Q(k) = erfc(k/√2)/2 falls monotonically: bisect for Q(k) = rate/#F.
  const double tail = false_alarm_rate / static_cast<double>(elements);
  double low = 0, high = 40;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (low + high);
    (0.5 * std::erfc(mid / std::sqrt(2.0)) > tail ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace emit
