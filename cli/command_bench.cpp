// emit bench: the time of each stage, offline and per frame, at several mesh sizes and electrode
// counts, with peak memory and naive baselines measured in the same run (jobs/bench_job.hpp).
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "commands.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/jobs/bench_job.hpp"

namespace emit::cli {

namespace {

struct BenchArgs {
  BenchJob job;
  std::vector<std::string> sizes{"1.5k", "6k", "24k", "100k"};
  bool no_baselines = false;
};

/// "6k" → 6000, "1.5k" → 1500, "24000" → 24000: finite, from 1 to an int's largest (the job
/// bounds it by the sensor's mesh.max_triangles). \throw InvalidInput naming the value.
int parse_size(const std::string& text) {
  char* end = nullptr;
  double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() && (*end == 'k' || *end == 'K')) value *= 1000, ++end;
  if (end == text.c_str() || *end != '\0' || !(value >= 1 && value <= std::numeric_limits<int>::max()))
    throw InvalidInput("--sizes: " + quote_input(text) + " is not a triangle count (such as 6k or 24000)");
  return static_cast<int>(value);
}

std::string ratio_text(double baseline_s, double ours_s) {
  if (baseline_s < 0) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.1fs (%.0fx)", baseline_s, baseline_s / ours_s);
  return text;
}

void print_header(const std::string& sensor_name, bool current_injection) {
  if (current_injection) {
    std::printf(
        "emit bench: current-injection EIT difference imaging on %s (its protocol), one case a\n"
        "process, the job pyEIT's and EIDORS's users run; offline = mesh + Jacobian dlog V/dsigma by the\n"
        "adjoint method (model: the complete electrode model's assembly and factorisation, inside it) +\n"
        "the NOSER operator at the automatic lambda; per frame: the compact operator's product R*dV, and\n"
        "the dense R's (what they apply). Baseline: the K x K normal equations against Jacobian + operator.\n\n",
        sensor_name.c_str());
    const char* format = "%9s %4s %5s | %6s %6s %6s %6s %7s | %7s %9s | %7s | %14s\n";
    std::printf(format, "triangles", "el", "rank", "mesh", "model", "jacob", "oper", "offline", "product", "dense R",
                "peak", "K x K normal");
    std::printf(format, "", "", "", "s", "s", "s", "s", "s", "us", "us", "MiB", "eq. (ratio)");
    return;
  }
  std::printf(
      "emit bench: the paper method's pipeline on %s, one case a process; offline = mesh + Jacobian +\n"
      "operator; per frame: product R*dV, eq. 8, contacts, and the whole frame (dV to contacts); read:\n"
      "streaming the operator's bytes once at full memory speed, the floor under the product.\n"
      "Baselines: the K x K normal equations (against Jacobian + operator) and the Jacobian by one\n"
      "solve per element and grounding, where they finish in reasonable time.\n\n",
      sensor_name.c_str());
  const char* format = "%9s %4s %5s | %6s %6s %6s %6s %6s %7s %6s | %7s %6s %7s %7s %6s | %7s | %14s %14s\n";
  std::printf(format, "triangles", "el", "rank", "mesh", "assem", "factor", "jacob", "oper", "offline", "load",
              "product", "eq. 8", "contact", "frame", "read", "peak", "K x K normal", "brute-force J");
  std::printf(format, "", "", "", "s", "s", "s", "s", "s", "s", "ms", "us", "us", "us", "us", "us", "MiB",
              "eq. (ratio)", "(ratio)");
}

void print_row(const BenchRow& row) {
  if (!row.error.empty()) {
    std::fprintf(stderr, "emit: bench: %d electrodes, %d triangles: %s\n", row.electrodes, row.target_triangles,
                 row.error.c_str());
    return;
  }
  const PipelineTiming& t = row.timing;
  if (row.current_injection) {
    std::printf("%9ld %4d %5d | %6.3f %6.3f %6.3f %6.3f %7.3f | %7.1f %9.1f | %7.0f | %14s\n", t.triangles,
                t.electrodes, t.rank, t.mesh_s, t.factorisation_s, t.jacobian_s, t.operator_s, t.offline_s(),
                t.product_us, t.dense_product_us, row.peak_MiB,
                ratio_text(row.baselines.normal_equations_s, t.operator_s + t.jacobian_s).c_str());
    std::fflush(stdout);
    return;
  }
  std::printf(
      "%9ld %4d %5d | %6.3f %6.3f %6.3f %6.3f %6.3f %7.3f %6.1f | %7.1f %6.1f %7.1f %7.1f %6.1f | %7.0f | %14s %14s\n",
      t.triangles, t.electrodes, t.rank, t.mesh_s, t.assembly_s, t.factorisation_s, t.jacobian_s, t.operator_s,
      t.offline_s(), 1e3 * t.load_s, t.product_us, t.pressure_us, t.contacts_us, t.frame_us, t.operator_read_us,
      row.peak_MiB, ratio_text(row.baselines.normal_equations_s, t.operator_s + t.jacobian_s).c_str(),
      ratio_text(row.baselines.brute_force_jacobian_s, t.jacobian_s).c_str());
  std::fflush(stdout);
}

void run_bench(BenchArgs args) {
  args.job.triangles.clear();
  for (const std::string& text : args.sizes) args.job.triangles.push_back(parse_size(text));
  args.job.baselines = !args.no_baselines;
  bool header = false;
  const int failures = run_bench_job(
      args.job,
      [&](const BenchRow& row) {
        if (!header) print_header(row.sensor_name, row.current_injection), header = true;
        print_row(row);
      },
      stderr_progress());
  if (failures > 0) throw Error(std::to_string(failures) + " bench case(s) failed");
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand("bench", "Time every stage, offline and per frame, at several mesh sizes");
  cmd->footer(
      "Example:\n  emit bench --sizes 6k,24k --electrodes 16\nOne thread unless 'emit --threads N bench' says more.");
  cmd->add_option("--sensor", a->job.sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--sizes", a->sizes, "Triangle counts, about (default 1.5k,6k,24k,100k)")->delimiter(',');
  cmd->add_option("--electrodes", a->job.electrodes, "Electrode counts (default 16,32)")
      ->delimiter(',')
      ->check(CLI::Range(3, 256));
  cmd->add_flag("--no-baselines", a->no_baselines, "Skip the K x K normal equations baseline");
  cmd->add_flag("--brute-force", a->job.brute_force, "Also time the brute-force Jacobian (about a minute at 2.5k)");
  cmd->callback([a] { run_bench(*a); });
}

}  // namespace emit::cli
