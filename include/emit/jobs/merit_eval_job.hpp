#pragma once
/// \file merit_eval_job.hpp
/// `emit eval --figures-of-merit` (GREIT's figures per method against place, with their plots:
/// eval/figures_of_merit.hpp) and `emit eval --resolvability` (what a frame can tell:
/// eval/resolvability_study.hpp), a sheet at a time.
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/eval/figures_of_merit.hpp"
#include "emit/eval/resolvability_study.hpp"

namespace emit {

struct MeritEvalReport {
  FiguresOfMerit merit;
  std::vector<std::string> plots;  ///< written into the output folder (none without one)
};

/// The figures of merit on one sheet; a plot per figure into `out_dir` unless empty (made before
/// any work). \throw InvalidInput (a bad option, a curved sheet), IoError, SolverError.
MeritEvalReport run_figures_of_merit_job(const EvalCase& eval_case, const FiguresOfMeritOptions& options,
                                         const std::string& out_dir, const Progress& progress = {});

/// What a frame of one (flat) sheet can tell: its fit model built, then the study.
/// \throw InvalidInput (a bad option, a curved sheet), SolverError.
ResolvabilityStudy run_resolvability_job(const EvalCase& eval_case, const ResolvabilityOptions& options,
                                         const Progress& progress = {});

}  // namespace emit
