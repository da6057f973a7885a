#pragma once
// `emit eval --figures-of-merit` and `emit eval --resolvability`: their options and their run
// (eval_merit.cpp), hooked into `emit eval` (command_eval.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "emit/eval/figures_of_merit.hpp"
#include "emit/eval/resolvability_study.hpp"

namespace emit::cli {

struct MeritEvalArgs {
  bool figures = false, resolvability = false;
  std::string out_dir = "emit-merit";  ///< the figures' plots
  FiguresOfMeritOptions figure_options;
};

void add_merit_eval_options(CLI::App* cmd, MeritEvalArgs& args);

/// Runs --figures-of-merit or --resolvability on each chosen sheet (the 60 mm one by default) if
/// one was asked for. \return whether one was.
bool run_merit_eval(MeritEvalArgs& args, const std::string& sheet, const std::vector<Method>& methods, int mesh_seed,
                    std::uint64_t seed, bool quick);

}  // namespace emit::cli
