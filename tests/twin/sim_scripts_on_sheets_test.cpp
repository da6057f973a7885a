// A simulated minute of every live script on every built-in sheet stays on the sheet (issue 32:
// `emit live --sensor dome25.json --source sim` failed after 3 s, its finger at the dome's apex
// "off the sheet"). A minute at 50 frames/s is 3,000 frames and a twin frame costs ~38 ms, so
// each script's presses are checked without solving them: every one placed as the twin places it
// (Twin::placed, which validates it as every frame does), its centre the indenter's radius + 3 mm
// from the border in 3D (twin/sim_script.hpp); then a real frame at the riskiest moments (the press
// nearest the border, the first press, at the middle: the dome's apex), with all of its disc
// loaded. The sheets are examples/sensors/*.json as the folder holds them, and the built-in default.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/press_contact.hpp"
#include "emit/twin/sim_script.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

constexpr double frames_per_s = 50;
constexpr std::uint64_t minute_frames = 60ull * 50;

/// "default" (the built-in sensor) and the name of every examples/sensors/*.json.
std::vector<std::string> built_in_sheets() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("examples/sensors")))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  names.insert(names.begin(), "default");
  return names;
}

/// How far a press's centre is from the sheet's border in 3D, where its disc ends (it loads what
/// is within its radius in 3D, twin/press_contact.hpp): to the nearest of the border's points on
/// the surface, every 0.1 mm along it (the nearest is then found to 0.05 mm); a sleeve's ends
/// along its axis (its seam is no border). Negative off the sheet.
class BorderDistance {
 public:
  explicit BorderDistance(const Sensor& sensor) : sensor_(sensor), outline_(sheet_outline(sensor)) {
    const auto samples = static_cast<int>(std::ceil(outline_.length_mm() / 0.1));
    for (int k = 0; k < samples && !is_sleeve(sensor.shape); ++k)
      points_.push_back(surface_point_mm(sensor.shape, outline_.point_at(outline_.length_mm() * k / samples)));
  }
  double operator()(const Press& press) const {
    const Vector2 chart = press_chart_mm(sensor_.shape, press);
    if (is_sleeve(sensor_.shape) || !outline_.contains(chart))
      return chart_distance_to_border_mm(sensor_.shape, outline_, chart);
    const Vector3 centre(press.x_mm, press.y_mm, press.z_mm);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vector3& p : points_) nearest = std::min(nearest, (p - centre).norm());
    return nearest;
  }

 private:
  const Sensor& sensor_;
  const Border& outline_;
  std::vector<Vector3> points_;
};

/// Σ ∫ g dA of the press's contact as the twin loads it, over that of its whole disc, πr²·g(F/πr²).
/// 1 on a flat sheet and on the dome (Archimedes: a ball centred on a sphere cuts πr² from it),
/// up to the edge's quadrature (h/64) and the mesh's chords; the sleeve's and the patch's area
/// within 5 mm of a point is at most 0.5 % more (arc 2R·asin(s/2R) over chord s), the fingertip's
/// (radius 9 mm) 1.3 %. A disc partly off the sheet loses its part outside.
double loaded_fraction(const Twin& twin, const Press& press) {
  const ContactLoad load = press_contact_load(twin.mesh(), twin.placed({press}), twin.sensor().contact);
  const double area_mm2 = std::numbers::pi * press.radius_mm * press.radius_mm;
  return load.total_conductance_S() /
         (area_mm2 * twin.sensor().contact.conductance_S_per_mm2(press.force_N / area_mm2));
}

class SimScriptsOnSheets : public testing::TestWithParam<std::string> {};

