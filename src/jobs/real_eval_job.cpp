#include "emit/jobs/real_eval_job.hpp"

#include <filesystem>

#include "emit/core/errors.hpp"
#include "emit/core/output_paths.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/render/line_plot.hpp"

namespace emit {

namespace {

void write_contacts(const RealEvaluation& e, std::ostream& out) {
  for (std::size_t k = 0; k < e.located.size(); ++k) {
    std::vector<Contact> contacts;
    if (const LocatedPress& p = e.located[k]; p.found) {
      Contact c;
      c.x_mm = p.position_mm.x();
      c.y_mm = p.position_mm.y();
      c.x_std_mm = p.x_std_mm;
      c.y_std_mm = p.y_std_mm;
      contacts.push_back(c);
    }
    write_contacts_line(out, static_cast<long>(e.calibration_presses) + static_cast<long>(k), contacts);
  }
}

std::string write_curve_plot(const RealEvalReport& report, const std::string& folder) {
  const RealEvaluation& e = report.evaluation;
  PlotSeries held_out{"held-out presses (mean)", {}, {}, series_colour(0), true, {}};
  PlotSeries validated{"cross-validated on the calibration", {}, {}, series_colour(1), true, {}};
  PlotSeries centre{"always the centre", {}, {}, series_colour(7), false, {}};
  for (const RealCurvePoint& p : e.curve) {
    held_out.x.push_back(static_cast<double>(p.calibration_presses));
    held_out.y.push_back(p.held_out.mean);
    validated.x.push_back(static_cast<double>(p.calibration_presses));
    validated.y.push_back(p.kept.cross_validated_mm);
  }
  centre.x = {held_out.x.front(), held_out.x.back()};
  centre.y = {e.held_out_centre.mean, e.held_out_centre.mean};
  PlotOptions options;
  options.title = "Position error against calibration presses";
  options.x_label = "calibration presses (the first N)";
  options.y_label = "mean error, mm";
  options.log_x = true;
  options.log_y = true;
  std::string path = (std::filesystem::path(folder) / "real_error_vs_calibration.png").string();
  write_png(render_line_plot({held_out, validated, centre}, options), path);
  return path;
}

}  // namespace

RealEvalReport run_real_eval_job(const RealEvalJob& job, const Progress& progress) {
  const auto in = [&](const char* name) { return (std::filesystem::path(job.folder) / name).string(); };
  auto [contacts] = open_outputs({{"--real", in("frames.csv")},
                                  {"--real", in("references_per_frame.csv")},
                                  {"--real", in("reference.csv")},
                                  {"--real", in("truth.csv")},
                                  {"--sensor", job.sensor_path}},
                                 {OutputRequest{{"--contacts", job.contacts_path}}});
  if (!job.plots_dir.empty()) prepare_output_folder({"--plots", job.plots_dir});
  const Sensor sensor = load_sheet_sensor(job.sensor_path);
  if (!sensor.excitation)
    throw InvalidInput(job.sensor_path +
                       ": has no \"excitation\"; emit eval --real needs a current-injection "
                       "skin's protocol (README \"Current-injection skins\")");
  progress.say("reading " + job.folder);
  const RealDataset data = read_real_dataset(job.folder);
  RealEvalReport report;
  report.sensor_name = sensor.name;
  report.evaluation = evaluate_real(data, sensor, job.options, progress);
  if (contacts.given()) {
    write_contacts(report.evaluation, contacts.stream());
    contacts.commit();
  }
  if (!job.plots_dir.empty()) report.plot_path = write_curve_plot(report, job.plots_dir);
  return report;
}

}  // namespace emit
