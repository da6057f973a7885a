// Sensor descriptions: the default layout rule, the examples, and every validation error.
#include "emit/sensor/sensor_json.hpp"

#include <cmath>
#include <fstream>
#include <numbers>
#include <regex>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

using nlohmann::json;

// README, "Sensor description": 4 per side centred at 7.5, 22.5, 37.5, 52.5 mm, counter-clockwise from the bottom
// side's leftmost (bottom L→R, right B→T, top R→L, left T→B).
TEST(Sensor, DefaultLayoutFollowsThePaper) {
  const Sensor s = default_sensor();
  ASSERT_EQ(s.electrode_count(), 16);
  const double c[4] = {7.5, 22.5, 37.5, 52.5};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR((s.electrodes[i].center_mm - Vector2(c[i], 0)).norm(), 0, 1e-12);
    EXPECT_NEAR((s.electrodes[4 + i].center_mm - Vector2(60, c[i])).norm(), 0, 1e-12);
    EXPECT_NEAR((s.electrodes[8 + i].center_mm - Vector2(c[3 - i], 60)).norm(), 0, 1e-12);
    EXPECT_NEAR((s.electrodes[12 + i].center_mm - Vector2(0, c[3 - i])).norm(), 0, 1e-12);
  }
  for (const auto& e : s.electrodes) EXPECT_EQ(e.width_mm, 3.0);
}

TEST(Sensor, CircleLayoutStartsAtAngleZeroCounterClockwise) {
  const Sensor s = load_sensor(test::source_path("examples/sensors/circle40.json"));
  EXPECT_NEAR((s.electrodes[0].center_mm - Vector2(80, 40)).norm(), 0, 1e-12);
  EXPECT_NEAR((s.electrodes[4].center_mm - Vector2(40, 80)).norm(), 0, 1e-12);  // a quarter turn on
}

// The conformance files' explicit lists land on the same electrodes as our default rule.
TEST(Sensor, ExplicitListsMatchTheDefaultRule) {
  const Sensor square = load_sensor(test::source_path("tests/data/conformance/square60_sensor.json"));
  const Sensor circle = load_sensor(test::source_path("tests/data/conformance/circle40_sensor.json"));
  const Sensor square_default = default_sensor();
  const Sensor circle_default = load_sensor(test::source_path("examples/sensors/circle40.json"));
  for (int e = 0; e < 16; ++e) {
    EXPECT_NEAR(square.electrodes[e].center_s_mm, square_default.electrodes[e].center_s_mm, 1e-9);
    EXPECT_NEAR(circle.electrodes[e].center_s_mm, circle_default.electrodes[e].center_s_mm, 1e-9);
  }
}

TEST(Sensor, AllExamplesLoad) {
  for (const char* name :
       {"default60", "square30", "circle40", "square120_32", "hexagon", "dome25", "sleeve", "cylinder_patch"}) {
    const Sensor s = load_sensor(test::source_path(std::string("examples/sensors/") + name + ".json"));
    EXPECT_GE(s.electrode_count(), 12) << name;
    EXPECT_TRUE(s.border.has_value()) << name;
  }
  EXPECT_EQ(load_sensor(test::source_path("examples/sensors/square120_32.json")).electrode_count(), 32);
}

TEST(Sensor, ContactLawFollowsEquation2) {
  ContactLaw law;  // r_c = 2e5 · P^-1.2
  EXPECT_NEAR(law.conductance_S_per_mm2(0.1), 1.0 / (2e5 * std::pow(0.1, -1.2)), 1e-20);
  EXPECT_EQ(law.conductance_S_per_mm2(0.001), 0.0);  // below the separator's minimum
  EXPECT_LT(law.conductance_S_per_mm2(0.1), law.conductance_S_per_mm2(0.2));
}

json base_sensor() {
  return json::parse(R"({"shape": {"type": "rectangle", "width_mm": 60, "height_mm": 60},
                         "electrodes": {"count": 16, "width_mm": 3}})");
}

struct BadCase {
  const char* what;
  std::function<void(json&)> edit;
  const char* message_contains;
};

