#include "emit/sensor/excitation.hpp"

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

Matrix Excitation::drive_currents_A(int electrode_count) const {
  Matrix I = Matrix::Zero(electrode_count, static_cast<Index>(drives.size()));
  for (std::size_t d = 0; d < drives.size(); ++d) {
    I(drives[d].source, static_cast<Index>(d)) += current_A;
    I(drives[d].sink, static_cast<Index>(d)) -= current_A;
  }
  return I;
}

std::vector<EitDrive> drive_pattern(const std::string& name, int electrode_count) {
  const int N = electrode_count;
  if (N < 3) throw InvalidInput("drive pattern: a current-injection skin needs at least 3 electrodes");
  int skip = -1;
  if (name == "adjacent") {
    skip = 0;
  } else if (name == "opposite") {
    if (N % 2 != 0)
      throw InvalidInput("drive pattern \"opposite\": " + std::to_string(N) + " electrodes have no opposite");
    skip = N / 2 - 1;
  } else if (name.rfind("skip-", 0) == 0 && name.size() > 5 && name.size() < 9 &&
             name.find_first_not_of("0123456789", 5) == std::string::npos) {
    skip = std::stoi(name.substr(5));
    if (skip > N - 2)
      throw InvalidInput("drive pattern \"" + name + "\": skip at most " + std::to_string(N - 2) + " of " +
                         std::to_string(N) + " electrodes");
  } else {
    throw InvalidInput("drive pattern \"" + name + "\": must be adjacent, opposite or skip-<s> (e.g. skip-4)");
  }
  std::vector<EitDrive> drives(static_cast<std::size_t>(N));
  for (int k = 0; k < N; ++k) drives[static_cast<std::size_t>(k)] = {k, (k + skip + 1) % N};
  return drives;
}

std::vector<EitReading> adjacent_readings(const std::vector<EitDrive>& drives, int electrode_count, bool skip_driving) {
  const int N = electrode_count;
  std::vector<EitReading> readings;
  for (std::size_t d = 0; d < drives.size(); ++d)
    for (int m = 0; m < N; ++m) {
      const int plus = (m + 1) % N, minus = m;
      const auto driving = [&](int e) { return e == drives[d].source || e == drives[d].sink; };
      if (skip_driving && (driving(plus) || driving(minus))) continue;
      readings.push_back({static_cast<int>(d), plus, minus});
    }
  return readings;
}

void require_emit_protocol(const Sensor& sensor, const std::string& where) {
  if (sensor.excitation)
    throw InvalidInput(where +
                       ": is a current-injection skin (it has an \"excitation\"); this command models EMIT sheets. "
                       "Locate its presses with emit eval --real DIR --sensor FILE");
}

}  // namespace emit
