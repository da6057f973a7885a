// The live simulator's twin (TwinOptions::condensed_frames) gives the frames the direct solve
// gives, on the twin's own mesh: the live figure-eight's presses on the default sheet and on the
// dome (3D cells on a curved sheet), to test::solve_roundoff of the largest potential (both solve
// the same system; the condensation only eliminates it in another order).
#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/twin/sim_source.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

double worst_difference(const std::string& sheet, SimScript::Kind kind) {
  const Sensor sensor = load_sheet_sensor(test::source_path("examples/sensors/" + sheet));
  TwinOptions direct_options, condensed_options;
  direct_options.adc = condensed_options.adc = false;
  condensed_options.condensed_frames = true;
  Twin direct(sensor, direct_options), condensed(sensor, condensed_options);
  SimScript script;
  script.kind = kind;
  const SimSource source(sensor, script, SourceOptions{});
  double worst = 0;
  int pressed = 0;
  for (std::uint64_t k = 15; k < 15 + 300; k += 23) {  // 6 s of the script, every 23rd frame
    const std::vector<Press> presses = source.presses_of(k);
    pressed += !presses.empty();
    const Frame a = direct.exact_frame(presses), b = condensed.exact_frame(presses);
    const double scale = a.cwiseAbs().maxCoeff();
    if (scale > 0) worst = std::max(worst, (a - b).cwiseAbs().maxCoeff() / scale);
    else EXPECT_EQ(b.cwiseAbs().maxCoeff(), 0.0);
  }
  EXPECT_GE(pressed, 8);
  std::printf("%s: condensed against direct, at most %.2e of the largest potential\n", sheet.c_str(), worst);
  return worst;
}

TEST(CondensedTwin, LiveFramesEqualTheDirectSolveOnTheDefaultSheet) {
  EXPECT_LE(worst_difference("default60.json", SimScript::Kind::loop), test::solve_roundoff);
}

TEST(CondensedTwin, RandomPressesEqualTheDirectSolveOnTheDome) {
  EXPECT_LE(worst_difference("dome25.json", SimScript::Kind::random), test::solve_roundoff);
}

TEST(CondensedTwin, RefusedWithAResistiveDrivingLayer) {
  TwinOptions options;
  options.condensed_frames = true;
  options.driving_sheet_resistance_ohm_per_sq = 10;
  EXPECT_THROW(options.validate(), InvalidInput);
}

}  // namespace
}  // namespace emit
