#include "emit/jobs/eval_job.hpp"

#include "emit/core/errors.hpp"
#include "emit/core/output_paths.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/pipeline/pipeline.hpp"

namespace emit {

std::vector<EvalSheet> eval_sheets(const std::string& examples_dir, const std::string& sheet) {
  std::vector<EvalSheet> sheets;
  for (EvalCase& c : standard_eval_cases(examples_dir))
    if (c.name.rfind(sheet, 0) == 0) sheets.push_back({c, electrode_count_of(c.sensor)});
  if (sheets.empty())
    throw InvalidInput("--sheet " + quote_input(sheet) +
                       ": no sheet's name begins with it (60, 30, circle, 120, dome, sleeve, fingertip)");
  return sheets;
}

SheetEvalReport run_sheet_eval_job(const EvalCase& eval_case, const EvalOptions& options, const std::string& plots_dir,
                                   const Progress& progress) {
  if (!plots_dir.empty()) prepare_output_folder({"--plots", plots_dir});  // before minutes of work
  SheetEvalReport report;
  report.evaluation = evaluate_sheet(eval_case, options, progress);
  if (!plots_dir.empty()) report.plots = write_sweep_plots(eval_case, report.evaluation, plots_dir);
  return report;
}

RealisticEvaluation run_realistic_eval_job(const EvalCase& eval_case, const RealisticEvalOptions& options,
                                           const Progress& progress) {
  options.validate();
  return evaluate_realistic_sheet(eval_case, options, progress);
}

OutlineEvaluation run_outline_eval_job(const EvalCase& eval_case, const OutlineEvalOptions& options,
                                       const Progress& progress) {
  return evaluate_outlines(eval_case, options, progress);
}

TrackingEvaluation run_tracking_eval_job(const EvalCase& eval_case, const TrackingEvalOptions& options,
                                         const Progress& progress) {
  return evaluate_tracking(eval_case, options, progress);
}

}  // namespace emit
