#pragma once
/// \file error_stats.hpp
/// Summaries of positional errors as the paper reports them (§3.2: mean ± std), with the median
/// and 95th percentile, and how many presses were not found at all.
#include <vector>

#include "emit/frame/contacts.hpp"
#include "emit/sensor/press.hpp"

namespace emit {

struct ErrorStats {
  int count = 0;   ///< presses found
  int missed = 0;  ///< presses with no contact
  double mean = 0, std = 0, median = 0, p95 = 0;
};

/// \param errors_mm one per found press. Standard deviation with n − 1.
ErrorStats summarize_errors(std::vector<double> errors_mm, int missed);

/// The distance from a contact to a press's centre, in 3D (on a flat sheet both have z = 0).
double position_error_mm(const Contact& contact, const Press& press);
/// The distance from a point to a press's centre, in 3D.
double position_error_mm(const Vector3& point_mm, const Press& press);

/// For a single-press frame: the distance from the strongest contact (largest force, the first)
/// to the press centre, or a negative value when there is no contact.
double single_press_error_mm(const std::vector<Contact>& contacts, const Press& truth);

}  // namespace emit
