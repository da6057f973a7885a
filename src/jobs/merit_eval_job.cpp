#include "emit/jobs/merit_eval_job.hpp"

#include "emit/core/output_paths.hpp"
#include "emit/model/fit_model.hpp"

namespace emit {

MeritEvalReport run_figures_of_merit_job(const EvalCase& eval_case, const FiguresOfMeritOptions& options,
                                         const std::string& out_dir, const Progress& progress) {
  options.validate();
  require_flat_sheet(eval_case.sensor, "--figures-of-merit on the " + eval_case.name);
  if (!out_dir.empty()) prepare_output_folder({"--out", out_dir});  // before minutes of work
  MeritEvalReport report;
  report.merit = evaluate_figures_of_merit(eval_case, options, progress);
  if (!out_dir.empty()) report.plots = write_figure_of_merit_plots(eval_case, report.merit, out_dir);
  return report;
}

ResolvabilityStudy run_resolvability_job(const EvalCase& eval_case, const ResolvabilityOptions& options,
                                         const Progress& progress) {
  options.validate();
  require_flat_sheet(eval_case.sensor, "--resolvability on the " + eval_case.name);
  progress.say("  the fit model");
  const FitModel fit = build_fit_model(eval_case.sensor);
  return study_resolvability(eval_case.sensor, fit, options, progress);
}

}  // namespace emit