void PrintTo(const BadCase& bad, std::ostream* os) { *os << bad.what; }

class SensorValidation : public ::testing::TestWithParam<BadCase> {};

TEST_P(SensorValidation, NamesTheKeyAndSaysWhy) {
  json j = base_sensor();
  GetParam().edit(j);
  try {
    parse_sensor(j, "s.json");
    FAIL() << GetParam().what << ": expected InvalidInput";
  } catch (const InvalidInput& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("s.json: ", 0), 0u) << message;
    EXPECT_NE(message.find(GetParam().message_contains), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

json explicit_electrodes(const std::vector<std::array<double, 3>>& list) {
  json electrodes = json::array();
  for (const auto& [x, y, w] : list) electrodes.push_back({{"x_mm", x}, {"y_mm", y}, {"width_mm", w}});
  return electrodes;
}

/// A sleeve (README "Sensor description"): R = 15 mm, L = 60 mm.
json sleeve_shape() { return {{"type", "cylinder"}, {"radius_mm", 15}, {"length_mm", 60}, {"angle_deg", 360}}; }

/// Electrodes of 3 mm on a cylinder, each {x_mm, angle_deg}.
json sleeve_electrodes(const std::vector<std::array<double, 2>>& list) {
  json electrodes = json::array();
  for (const auto& [x, angle] : list) electrodes.push_back({{"x_mm", x}, {"angle_deg", angle}, {"width_mm", 3}});
  return electrodes;
}

INSTANTIATE_TEST_SUITE_P(
    Errors, SensorValidation,
    ::testing::Values(
        BadCase{"unknown top-level key", [](json& j) { j["colour"] = "red"; }, "colour: unknown key"},
        BadCase{"unknown nested key",
                [](json& j) {
                  j["adc"] = {{"bitz", 12}};
                },
                "adc.bitz: unknown key"},
        BadCase{"missing shape", [](json& j) { j.erase("shape"); }, "shape: missing"},
        BadCase{"unknown shape",
                [](json& j) {
                  j["shape"] = {{"type", "star"}};
                },
                "shape.type: must be"},
        BadCase{"negative resistance", [](json& j) { j["probing_sheet_resistance_ohm_per_sq"] = -5; },
                "probing_sheet_resistance_ohm_per_sq: must be positive"},
        BadCase{"negative width", [](json& j) { j["shape"]["width_mm"] = -60; }, "shape.width_mm: must be positive"},
        BadCase{"cap wider than its sphere",
                [](json& j) {
                  j["shape"] = {{"type", "spherical_cap"}, {"sphere_radius_mm", 15}, {"base_radius_mm", 20}};
                },
                "shape.base_radius_mm: must not exceed sphere_radius_mm (15), got 20"},
        BadCase{"an electrode by angle on a rectangle",
                [](json& j) {
                  j["electrodes"] = json::array({{{"angle_deg", 0}, {"width_mm", 3}}});
                },
                "electrodes[0].angle_deg: is for a circle's or a spherical cap's rim; give x_mm, y_mm"},
        BadCase{"an electrode by angle and by place",
                [](json& j) {
                  j["shape"] = {{"type", "circle"}, {"radius_mm", 20}};
                  j["electrodes"] = json::array({{{"angle_deg", 0}, {"x_mm", 40}, {"y_mm", 20}, {"width_mm", 3}}});
                },
                "electrodes[0]: give angle_deg or x_mm, y_mm, not both"},
        BadCase{"x_mm with angle_deg off a cylinder",
                [](json& j) {
                  j["electrodes"] = json::array({{{"x_mm", 10}, {"angle_deg", 0}, {"width_mm", 3}}});
                },
                "electrodes[0].angle_deg: with x_mm is for a cylinder; give x_mm, y_mm"},
        BadCase{"cylinder angle beyond a turn",
                [](json& j) {
                  j["shape"] = {{"type", "cylinder"}, {"radius_mm", 15}, {"length_mm", 60}, {"angle_deg", 400}};
                },
                "shape.angle_deg: must be in (0, 360] (360 is a sleeve), got 400"},
        BadCase{"cylinder angle zero",
                [](json& j) {
                  j["shape"] = {{"type", "cylinder"}, {"radius_mm", 15}, {"length_mm", 60}, {"angle_deg", 0}};
                },
                "shape.angle_deg: must be in (0, 360] (360 is a sleeve), got 0"},
        BadCase{"cylinder without a length",
                [](json& j) {
                  j["shape"] = {{"type", "cylinder"}, {"radius_mm", 15}, {"angle_deg", 90}};
                },
                "shape.length_mm: missing"},
        BadCase{"sleeve with an odd count",
                [](json& j) {
                  j["shape"] = sleeve_shape();
                  j["electrodes"]["count"] = 15;
                },
                "electrodes.count: the default layout puts count/2 electrodes on each rim of a sleeve, so count must "
                "be even (got 15)"},
        BadCase{"y_mm on a cylinder",
                [](json& j) {
                  j["shape"] = sleeve_shape();
                  j["electrodes"] = json::array({{{"x_mm", 30}, {"y_mm", 0}, {"width_mm", 3}}});
                },
                "electrodes[0].y_mm: a cylinder's electrodes are placed by x_mm (along its axis) and angle_deg"},
        BadCase{"sleeve angle out of range",
                [](json& j) {
                  j["shape"] = sleeve_shape();
                  j["electrodes"] = sleeve_electrodes({{30, 0}, {30, 90}, {-30, -180}});
                },
                "electrodes[2].angle_deg: must be in (-180, 180] on a sleeve, got -180"},
        BadCase{"patch angle beyond the patch",
                [](json& j) {
                  j["shape"] = {{"type", "cylinder"}, {"radius_mm", 20}, {"length_mm", 60}, {"angle_deg", 120}};
                  j["electrodes"] = sleeve_electrodes({{30, 0}, {30, 70}, {-30, 0}});
                },
                "electrodes[1].angle_deg: must be within +-60 (the patch's angle is 120), got 70"},
        BadCase{"cylinder electrode beyond the rims",
                [](json& j) {
                  j["shape"] = sleeve_shape();
                  j["electrodes"] = sleeve_electrodes({{30, 0}, {31, 90}, {-30, 0}});
                },
                "electrodes[1].x_mm: must be within +-30 (half the length), got 31"},
        BadCase{"sleeve electrode off the rims",
                [](json& j) {
                  j["shape"] = sleeve_shape();
                  j["electrodes"] = sleeve_electrodes({{30, 0}, {30, 90}, {10, 90}});
                },
                "electrodes[2]: (x_mm 10, angle_deg 90) is not on the border: give x_mm = +-30 (a rim)"},
        BadCase{"sleeve electrode on the seam",
                [](json& j) {
                  j["shape"] = sleeve_shape();
                  j["electrodes"] = sleeve_electrodes({{30, 0}, {30, 90}, {10, 180}});
                },
                "electrodes[2]: lies on the sleeve's seam (angle 180 deg between its rims), not on a rim"},
        BadCase{"sleeve electrode across a rim's seam point",
                [](json& j) {
                  j["shape"] = sleeve_shape();
                  j["electrodes"] = sleeve_electrodes({{30, 0}, {30, 90}, {-30, 175}});
                },
                "electrodes[2]: crosses its rim's seam point (angle 180 deg): 3 mm wide, it must lie wholly within "
                "(-180, 180) deg"},
        BadCase{"text for a number", [](json& j) { j["drive_voltage_V"] = "3.3"; },
                "drive_voltage_V: must be a number"},
        BadCase{"fewer than 3 electrodes", [](json& j) { j["electrodes"]["count"] = 2; }, "at least 3 electrodes"},
        BadCase{"fewer than 3 explicit",
                [](json& j) {
                  j["electrodes"] = explicit_electrodes({{10, 0, 3}, {60, 30, 3}});
                },
                "at least 3 electrodes"},
        BadCase{"count not a multiple of 4", [](json& j) { j["electrodes"]["count"] = 10; }, "multiple of 4"},
        BadCase{"electrode off the border",
                [](json& j) {
                  j["electrodes"] = explicit_electrodes({{10, 0, 3}, {60, 30, 3}, {30, 31, 3}});
                },
                "electrodes[2]: centre"},
        BadCase{"overlapping electrodes",
                [](json& j) {
                  j["electrodes"] = explicit_electrodes({{10, 0, 3}, {12, 0, 3}, {60, 30, 3}});
                },
                "overlap"},
        BadCase{"electrodes too wide to fit", [](json& j) { j["electrodes"]["width_mm"] = 16; }, "overlap"},
        BadCase{"positive gamma",
                [](json& j) {
                  j["contact_law"] = {{"gamma", 1.2}};
                },
                "contact_law.gamma: must be negative"},
        BadCase{"degenerate polygon",
                [](json& j) {
                  j["shape"] = {{"type", "polygon"}, {"points_mm", {{0, 0}, {1, 1}, {2, 2}}}};
                },
                "zero area"},
        // Gmsh used to throw a std::string from inside an OpenMP region (rc 134) on this one.
        BadCase{"self-intersecting polygon",
                [](json& j) {
                  j["shape"] = {{"type", "polygon"}, {"points_mm", {{0, 0}, {60, 0}, {60, 60}, {30, -20}, {0, 60}}}};
                  j["electrodes"] = {{"count", 8}, {"width_mm", 3}};
                },
                "edges 0-1 and 2-3 meet"},
        BadCase{"polygon touching itself",
                [](json& j) {
                  j["shape"] = {{"type", "polygon"}, {"points_mm", {{0, 0}, {60, 0}, {30, 0}, {30, 30}}}};
                  j["electrodes"] = {{"count", 8}, {"width_mm", 1}};
                },
                "must not cross or touch itself"},
        // Checking 200,000 points for crossings took over a minute (every pair of edges).
        BadCase{"polygon of 200,000 points",
                [](json& j) {
                  json points = json::array();
                  for (int k = 0; k < 200000; ++k)
                    points.push_back({30 + 25 * std::cos(k * 2 * std::numbers::pi / 200000),
                                      30 + 25 * std::sin(k * 2 * std::numbers::pi / 200000)});
                  j["shape"] = {{"type", "polygon"}, {"points_mm", points}};
                },
                "shape.points_mm: 200000 points, more than the 20000 a polygon may have: simplify the outline"},
        // A file of another kind was taken for a .msh: "a .msh sensor takes its electrodes from the
        // file's curves".
        BadCase{"an .obj sheet",
                [](json& j) {
                  j["shape"] = {{"type", "mesh"}, {"file", "sheet.obj"}};
                  j["electrodes"] = {{{"at_mm", {0, 0, 0}}}, {{"at_mm", {1, 0, 0}}}};
                },
                "shape.file: \"sheet.obj\" is a \".obj\" file: a sheet's file is a Gmsh mesh (.msh), an STL surface "
                "(.stl) or CAD (.step, .stp, .iges, .igs)"},
        BadCase{"a .brep sheet",
                [](json& j) {
                  j["shape"] = {{"type", "mesh"}, {"file", "cad/sheet.brep"}};
                },
                "shape.file: \"cad/sheet.brep\" is a \".brep\" file: a sheet's file is a Gmsh mesh (.msh)"},
        BadCase{"a sheet file without an extension",
                [](json& j) {
                  j["shape"] = {{"type", "mesh"}, {"file", "sheet"}};
                  j["electrodes"] = {{{"at_mm", {0, 0, 0}}}, {{"at_mm", {1, 0, 0}}}};
                },
                "shape.file: \"sheet\" has no extension: a sheet's file is a Gmsh mesh (.msh), an STL surface"},
        // The width's rounding used to be reported as electrodes "touching".
        BadCase{"electrode wider than the border", [](json& j) { j["electrodes"]["width_mm"] = 1e300; },
                "longer than the whole border"},
        BadCase{"adc bits out of range",
                [](json& j) {
                  j["adc"] = {{"bits", 40}};
                },
                "adc.bits: must be between"},
        BadCase{"mesh coarser than the sheet",
                [](json& j) {
                  j["mesh"] = {{"element_size_mm", 40}};
                },
                "mesh.element_size_mm"}),
    [](const auto& info) {
      std::string name = info.param.what;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

// sensor_json.hpp lists the keys a description may have: every key the parser reads (through its
// readers' number, value, has, ... calls in sensor_json.cpp and excitation.cpp) is in that list.
TEST(Sensor, TheHeadersListOfKeysHasEveryKeyTheParserReads) {
  std::string header = test::read_text(test::source_path("include/emit/sensor/sensor_json.hpp"));
  header = header.substr(0, header.find("#include"));
  const std::regex key_read(R"re(\b(?:has|integer_or|number|number_or|point|string|value)\("([A-Za-z_]+)")re");
  int keys = 0;
  for (const char* source : {"src/sensor/sensor_json.cpp", "src/sensor/excitation.cpp"}) {
    const std::string text = test::read_text(test::source_path(source));
    for (auto it = std::sregex_iterator(text.begin(), text.end(), key_read); it != std::sregex_iterator();
         ++it, ++keys) {
      const std::string key = (*it)[1];
      EXPECT_TRUE(std::regex_search(header, std::regex("\\b" + key + "\\b"))) << source << " reads \"" << key << "\"";
    }
  }
  EXPECT_GT(keys, 30) << "the parser's readers were not found: has the regex gone stale?";
}

TEST(Sensor, MissingFileIsAnIoError) { EXPECT_THROW(load_sensor("/nonexistent/sensor.json"), IoError); }

TEST(Sensor, MalformedJsonNamesTheFile) {
  const std::string path = test::temp_folder("bad_json") + "/bad.json";
  std::ofstream(path) << "{\"shape\": ";
  try {
    load_sensor(path);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": not valid JSON", 0), 0u) << e.what();
  }
}

// Found by tests/fuzz/sensor_json_fuzz.cpp: nlohmann throws out_of_range, not parse_error, for a
// number beyond a double's range; it escaped load_sensor as a non-emit exception.
TEST(Sensor, NumberBeyondADoubleNamesTheFile) {
  const std::string path = test::temp_folder("big_number_json") + "/big.json";
  std::ofstream(path) << R"({"shape": {"type": "rectangle", "width_mm": 1e999, "height_mm": 60}})";
  try {
    load_sensor(path);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": a number out of range (", 0), 0u) << e.what();
  }
}