TEST_P(SimScriptsOnSheets, AMinuteOfEachScriptStaysOnTheSheet) {
  const std::string name = GetParam();
  const std::string path = test::source_path("examples/sensors/" + name + ".json");
  const Sensor sensor = name == "default" ? default_sensor() : load_sheet_sensor(path);
  try {
    require_emit_protocol(sensor, path);
  } catch (const InvalidInput& e) {
    GTEST_SKIP() << "not a sheet `emit live` reads: " << e.what();
  }
  Twin twin(sensor);  // its mesh is the scripts' (as SimSource's), its placing the frames'
  const BorderDistance room_mm(sensor);
  SourceOptions options;
  options.frames_per_s = frames_per_s;
  for (const std::string spec : {"sim", "sim:random", "sim:fixed"}) {
    SCOPED_TRACE(name + ", " + spec);
    const ScriptedPresses script(sensor, twin.mesh(), parse_sim_script(spec), options);
    // Less the sampling's 0.05 mm against the script's own (0.25 mm: 0.125 mm): both far below the margin.
    const double least_room_mm = script.script().radius_mm + ScriptedPresses::margin_mm - 0.2;
    std::uint64_t pressed = 0, failures = 0;
    Press riskiest, first;
    double riskiest_room_mm = std::numeric_limits<double>::infinity();
    for (std::uint64_t sequence = 0; sequence < minute_frames + options.untouched_frames && failures < 5; ++sequence) {
      for (const Press& press : script.presses_of(sequence)) {
        if (pressed++ == 0) first = press;
        try {
          twin.placed({press});
        } catch (const InvalidInput& e) {
          ADD_FAILURE() << "frame " << sequence << ": " << e.what();
          ++failures;
        }
        const double room = room_mm(press);
        if (room < riskiest_room_mm) riskiest_room_mm = room, riskiest = press;
        if (room < least_room_mm) {
          ADD_FAILURE() << "frame " << sequence << ": the press at (" << press.x_mm << ", " << press.y_mm << ", "
                        << press.z_mm << ") mm is " << room << " mm from the border";
          ++failures;
        }
      }
    }
    // The figure-eight presses 6 s of every 7 (8 rounds and 4 s: 2,600 frames of the minute), the
    // random script 0.6 s of every 0.8 (75 × 30 = 2,250), the fixed one throughout (3,000): a
    // script that found no room and pressed nothing would pass the checks above. Within a frame
    // per lift-off (16, 150 edges): the frame on an edge falls either side by rounding.
    const double expected = spec == "sim" ? 2600 : spec == "sim:random" ? 2250 : 3000;
    EXPECT_NEAR(static_cast<double>(pressed), expected, spec == "sim" ? 16 : spec == "sim:random" ? 150 : 0);
    std::printf(
        "%s, %s: %llu presses, the nearest %.2f mm from the border (radius + margin %.1f mm); figure-eight %.2f of its "
        "reach\n",
        name.c_str(), spec.c_str(), static_cast<unsigned long long>(pressed), riskiest_room_mm,
        script.script().radius_mm + ScriptedPresses::margin_mm, script.loop_scale());
    if (spec == "sim") {
      EXPECT_GE(script.loop_scale(), 0.5) << "the figure-eight shrank to a dot";
    }
    // Real frames at the riskiest moments: all of each disc loaded, and readings on the ADC's scale.
    std::vector<Press> moments = {riskiest};
    if (first.x_mm != riskiest.x_mm || first.y_mm != riskiest.y_mm || first.z_mm != riskiest.z_mm)
      moments.push_back(first);
    for (const Press& press : moments) {
      EXPECT_NEAR(loaded_fraction(twin, press), 1.0, 0.02)
          << "press at (" << press.x_mm << ", " << press.y_mm << ", " << press.z_mm << ") mm";
      const Frame frame = twin.exact_frame({press});
      EXPECT_TRUE(frame.allFinite());
      EXPECT_GE(frame.minCoeff(), -1e-12);  // the grounded electrode reads 0 V, to the solve's rounding
      EXPECT_LE(frame.maxCoeff(), sensor.drive_voltage_V * (1 + 1e-9));  // a passive sheet: no more than the drive
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BuiltInSheets, SimScriptsOnSheets, testing::ValuesIn(built_in_sheets()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace emit
