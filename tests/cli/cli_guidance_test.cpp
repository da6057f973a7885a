// The command line guides as a good Unix tool's does (suite CliGuidance; each run parses and
// stops, well under a second): a mistyped option is named with the one meant and the command's own
// help, in every command; the help shows each option's value kind in plain words.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace emit {
namespace {

using test::run_emit;

struct Typo {
  std::string name;       ///< the test's
  std::string arguments;  ///< as typed
  std::string message;    ///< stderr, whole
};

class CliGuidance : public ::testing::TestWithParam<Typo> {};

// Exit 2 (a command line refused) and one line: the option as typed, the one meant, the command's
// help. Before, `--referense x` said "--reference is required (see 'emit --help')" and `--imagess
// m2/` "The following arguments were not expected: m2/ --imagess".
TEST_P(CliGuidance, AMistypedOptionIsNamedWithTheOneMeant) {
  const auto r = run_emit(GetParam().arguments);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err, "emit: " + GetParam().message + "\n");
  EXPECT_EQ(r.out, "");
}

std::string meant(const std::string& typed, const std::string& option, const std::string& command) {
  return "unknown option \"" + typed + "\" (did you mean " + option + "? see 'emit " + command + " --help')";
}

INSTANTIATE_TEST_SUITE_P(
    EachCommand, CliGuidance,
    ::testing::Values(
        Typo{"mesh", "mesh --ot m.msh", meant("--ot", "--out", "mesh")},
        Typo{"simulate", "simulate --pres 30,30,5,10 --out f.csv", meant("--pres", "--press", "simulate")},
        Typo{"reconstruct", "reconstruct --referense ref.csv --frames f.csv",
             meant("--referense", "--reference", "reconstruct")},
        Typo{"reconstruct_images", "reconstruct --imagess m2/", meant("--imagess", "--images", "reconstruct")},
        Typo{"calibrate", "calibrate --frame f.csv", meant("--frame", "--frames", "calibrate")},
        Typo{"eval", "eval --realistc", meant("--realistc", "--realistic", "eval")},
        Typo{"bench", "bench --size 6k", meant("--size", "--sizes", "bench")},
        Typo{"live", "live --sourc sim", meant("--sourc", "--source", "live")},
        Typo{"export", "export r.emitrec --frame f.csv", meant("--frame", "--frames", "export")},
        Typo{"demo", "demo --second 3", meant("--second", "--seconds", "demo")},
        // Begun, not finished: the only option it begins.
        Typo{"prefix", "reconstruct --calib c.json", meant("--calib", "--calibration", "reconstruct")},
        // With its value after '=': the name alone is compared.
        Typo{"with_value", "live --fsp=10", meant("--fsp", "--fps", "live")},
        // Nothing near: where the options are.
        Typo{"far_from_all", "reconstruct --xyz",
             "unknown option \"--xyz\"; the options of emit reconstruct are in 'emit reconstruct --help'"},
        // An option given no value; a negative number is a value, not an option.
        Typo{"no_value", "simulate --press -3,4 --out", "--out needs a value (see 'emit simulate --help')"},
        Typo{"misspelled_command", "reconstuct --frames x",
             "unknown command \"reconstuct\" (did you mean \"reconstruct\"?); the commands are in 'emit --help'"},
        Typo{"no_command", "--threads 2", "no command given: try 'emit demo', or see 'emit --help'"}),
    [](const auto& info) { return info.param.name; });

// Every command's help: a line of what it does, an example that runs, and each option's value kind
// without the checks' names or CLI11's "Needs:" lists (a line read "--sensor FILE Needs: --real
// With --real: ...").
TEST(CliHelp, EachCommandSaysWhatItDoesWithAnExample) {
  for (const std::string command :
       {"mesh", "simulate", "reconstruct", "calibrate", "eval", "bench", "live", "export", "demo"}) {
    const auto r = run_emit(command + " --help");
    ASSERT_EQ(r.exit_code, 0) << command << ": " << r.err;
    EXPECT_NE(r.out.find("\nUsage: emit " + command + " [OPTIONS]"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\nExample"), std::string::npos) << command << " has no example:\n" << r.out;
    EXPECT_NE(r.out.find("\n  emit " + command + " "), std::string::npos) << r.out;
    for (const char* noise :
         {"Needs:", "Excludes:", ":PRESSES", ":POSITIVE", ":NUMBER", "TEXT:FILE", "{false}", "issue ", "Options::"})
      EXPECT_EQ(r.out.find(noise), std::string::npos) << command << " --help shows \"" << noise << "\":\n" << r.out;
  }
  const auto eval = run_emit("eval --help");
  EXPECT_NE(eval.out.find("  --sensor FILE "), std::string::npos) << eval.out;
  EXPECT_NE(eval.out.find("  --calibration-presses INT "), std::string::npos) << eval.out;
  const auto calibrate = run_emit("calibrate --help");
  EXPECT_EQ(calibrate.out.find("paper eq. 8"), std::string::npos) << "it fits the sheet, not eq. 8 alone";
}

}  // namespace
}  // namespace emit
