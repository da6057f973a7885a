#pragma once
/// \file eval_job.hpp
/// `emit eval` on the digital twin: the standard sheets, each evaluated per method beside the
/// paper's figures (eval/sheet_evaluation.hpp) with its plots, or the round a user runs with a real
/// sheet on a realistic one (`--realistic`, eval/realistic_evaluation.hpp), or pressed regions of
/// many outlines (`--outlines`, eval/outline_evaluation.hpp), or touches over time (`--tracking`,
/// eval/tracking_evaluation.hpp). A sheet at a time, so
/// the command can print each as it is done (an evaluation runs for minutes).
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/eval/outline_evaluation.hpp"
#include "emit/eval/realistic_evaluation.hpp"
#include "emit/eval/sheet_evaluation.hpp"
#include "emit/eval/tracking_evaluation.hpp"

namespace emit {

struct EvalSheet {
  EvalCase eval_case;
  int electrodes = 0;
};

/// The standard sheets (eval/sheet_evaluation.hpp) whose name begins with `sheet` (all for ""):
/// "60" is the 60 mm sheet, not the sleeve 60 mm long. \throw InvalidInput if none does.
std::vector<EvalSheet> eval_sheets(const std::string& examples_dir, const std::string& sheet);

struct SheetEvalReport {
  SheetEvaluation evaluation;
  std::vector<std::string> plots;  ///< written into the plots' folder (none without one)
};

/// One sheet evaluated; its error-versus-λ² and L-curve plots into `plots_dir` unless empty.
/// \throw InvalidInput (a bad option), IoError (a plot that cannot be written; a plots folder
/// that cannot be made, such as an existing file, before any work).
SheetEvalReport run_sheet_eval_job(const EvalCase& eval_case, const EvalOptions& options, const std::string& plots_dir,
                                   const Progress& progress = {});

/// The realistic round on one sheet. \throw InvalidInput (a bad option), SolverError.
RealisticEvaluation run_realistic_eval_job(const EvalCase& eval_case, const RealisticEvalOptions& options,
                                           const Progress& progress = {});

/// Pressed outlines scored per method on one flat sheet. \throw InvalidInput (a bad option, a
/// curved sheet), SolverError.
OutlineEvaluation run_outline_eval_job(const EvalCase& eval_case, const OutlineEvalOptions& options,
                                       const Progress& progress = {});

/// Touches over time on one sheet: crossings, a still press, steps. \throw InvalidInput (a bad
/// option, a sheet without room), SolverError.
TrackingEvaluation run_tracking_eval_job(const EvalCase& eval_case, const TrackingEvalOptions& options,
                                         const Progress& progress = {});

}  // namespace emit
