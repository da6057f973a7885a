#include "reconstruct_inputs.hpp"

#include <variant>

#include "emit/io/calibration_json.hpp"
#include "emit/pipeline/pipeline.hpp"

namespace emit::detail {

std::optional<Calibration> load_job_calibration(const std::string& path, Method method, const Progress& progress) {
  if (path.empty()) return std::nullopt;
  Calibration calibration = load_calibration(path);
  check_calibration_for_method(calibration, method, path);
  if (const auto* linear = std::get_if<LinearCalibration>(&calibration); linear && !linear->force_law)
    progress.warn(path +
                  ": no force_law (written before emit calibrated forces): each contact's force and area are eq. "
                  "8's over its 50 % region, the image's, several times the press's; run emit calibrate again");
  return calibration;
}

std::vector<int> leave_out_dead(const std::vector<DeadElectrode>& dead, int electrode_count, const Progress& progress) {
  std::vector<int> excluded;
  for (const DeadElectrode& d : dead) {
    progress.warn("electrode " + std::to_string(d.electrode) + " " + d.reason + ": leaving out its " +
                  std::to_string(2 * (electrode_count - 1)) + " measurements");
    excluded.push_back(d.electrode);
  }
  return excluded;
}

}  // namespace emit::detail
