// A current-injection skin's "excitation" in the sensor JSON (sensor/sensor_json.hpp): the named
// patterns, explicit lists in the frame's order, the round trip, and every refusal in one line.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

using nlohmann::json;

json ring(const json& excitation, int electrodes = 8) {
  return {{"shape", {{"type", "circle"}, {"radius_mm", 40}, {"center_mm", {0, 0}}}},
          {"electrodes", {{"count", electrodes}, {"width_mm", 2}}},
          {"excitation", excitation}};
}

TEST(ExcitationJson, TheHydrogelSkinsExampleIsItsBoardsTable) {
  const Sensor s = load_sensor(test::source_path("examples/sensors/hydrogel_hardman.json"));
  ASSERT_TRUE(s.excitation);
  ASSERT_EQ(s.electrode_count(), 16);
  // Electrode 0 lowermost, counter-clockwise (the data set's sensor.json, paper Fig. 2).
  EXPECT_NEAR((s.electrodes[0].center_mm - Vector2(0, -85)).norm(), 0, 1e-9);
  EXPECT_NEAR((s.electrodes[4].center_mm - Vector2(85, 0)).norm(), 0, 1e-9);
  const std::vector<EitReading> table = adjacent_readings(drive_pattern("opposite", 16), 16, true);
  ASSERT_EQ(s.excitation->readings.size(), 192u);
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(s.excitation->readings[i].drive, table[i].drive);
    EXPECT_EQ(s.excitation->readings[i].plus, table[i].plus);
    EXPECT_EQ(s.excitation->readings[i].minus, table[i].minus);
  }
  EXPECT_EQ(s.excitation->frequency_Hz, 25000);
  EXPECT_TRUE(s.excitation->contact_impedance_ohm_mm.empty());                                // the shunt model
  EXPECT_FALSE(load_sensor(test::source_path("examples/sensors/circle40.json")).excitation);  // EMIT stays the default
}

TEST(ExcitationJson, ExplicitListsAreReadInTheFramesOrderAndRoundTrip) {
  const Sensor s = parse_sensor(ring({{"current_A", 0.002},
                                      {"drive", {{0, 4}, {2, 6}}},
                                      {"measure", {{1, 0}, {3, 2}, {5, 4}}},
                                      {"skip_driving_electrodes", true},
                                      {"contact_impedance_ohm_mm", {1, 2, 3, 4, 5, 6, 7, 8}}}));
  const Excitation& e = *s.excitation;
  ASSERT_EQ(e.drives.size(), 2u);
  EXPECT_EQ(e.drives[1].source, 2);
  EXPECT_EQ(e.drives[1].sink, 6);
  // Drive 0 (0 → 4) keeps none of (1,0) and (5,4); drive 1 (2 → 6) drops (3,2).
  ASSERT_EQ(e.readings.size(), 3u);
  EXPECT_EQ(e.readings[0].drive, 0);
  EXPECT_EQ(e.readings[0].plus, 3);
  EXPECT_EQ(e.readings[1].drive, 1);
  EXPECT_EQ(e.readings[1].plus, 1);
  EXPECT_EQ(e.readings[2].plus, 5);
  EXPECT_EQ(e.contact_impedance_ohm_mm[7], 8);
  const Sensor back = parse_sensor(sensor_to_json(s));
  ASSERT_TRUE(back.excitation);
  EXPECT_EQ(back.excitation->current_A, 0.002);
  ASSERT_EQ(back.excitation->readings.size(), 3u);
  EXPECT_EQ(back.excitation->readings[2].drive, 1);
  EXPECT_EQ(back.excitation->readings[2].minus, 4);
  EXPECT_EQ(back.excitation->contact_impedance_ohm_mm, e.contact_impedance_ohm_mm);

  const Sensor listed = parse_sensor(ring({{"drive", "adjacent"}, {"readings", {{7, 3, 2}, {0, 5, 1}}}}));
  ASSERT_EQ(listed.excitation->readings.size(), 2u);
  EXPECT_EQ(listed.excitation->readings[0].drive, 7);
  EXPECT_EQ(listed.excitation->readings[1].minus, 1);
  // Without skipping, every drive reads every adjacent pair (pyEIT's default): 8 × 8.
  EXPECT_EQ(parse_sensor(ring({{"drive", "skip-2"}})).excitation->readings.size(), 64u);
}

