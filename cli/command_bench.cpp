// emit bench: the time of each stage, offline and per frame, at several mesh sizes and electrode
// counts, with peak memory and naive baselines measured in the same run. Each case runs in a
// child process of its own, so its peak memory is its own.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "emit/errors.hpp"
#include "emit/eval/pipeline_timing.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit::cli {

namespace {

struct BenchArgs {
  std::string sensor_path;
  std::vector<std::string> sizes{"1.5k", "6k", "24k", "100k"};
  std::vector<int> electrodes{16, 32};
  bool no_baselines = false, brute_force = false;
};

// The baselines grow as K³ (the K×K Cholesky: ~8 s at 6.8k triangles) and as K·N sparse solves
// (the brute-force Jacobian: ~1 min at 2.5k); above these sizes they would take the run over.
constexpr long max_normal_equations_triangles = 7000;
constexpr long max_brute_force_triangles = 2500;

/// "6k" → 6000, "1.5k" → 1500, "24000" → 24000. \throw InvalidInput naming the value.
int parse_size(const std::string& text) {
  try {
    std::size_t used = 0;
    double value = std::stod(text, &used);
    if (used < text.size() && (text.substr(used) == "k" || text.substr(used) == "K")) value *= 1000, ++used;
    if (used != text.size() || !(value >= 1)) throw std::invalid_argument(text);
    return static_cast<int>(value);
  } catch (const std::exception&) {
    throw InvalidInput("--sizes: \"" + text + "\" is not a triangle count (such as 6k or 24000)");
  }
}

/// The sensor with `count` electrodes by the default layout, at its own electrode width.
Sensor with_electrodes(const Sensor& sensor, int count) {
  if (count == sensor.electrode_count()) return sensor;
  nlohmann::json j = sensor_to_json(sensor);
  if (j.at("shape").at("type") == "mesh") throw InvalidInput("--electrodes: a mesh-file sensor keeps its own electrodes");
  j["electrodes"] = {{"count", count}, {"width_mm", sensor.electrodes.at(0).width_mm}};
  return parse_sensor(j, "--electrodes " + std::to_string(count));
}

/// What a child sends back: its result, or the error that stopped it.
template <class Result>
struct ChildReport {
  Result result;
  char error[240] = "";
};

/// Runs `work` in a child process, so the peak memory measured is its own.
/// \return the child's report; `peak_MiB` its peak resident memory.
template <class Result, class Work>
ChildReport<Result> run_in_child(Work&& work, double& peak_MiB) {
  int channel[2];
  if (::pipe(channel) != 0) throw IoError("bench: cannot create a pipe");
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) throw IoError("bench: cannot fork");
  if (child == 0) {
    ::close(channel[0]);
    ChildReport<Result> report;
    try {
      report.result = work();
    } catch (const std::exception& e) {
      std::snprintf(report.error, sizeof report.error, "%s", e.what());
    }
    const bool sent = ::write(channel[1], &report, sizeof report) == static_cast<ssize_t>(sizeof report);
    ::_exit(sent ? 0 : 1);
  }
  ::close(channel[1]);
  ChildReport<Result> report;
  const bool received = ::read(channel[0], &report, sizeof report) == static_cast<ssize_t>(sizeof report);
  ::close(channel[0]);
  int status = 0;
  rusage usage{};
  ::wait4(child, &status, 0, &usage);
  peak_MiB = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
  if (!received)
    std::snprintf(report.error, sizeof report.error, "the process ended without a result (status %d)", status);
  return report;
}

std::string ratio_text(double baseline_s, double ours_s) {
  if (baseline_s < 0) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.1fs (%.0fx)", baseline_s, baseline_s / ours_s);
  return text;
}

void print_header() {
  std::printf("%9s %4s %5s | %6s %6s %6s %6s %6s %7s %6s | %7s %6s %7s %7s %6s | %7s | %14s %14s\n", "triangles",
              "el", "rank", "mesh", "assem", "factor", "jacob", "oper", "offline", "load", "product", "eq. 8", "contact",
              "frame", "read", "peak", "K x K normal", "brute-force J");
  std::printf("%9s %4s %5s | %6s %6s %6s %6s %6s %7s %6s | %7s %6s %7s %7s %6s | %7s | %14s %14s\n", "", "", "", "s",
              "s", "s", "s", "s", "s", "ms", "us", "us", "us", "us", "us", "MiB", "eq. (ratio)", "(ratio)");
}

