// `emit eval --figures-of-merit` and `emit eval --resolvability` (eval_merit.hpp).
#include "eval_merit.hpp"

#include <cstdio>

#include "commands.hpp"
#include "emit/core/errors.hpp"
#include "emit/jobs/eval_job.hpp"
#include "emit/jobs/merit_eval_job.hpp"

namespace emit::cli {

void add_merit_eval_options(CLI::App* cmd, MeritEvalArgs& args) {
  CLI::Option* figures = cmd->add_flag("--figures-of-merit", args.figures,
                                       "GREIT's figures of merit (AR, PE, RES, SD, RNG) per method, of small presses "
                                       "from the centre towards the border, with a plot per figure (--out)");
  CLI::Option* resolvability =
      cmd->add_flag("--resolvability", args.resolvability,
                    "What a frame can tell, from the exact model and the noise: the Cramer-Rao bound on a round "
                    "press's radius, centre and force; the smallest gap between two bars; a ring's hole");
  figures->excludes(resolvability);
  cmd->add_option("--out", args.out_dir, "With --figures-of-merit: the plots' folder (\"\": none)")
      ->capture_default_str()
      ->needs(figures);
  cmd->add_option("--radius-mm", args.figure_options.radius_mm, "With --figures-of-merit: the presses' radius")
      ->check(checked_by(&FiguresOfMeritOptions::radius_mm))
      ->capture_default_str()
      ->needs(figures);
  cmd->add_option("--force-N", args.figure_options.force_N, "With --figures-of-merit: the presses' force")
      ->check(checked_by(&FiguresOfMeritOptions::force_N))
      ->capture_default_str()
      ->needs(figures);
}

bool run_merit_eval(MeritEvalArgs& args, const std::string& sheet, const std::vector<Method>& methods, int mesh_seed,
                    std::uint64_t seed, bool quick) {
  if (!args.figures && !args.resolvability) return false;
  const std::vector<EvalSheet> sheets = eval_sheets(examples_dir(), sheet.empty() ? "60" : sheet);
  if (args.figures) {
    FiguresOfMeritOptions& o = args.figure_options;
    o.methods = methods, o.mesh_seed = mesh_seed, o.seed = seed;
    if (quick) o.step_mm = 9, o.rays = 1;
    o.validate();
    std::printf(
        "emit eval --figures-of-merit: GREIT's figures (Adler et al. 2009) of each method's image of small presses, "
        "twin on a mesh of its own (seed %d)%s\n"
        "  AR: the image's integral per newton (-dphi: a linear method's image delta phi; -P and fit: the pressure "
        "picture); PE > 0: drawn towards the centre\n",
        mesh_seed, quick ? " (--quick: a few places)" : "");
    for (const auto& [c, electrodes] : sheets) {
      std::printf("\n%s, %d electrodes\n", c.name.c_str(), electrodes);
      std::fflush(stdout);
      print_figures_of_merit(o, run_figures_of_merit_job(c, o, args.out_dir, stderr_progress()));
    }
    return true;
  }
  const ResolvabilityOptions o = quick ? quick_resolvability_options() : ResolvabilityOptions{};
  std::printf(
      "emit eval --resolvability: what a frame can tell, from the exact forward model (the fit mesh's Green's "
      "function) and the readings' noise%s\n",
      quick ? " (--quick: a few cases)" : "");
  for (const auto& [c, electrodes] : sheets) {
    std::printf("\n%s, %d electrodes\n", c.name.c_str(), electrodes);
    std::fflush(stdout);
    print_resolvability(o, run_resolvability_job(c, o, stderr_progress()));
  }
  return true;
}

}  // namespace emit::cli
