#include "emit/jobs/calibrate_job.hpp"

#include <cstdio>
#include <fstream>
#include <vector>

#include "emit/core/errors.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {

namespace {

ContactLawFit fit_law_from_pairs(const std::string& path, std::size_t& pairs) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open resistance-pressure pairs");
  std::vector<double> pressure, resistance;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (number == 1 && line.find_first_of("0123456789") != 0) continue;  // a header
    double p = 0, r = 0;
    // glibc's sscanf converts as strtod does; the field count rejects a malformed line.
    if (std::sscanf(line.c_str(), "%lf,%lf", &p, &r) != 2)  // NOLINT(cert-err34-c)
      throw InvalidInput(path + ":" + std::to_string(number) + ": expected pressure_N_per_mm2,resistance_ohm");
    pressure.push_back(p), resistance.push_back(r);
  }
  pairs = pressure.size();
  return fit_contact_law(pressure, resistance);
}

PressCalibrationResult calibrate_presses(const CalibrateJob& job, const Progress& progress) {
  const Sensor sensor = job.sensor_path.empty() ? default_sensor() : load_sensor(job.sensor_path);
  const int N = electrode_count_of(sensor);
  const Frame reference = average_frames(read_frames_csv(job.reference_path, N));
  const std::vector<Frame> frames = read_frames_csv(job.frames_path, N);
  const PressSequence truth = read_presses_csv(job.truth_path);
  if (truth.size() != frames.size())
    throw InvalidInput(job.truth_path + ": " + std::to_string(truth.size()) + " frames of presses for " +
                       std::to_string(frames.size()) + " frames in " + job.frames_path);
  std::size_t single = 0;
  for (const auto& presses : truth) single += presses.size() == 1;
  if (single == 0) throw InvalidInput(job.truth_path + ": no single presses to calibrate on");
  PressCalibrationResult result = calibrate_from_presses(sensor, job.options, reference, frames, truth, progress.stage);
  write_calibration(job.out_path, result.calibration);
  return result;
}

}  // namespace

CalibrateReport run_calibrate_job(const CalibrateJob& job, const Progress& progress) {
  const bool presses = !job.frames_path.empty();
  if (presses && (job.reference_path.empty() || job.truth_path.empty() || job.out_path.empty()))
    throw InvalidInput("pressure calibration needs --reference, --frames, --truth and --out");
  if (!presses && job.contact_law_path.empty())
    throw InvalidInput("nothing to calibrate: give --frames (with --reference, --truth, --out) or --contact-law");
  CalibrateReport report;
  if (!job.contact_law_path.empty()) report.contact_law = fit_law_from_pairs(job.contact_law_path, report.pairs);
  if (presses) report.presses = calibrate_presses(job, progress);
  return report;
}

}  // namespace emit