void print_row(const PipelineTiming& t, const BaselineTiming& b, double peak_MiB) {
  std::printf("%9ld %4d %5d | %6.3f %6.3f %6.3f %6.3f %6.3f %7.3f %6.1f | %7.1f %6.1f %7.1f %7.1f %6.1f | %7.0f | %14s %14s\n",
              t.triangles, t.electrodes, t.rank, t.mesh_s, t.assembly_s, t.factorisation_s, t.jacobian_s, t.operator_s,
              t.offline_s(), 1e3 * t.load_s, t.product_us, t.pressure_us, t.contacts_us, t.frame_us, t.operator_read_us, peak_MiB,
              ratio_text(b.normal_equations_s, t.operator_s + t.jacobian_s).c_str(),
              ratio_text(b.brute_force_jacobian_s, t.jacobian_s).c_str());
  std::fflush(stdout);
}

void run_bench(const BenchArgs& args) {
  const Sensor sensor = sensor_from_option(args.sensor_path);
  std::vector<int> sizes;
  for (const std::string& text : args.sizes) sizes.push_back(parse_size(text));
  const std::string scratch = (std::filesystem::temp_directory_path() / ("emit-bench-" + std::to_string(::getpid()))).string();
  std::printf("emit bench: the paper method's pipeline on %s, one case a process; offline = mesh + Jacobian +\n"
              "operator; per frame: product R*dV, eq. 8, contacts, and the whole frame (dV to contacts); read:\n"
              "streaming the operator's bytes once at full memory speed, the floor under the product.\n"
              "Baselines: the K x K normal equations (against Jacobian + operator) and the Jacobian by one\n"
              "solve per element and grounding, where they finish in reasonable time.\n\n",
              sensor.name.c_str());
  print_header();
  int failures = 0;
  for (int electrodes : args.electrodes) {
    const Sensor case_sensor = with_electrodes(sensor, electrodes);
    for (int size : sizes) {
      std::fprintf(stderr, "timing %d electrodes, about %d triangles ...\n", electrodes, size);
      PipelineTimingOptions options;
      options.target_triangles = size;
      options.cache_dir = scratch;
      double peak_MiB = 0, baseline_peak_MiB = 0;
      const auto ours = run_in_child<PipelineTiming>([&] { return time_pipeline(case_sensor, options); }, peak_MiB);
      if (ours.error[0]) {
        std::fprintf(stderr, "emit: bench: %d electrodes, %d triangles: %s\n", electrodes, size, ours.error);
        ++failures;
        continue;
      }
      options.element_size_mm = ours.result.element_size_mm;  // the same mesh
      const bool normal_equations = !args.no_baselines && ours.result.triangles <= max_normal_equations_triangles;
      const bool brute_force = args.brute_force && ours.result.triangles <= max_brute_force_triangles;
      ChildReport<BaselineTiming> baselines;
      if (normal_equations || brute_force)
        baselines = run_in_child<BaselineTiming>(
            [&] { return time_baselines(case_sensor, options, normal_equations, brute_force); }, baseline_peak_MiB);
      if (baselines.error[0]) std::fprintf(stderr, "emit: bench: baseline: %s\n", baselines.error);
      print_row(ours.result, baselines.result, peak_MiB);
    }
  }
  std::error_code ignored;
  std::filesystem::remove_all(scratch, ignored);
  if (failures > 0) throw Error(std::to_string(failures) + " bench case(s) failed");
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand("bench", "Time every stage, offline and per frame, at several mesh sizes");
  cmd->footer("Single thread unless 'emit --threads N bench'. Example:\n  emit bench --sizes 6k,24k --electrodes 16");
  cmd->add_option("--sensor", a->sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--sizes", a->sizes, "Triangle counts, about (default 1.5k,6k,24k,100k)")->delimiter(',');
  cmd->add_option("--electrodes", a->electrodes, "Electrode counts (default 16,32)")
      ->delimiter(',')
      ->check(CLI::Range(3, 256));
  cmd->add_flag("--no-baselines", a->no_baselines, "Skip the K x K normal equations baseline");
  cmd->add_flag("--brute-force", a->brute_force, "Also time the brute-force Jacobian (about a minute at 2.5k)");
  cmd->callback([a] { run_bench(*a); });
}

}  // namespace emit::cli