// Found by tests/fuzz/sensor_json_fuzz.cpp: the message for a value of the wrong type dumped it,
// recursing once per level, and a value nested deep enough overflowed the stack.
TEST(Sensor, DeeplyNestedValueIsInvalidInput) {
  const std::string path = test::temp_folder("deep_json") + "/deep.json";
  const int depth = 200000;
  std::ofstream(path) << R"({"name": )" << std::string(depth, '[') << std::string(depth, ']') << "}";
  try {
    load_sensor(path);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), path + ": name: must be a string, got a nested JSON array");
  }
}

TEST(Sensor, RoundTripsThroughJson) {
  const Sensor s = load_sensor(test::source_path("examples/sensors/hexagon.json"));
  const Sensor back = parse_sensor(sensor_to_json(s));
  ASSERT_EQ(back.electrode_count(), s.electrode_count());
  for (int e = 0; e < s.electrode_count(); ++e)
    EXPECT_NEAR((back.electrodes[e].center_mm - s.electrodes[e].center_mm).norm(), 0, 1e-9);
}

// A spherical cap (README "Sensor description"): its rim the circle of radius a about the origin,
// electrodes from angle 0 counter-clockwise as on a circle, 3 mm of arc each; back through JSON.
TEST(Sensor, SphericalCapHasTheRimsElectrodesAndRoundTrips) {
  const Sensor s = load_sensor(test::source_path("tests/data/conformance/dome25_sensor.json"));
  EXPECT_EQ(s.shape.kind, ShapeKind::spherical_cap);
  EXPECT_EQ(s.shape.sphere_radius_mm, 25.0);
  EXPECT_EQ(s.shape.radius_mm, 20.0);
  ASSERT_EQ(s.electrode_count(), 16);
  EXPECT_NEAR((s.electrodes[0].center_mm - Vector2(20, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((s.electrodes[4].center_mm - Vector2(0, 20)).norm(), 0, 1e-9);  // a quarter turn on
  EXPECT_NEAR(s.border->length_mm(), 2 * std::numbers::pi * 20, 1e-9);
  const Sensor back = parse_sensor(sensor_to_json(s));
  EXPECT_EQ(back.shape.kind, ShapeKind::spherical_cap);
  EXPECT_EQ(back.shape.sphere_radius_mm, 25.0);
  EXPECT_EQ(back.shape.radius_mm, 20.0);
  ASSERT_EQ(back.electrode_count(), 16);
  for (int e = 0; e < 16; ++e) EXPECT_NEAR((back.electrodes[e].center_mm - s.electrodes[e].center_mm).norm(), 0, 1e-9);
}

// Electrodes on a rim by angle (README "Sensor description"): 16 at 22.5° steps from 0 are the
// {count: 16} layout, to rounding; an uneven list puts each where its angle says.
TEST(Sensor, RimElectrodesByAngle) {
  const Sensor even = load_sensor(test::source_path("tests/data/conformance/dome25_sensor.json"));
  json j = sensor_to_json(even);
  j["electrodes"] = json::array();
  for (int e = 0; e < 16; ++e) j["electrodes"].push_back({{"angle_deg", 22.5 * e}, {"width_mm", 3}});
  const Sensor by_angle = parse_sensor(j);
  ASSERT_EQ(by_angle.electrode_count(), 16);
  for (int e = 0; e < 16; ++e) {
    EXPECT_NEAR((by_angle.electrodes[e].center_mm - even.electrodes[e].center_mm).norm(), 0, 1e-9);
    EXPECT_NEAR(by_angle.electrodes[e].width_mm, 3, 1e-12);
  }
  j["electrodes"] = json::array({{{"angle_deg", 90}, {"width_mm", 4}},
                                 {{"angle_deg", 200}, {"width_mm", 3}},
                                 {{"angle_deg", -30}, {"width_mm", 3}}});
  const Sensor uneven = parse_sensor(j);
  EXPECT_NEAR((uneven.electrodes[0].center_mm - Vector2(0, 20)).norm(), 0, 1e-9);
  EXPECT_NEAR((uneven.electrodes[2].center_mm - 20 * Vector2(std::cos(-std::numbers::pi / 6), -0.5)).norm(), 0, 1e-9);
  EXPECT_NEAR(uneven.electrodes[0].width_mm, 4, 1e-12);
}

// A sleeve's default layout (README "Sensor description"): 8 electrodes on each rim, centred in
// equal divisions of the rim from its seam (θ = ±180°), so at 22.5° + k·45°; each rim numbered from
// the first past θ = 0 along the chart's border (θ rising on x = +L/2, falling on x = −L/2). A
// chart point (u, v) is x = u − L/2, θ = v/R − π. Back through JSON as {x_mm, angle_deg}.
TEST(Sensor, SleeveHasEightElectrodesOnEachRimAndRoundTrips) {
  const Sensor s = load_sensor(test::source_path("examples/sensors/sleeve.json"));
  ASSERT_EQ(s.shape.kind, ShapeKind::cylinder);
  ASSERT_EQ(s.electrode_count(), 16);
  const double R = 15, pi = std::numbers::pi;
  EXPECT_NEAR(s.border->length_mm(), 2 * 60 + 2 * 2 * pi * R, 1e-9);
  for (int k = 0; k < 8; ++k) {
    const double rising = (22.5 + 45 * k) * pi / 180, falling = -(22.5 + 45 * k) * pi / 180;
    const auto wrapped = [&](double theta) { return std::remainder(theta, 2 * pi); };
    EXPECT_NEAR((s.electrodes[k].center_mm - Vector2(60, R * (wrapped(rising) + pi))).norm(), 0, 1e-9) << k;
    EXPECT_NEAR((s.electrodes[8 + k].center_mm - Vector2(0, R * (wrapped(falling) + pi))).norm(), 0, 1e-9) << k;
    EXPECT_EQ(s.electrodes[k].width_mm, 3.0);
  }
  const json j = sensor_to_json(s);
  EXPECT_EQ(j["shape"]["type"], "cylinder");
  EXPECT_NEAR(j["electrodes"][0]["x_mm"].get<double>(), 30, 1e-12);
  EXPECT_NEAR(j["electrodes"][0]["angle_deg"].get<double>(), 22.5, 1e-9);
  EXPECT_NEAR(j["electrodes"][8]["x_mm"].get<double>(), -30, 1e-12);
  EXPECT_NEAR(j["electrodes"][8]["angle_deg"].get<double>(), -22.5, 1e-9);
  const Sensor back = parse_sensor(j);
  EXPECT_EQ(back.shape.kind, ShapeKind::cylinder);
  EXPECT_EQ(back.shape.radius_mm, 15.0);
  EXPECT_EQ(back.shape.length_mm, 60.0);
  EXPECT_EQ(back.shape.angle_deg, 360.0);
  ASSERT_EQ(back.electrode_count(), 16);
  for (int e = 0; e < 16; ++e) {
    EXPECT_NEAR((back.electrodes[e].center_mm - s.electrodes[e].center_mm).norm(), 0, 1e-9);
    EXPECT_NEAR(back.electrodes[e].center_s_mm, s.electrodes[e].center_s_mm, 1e-9);
  }
}

// An odd count per rim puts one electrode at θ = 0 (+z) on each rim.
TEST(Sensor, SleeveWithOddElectrodesPerRimHasOneOnTop) {
  json j = sensor_to_json(load_sensor(test::source_path("examples/sensors/sleeve.json")));
  j["electrodes"] = {{"count", 6}, {"width_mm", 3}};
  const Sensor s = parse_sensor(j);
  ASSERT_EQ(s.electrode_count(), 6);
  EXPECT_NEAR((s.electrodes[0].center_mm - Vector2(60, 15 * std::numbers::pi)).norm(), 0, 1e-9);
  EXPECT_NEAR((s.electrodes[3].center_mm - Vector2(0, 15 * std::numbers::pi)).norm(), 0, 1e-9);
}

// A patch's chart is the rectangle L × Rα: its default layout is that rectangle's, 4 per side;
// explicit electrodes on a rim (x = ±L/2) or a straight side (θ = ±α/2) land where they say.
TEST(Sensor, CylinderPatchIsItsChartsRectangleAndRoundTrips) {
  const Sensor s = load_sensor(test::source_path("examples/sensors/cylinder_patch.json"));
  const double arc = 20 * 2 * std::numbers::pi / 3;  // R α
  nlohmann::json j = base_sensor();
  j["shape"] = {{"type", "rectangle"}, {"width_mm", 60}, {"height_mm", arc}};
  const Sensor rectangle = parse_sensor(j);
  ASSERT_EQ(s.electrode_count(), 16);
  for (int e = 0; e < 16; ++e)
    EXPECT_NEAR((s.electrodes[e].center_mm - rectangle.electrodes[e].center_mm).norm(), 0, 1e-12) << e;
  const Sensor back = parse_sensor(sensor_to_json(s));
  EXPECT_EQ(back.shape.angle_deg, 120.0);
  for (int e = 0; e < 16; ++e)
    EXPECT_NEAR((back.electrodes[e].center_mm - s.electrodes[e].center_mm).norm(), 0, 1e-9) << e;
  j = sensor_to_json(s);
  j["electrodes"] = sleeve_electrodes({{-10, -60}, {30, 15}, {5, 60}, {-30, 0}});
  const Sensor listed = parse_sensor(j);
  EXPECT_NEAR((listed.electrodes[0].center_mm - Vector2(20, 0)).norm(), 0, 1e-9);
  EXPECT_NEAR((listed.electrodes[1].center_mm - Vector2(60, arc * 0.625)).norm(), 0, 1e-9);
  EXPECT_NEAR((listed.electrodes[2].center_mm - Vector2(35, arc)).norm(), 0, 1e-9);
  EXPECT_NEAR((listed.electrodes[3].center_mm - Vector2(0, arc / 2)).norm(), 0, 1e-9);
}

}  // namespace
}  // namespace emit
