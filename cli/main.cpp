// emit: electromechanical impedance tomography for soft tactile sensors.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/output_file.hpp"
#include "emit/core/threads.hpp"
#include "emit/core/version.hpp"
#include "stop_on_signals.hpp"

namespace {

int run(int argc, char** argv) {
  emit::remove_temporary_files_on_signals();  // Ctrl-C leaves no hidden half-written file behind
  // A reader that goes away (`| head`) is a failed write (EPIPE) each output reports, or `emit
  // live` stops on, closing its recordings: never a silent death.
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{
      "emit: pressure images from soft tactile sensors by electromechanical impedance tomography.\n"
      "Run 'emit demo' to see it work on the built-in 60 x 60 mm sensor."};
  app.name("emit");
  app.formatter(emit::cli::help_formatter());
  app.set_version_flag("--version", std::string("emit ") + emit::version());
  app.require_subcommand(1);
  app.fallthrough();  // --threads after the command, too
  int threads = 1;
  emit::set_thread_count(threads);
  app.add_option("--threads", threads, "threads for the linear algebra (default 1)")
      ->check(emit::cli::threads_within_limit())
      ->each([](const std::string& count) {
        emit::set_thread_count(static_cast<int>(std::strtod(count.c_str(), nullptr)));
      });
  emit::cli::add_mesh_command(app);
  emit::cli::add_simulate_command(app);
  emit::cli::add_reconstruct_command(app);
  emit::cli::add_calibrate_command(app);
  emit::cli::add_eval_command(app);
  emit::cli::add_bench_command(app);
  emit::cli::add_live_command(app);
  emit::cli::add_export_command(app);
  emit::cli::add_demo_command(app);
  try {
    app.parse(argc, argv);
  } catch (const emit::cli::ExitCode& e) {
    return e.code;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "emit: %s\n", emit::cli::parse_error_message(app, e, argc, argv).c_str());
    return 2;
  } catch (const emit::Error& e) {
    std::fprintf(stderr, "emit: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "emit: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // What the command line's set-up throws (CLI11's construction errors, bad_alloc) ends here as an
  // internal error, not in std::terminate.
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "emit: internal error: %s\n", e.what());
    return 3;
  } catch (...) {
    std::fprintf(stderr, "emit: internal error\n");
    return 3;
  }
}
