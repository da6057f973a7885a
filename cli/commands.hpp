#pragma once
// The emit command-line tool: one file per subcommand. A command parses its options into the
// library's job, calls it, and prints what it returns; it holds no maths and no pipeline.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "emit/core/progress.hpp"
#include "emit/core/types.hpp"
#include "emit/jobs/live_session.hpp"
#include "emit/model/method.hpp"
#include "emit/sensor/press.hpp"

namespace emit {
struct EvalCase;
struct RealisticEvaluation;
struct OutlineEvaluation;
struct RealisticSheet;
struct SimulateJob;
struct SimulateReport;
struct SheetEvalReport;
struct RealEvalJob;
struct RealEvalReport;
struct FiguresOfMeritOptions;
struct MeritEvalReport;
struct ResolvabilityOptions;
struct ResolvabilityStudy;
}  // namespace emit

namespace emit::cli {

void add_mesh_command(CLI::App& app);
void add_simulate_command(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_reconstruct_command(CLI::App& app);
void add_eval_command(CLI::App& app);
void add_calibrate_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_live_command(CLI::App& app);
void add_export_command(CLI::App& app);

/// --track-gate-mm, --track-coast-frames and --filter: the contacts' tracking (frame/contact_tracker.hpp),
/// for `emit live` and `emit reconstruct`.
void add_tracking_options(CLI::App* cmd, TrackerOptions& options);

/// Runs `emit live` (command_live.cpp): until Ctrl-C or the job's limits; prints the source, the
/// viewer's address, and frames/s and latency at the end. `emit demo` runs it too.
void run_live(const LiveJob& job);

/// Progress on stderr: stages as "<stage> ...", counts rewritten in place on a terminal (a line
/// every ~10 % otherwise; none for fewer than `min_count` items), warnings as "emit: warning: …".
Progress stderr_progress(long min_count = 0);

/// Validators whose messages name the rule and the value ("must be a positive number, got \"0\""),
/// not CLI11's range of doubles.
const CLI::Validator& positive_number();
const CLI::Validator& non_negative_number();
/// A number in [0, 1).
const CLI::Validator& fraction_below_one();
const CLI::Validator& positive_integer();
const CLI::Validator& non_negative_integer();
/// A thread count within core/limits.hpp's bound, said by its rule (limits::thread_count_rule).
const CLI::Validator& threads_within_limit();
/// A count of a real skin's presses: a whole number from 1 to io/real_dataset.hpp's bound.
const CLI::Validator& press_count();
/// A number handed to `check`, the library's own validation of it (an options struct's
/// validate()), whose message the option's error then is: the CLI refuses a value as the Python
/// module does, in the same words ("--lambda2: PipelineOptions::lambda2 must be 0 (the method's)
/// or positive, got -1").
CLI::Validator checked_by(const std::string& name, const std::function<void(double)>& check);
/// checked_by the validate() of an `Options` whose `field` holds the number, the others their defaults.
template <class Options>
CLI::Validator checked_by(double Options::*field) {
  return checked_by("NUMBER", [field](double x) {
    Options options;
    options.*field = x;
    options.validate();
  });
}
/// A seed given as `option`'s value: a whole number 0 or larger (not CLI11's unsigned parse, which
/// takes -1). \throw InvalidInput naming the option.
std::uint64_t parse_seed(const std::string& option, const std::string& text);
/// One value (a, a) or two (a range). \throw InvalidInput naming the option for another count.
std::array<double, 2> pair_or_single(const std::vector<double>& values, const std::string& option);

/// The one-line message for a command line CLI11 refused, pointing to the command's own help: an
/// option the command does not take named first, with the one meant ("emit reconstruct has no
/// option \"--referense\" (did you mean --reference? see 'emit reconstruct --help')"), a command that
/// does not exist likewise ("unknown command \"reconstuct\" (did you mean \"reconstruct\"?)"),
/// else CLI11's own.
std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv);
/// The help's layout: each option's value kind and default, without CLI11's checks' names and its
/// "Needs:"/"Excludes:" lists. Set on the app before its commands are added (they copy it).
std::shared_ptr<CLI::Formatter> help_formatter();

/// The operator cache: none with --no-cache, else --cache or the default folder.
std::string cache_dir_option(const std::string& cache_dir, bool no_cache);

/// The example sensors' folder: the installed one beside the command (bin/../share/emit/sensors,
/// cmake/install_rules.cmake) when there is one, else the source tree's examples/sensors.
std::string examples_dir();

/// `emit eval --realistic`'s table for one sheet: each figure beside its target
/// (realistic_eval_table.cpp).
void print_realistic_evaluation(const RealisticEvaluation& evaluation);
/// `emit eval --outlines`'s table for one sheet: per method, each outline family's scores
/// (outline_eval_table.cpp).
void print_outline_evaluation(const OutlineEvaluation& evaluation);
/// `emit eval`'s table for one sheet: each method's errors beside the paper's (eval_tables.cpp).
void print_sheet_evaluation(const EvalCase& eval_case, const SheetEvalReport& report, bool sweep);
/// `emit eval --real`'s report: the held-out error and its curve (eval_tables.cpp).
void print_real_evaluation(const RealEvalJob& job, const RealEvalReport& report);
/// `emit eval --figures-of-merit`'s table for one sheet: GREIT's figures per method (merit_tables.cpp).
void print_figures_of_merit(const FiguresOfMeritOptions& options, const MeritEvalReport& report);
/// `emit eval --resolvability`'s tables for one sheet: what a frame can tell (merit_tables.cpp).
void print_resolvability(const ResolvabilityOptions& options, const ResolvabilityStudy& study);

/// The realistic sheet's summary on stderr, for the user to compare a calibration with; `path`: the
/// file holding all of it.
void print_realistic_sheet(const RealisticSheet& sheet, const std::string& path);
/// What `emit simulate` did: the twin's mesh (stderr), the files written, and the frames as a
/// summary or, with `table`, each in full.
void print_simulate_report(const SimulateJob& job, const SimulateReport& report, bool table);
/// A short table of frames: presses and the largest readings.
void print_frames_summary(const std::vector<Frame>& frames, const PressSequence& presses);
/// One frame as an N×N table of volts (rows: grounded electrode, columns: sensed electrode).
void print_frame_table(const Frame& frame);

}  // namespace emit::cli
