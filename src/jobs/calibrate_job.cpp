#include "emit/jobs/calibrate_job.hpp"
#include "emit/mesh/sheet_file.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include "emit/acquire/electrode_health.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/output_paths.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/line_reader.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "reference_frames.hpp"

namespace emit {

namespace {

ContactLawFit fit_law_from_pairs(const std::string& path, std::size_t& pairs) {
  LineReader lines(path, "resistance-pressure pairs file");
  std::vector<double> pressure, resistance;
  for (std::string line; lines.next(line);) {
    if (lines.line_number() == 1 && line.find_first_of("0123456789") != 0) continue;  // a header
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    double p = 0, r = 0;
    int consumed = 0;
    // glibc's sscanf converts as strtod does; the field count and the end of the line reject a
    // malformed line.
    // NOLINTNEXTLINE(cert-err34-c)
    if (std::sscanf(line.c_str(), "%lf,%lf%n", &p, &r, &consumed) != 2 ||
        line.find_first_not_of(" \t", static_cast<std::size_t>(consumed)) != std::string::npos)
      throw InvalidInput(lines.where() + ": expected pressure_N_per_mm2,resistance_ohm, got " + quote_input(line));
    if (!(p > 0) || !(r > 0) || !std::isfinite(p) || !std::isfinite(r))
      throw InvalidInput(lines.where() + ": pressure and resistance must be positive, got " + quote_input(line));
    pressure.push_back(p), resistance.push_back(r);
  }
  pairs = pressure.size();
  if (pairs < 2)
    throw InvalidInput(path + ": " + std::to_string(pairs) +
                       " resistance-pressure pairs; the contact law needs at least 2");
  return fit_contact_law(pressure, resistance);
}

PressCalibrationResult calibrate_presses(const CalibrateJob& job, OutputFile& out, const Progress& progress) {
  const Sensor sensor = load_sheet_sensor(job.sensor_path);
  require_emit_protocol(sensor, job.sensor_path);
  const int N = electrode_count_of(sensor);
  const Reference reference = detail::read_reference(job.reference_path, sensor, N, progress);
  const std::vector<Frame> frames = read_frames_csv(job.frames_path, N);
  for (std::size_t f = 0; f < frames.size(); ++f)
    check_readings_in_range(frames[f], sensor.adc, job.frames_path + ": frame " + std::to_string(f));
  // Presses of unknown place or force (empty fields) are calibration's alone (io/presses_csv.hpp).
  const PressSequence truth = read_presses_csv(job.truth_path, frames.size(), UnknownPresses::allowed);
  if (truth.size() != frames.size())
    throw InvalidInput(job.truth_path + ": " + std::to_string(truth.size()) + " frames of presses for " +
                       std::to_string(frames.size()) + " frames in " + job.frames_path);
  std::size_t single = 0;
  for (const auto& presses : truth) single += presses.size() == 1;
  if (single == 0) throw InvalidInput(job.truth_path + ": no single presses to calibrate on");
  PressCalibrationResult result = calibrate_from_presses(sensor, job.options, reference, frames, truth, progress.stage);
  write_calibration(out.stream(), result.calibration, result.sheet ? &*result.sheet : nullptr);
  out.commit();
  return result;
}

}  // namespace

CalibrateReport run_calibrate_job(const CalibrateJob& job, const Progress& progress) {
  const bool presses = !job.frames_path.empty();
  if (presses && (job.reference_path.empty() || job.truth_path.empty() || job.out_path.empty()))
    throw InvalidInput("pressure calibration needs --reference, --frames, --truth and --out");
  if (!presses && job.contact_law_path.empty())
    throw InvalidInput("nothing to calibrate: give --frames (with --reference, --truth, --out) or --contact-law");
  auto [out] = open_outputs({{"--sensor", job.sensor_path},
                             {"--reference", job.reference_path},
                             {"--frames", job.frames_path},
                             {"--truth", job.truth_path},
                             {"--contact-law", job.contact_law_path}},
                            {OutputRequest{{"--out", job.out_path}}});
  CalibrateReport report;
  if (!job.contact_law_path.empty()) report.contact_law = fit_law_from_pairs(job.contact_law_path, report.pairs);
  if (presses) report.presses = calibrate_presses(job, out, progress);
  return report;
}

}  // namespace emit