TEST(ExcitationJson, MistakesAreNamedInOneLine) {
  const auto error = [](const json& excitation) { return test::error_of([&] { parse_sensor(ring(excitation)); }); };
  EXPECT_EQ(error({{"drive", "diagonal"}}),
            "sensor: excitation.drive: drive pattern \"diagonal\": must be adjacent, opposite or skip-<s> (e.g. "
            "skip-4)");
  EXPECT_EQ(error({{"drive", {{0, 8}}}}), "sensor: excitation.drive[0]: must be an electrode number 0 to 7, got 8");
  EXPECT_EQ(error({{"drive", {{3, 3}}}}), "sensor: excitation.drive[0]: names electrode 3 twice");
  EXPECT_EQ(error({{"drive", "opposite"}, {"measure", "diagonal"}}),
            "sensor: excitation.measure: must be \"adjacent\" or a list of [+, -] pairs, got \"diagonal\"");
  EXPECT_EQ(error({{"drive", "opposite"}, {"skip_driving_electrodes", 1}}),
            "sensor: excitation.skip_driving_electrodes: must be true or false, got 1");
  EXPECT_EQ(error({{"drive", "opposite"}, {"readings", {{0, 1, 2}}}, {"measure", "adjacent"}}),
            "sensor: excitation.readings: lists every reading: give it or \"measure\", not both");
  EXPECT_EQ(error({{"drive", "opposite"}, {"readings", {{8, 1, 2}}}}),
            "sensor: excitation.readings[0]: its drive must be 0 to 7, got 8");
  EXPECT_EQ(error({{"drive", "opposite"}, {"readings", {{0, 2, 2}}}}),
            "sensor: excitation.readings[0]: reads electrode 2 against itself");
  EXPECT_EQ(error({{"drive", {{0, 1}}}, {"measure", {{1, 0}}}, {"skip_driving_electrodes", true}}),
            "sensor: excitation.measure: leaves no reading");
  EXPECT_EQ(error({{"drive", "opposite"}, {"contact_impedance_ohm_mm", {1, 2}}}),
            "sensor: excitation.contact_impedance_ohm_mm: 2 values for 8 electrodes");
  EXPECT_EQ(error({{"drive", "opposite"}, {"contact_impedance_ohm_mm", -1}}),
            "sensor: excitation.contact_impedance_ohm_mm: must be a number of ohm mm, not negative, or a list of one "
            "per electrode; got -1");
  EXPECT_EQ(error({{"drive", "opposite"}, {"current", 1}}), "sensor: excitation.current: unknown key");
  EXPECT_EQ(error({{"measure", "adjacent"}}), "sensor: excitation.drive: missing");
}

// A contact impedance the model cannot hold (its system not positive definite at 1e-15 or 1e20
// ohm mm: "is an electrode disconnected?", naming no key) is refused naming the key, the range for
// this sheet and why; 0, the shunt model, and the range's ends are taken.
TEST(ExcitationJson, AContactImpedanceIsWithinWhatTheModelResolves) {
  const auto with = [](const json& z, double sheet_ohm_per_sq = 5000) {
    json j = ring({{"drive", "opposite"}, {"contact_impedance_ohm_mm", z}});
    j["probing_sheet_resistance_ohm_per_sq"] = sheet_ohm_per_sq;
    return j;
  };
  const std::string range =
      "sensor: excitation.contact_impedance_ohm_mm: must be 0 (the shunt model) or from 0.005 to 5e+09 (1e-06 to "
      "1e+06 mm of the sheet's 5000 ohm/sq: less is a perfect contact, give 0; more cuts the electrode off), got ";
  EXPECT_EQ(test::error_of([&] { parse_sensor(with(1e-15)); }), range + "1e-15");
  EXPECT_EQ(test::error_of([&] { parse_sensor(with(1e20)); }), range + "1e+20");
  EXPECT_EQ(test::error_of([&] { parse_sensor(with({1, 2, 3, 4, 5, 6, 7, 1e20})); }), range + "1e+20");
  // The range follows the sheet: 1e-6 to 1e6 mm of it.
  EXPECT_NE(test::error_of([&] { parse_sensor(with(1e-4, 1000)); }).find("from 0.001 to 1e+09"), std::string::npos);
  for (const double z : {0.0, 0.005, 1.0, 5e9})
    EXPECT_EQ(parse_sensor(with(z)).excitation->contact_impedance_ohm_mm[0], z) << z;
}

}  // namespace
}  // namespace emit
