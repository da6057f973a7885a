// Calibration files (io/calibration_json.hpp): each kind written and read back exactly, and every
// malformed file a one-line InvalidInput naming the file and the key.
#include "emit/io/calibration_json.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

// nlohmann::json writes doubles with 17 significant digits, so a round trip is exact.
TEST(CalibrationJson, LinearRoundTripIsExact) {
  const std::string path = test::temp_folder("calibration_linear") + "/c.json";
  write_calibration(path, LinearCalibration{3.25, -0.875, -1.0 / 1.3});
  const Calibration read = load_calibration(path);
  ASSERT_TRUE(std::holds_alternative<LinearCalibration>(read));
  const auto& c = std::get<LinearCalibration>(read);
  EXPECT_EQ(c.a1, 3.25);
  EXPECT_EQ(c.a2, -0.875);
  EXPECT_EQ(c.a3, -1.0 / 1.3);
}

// With emit's force law (model/force_law.hpp): every field back exactly; and a file written
// before the force law, a1, a2, a3 alone, still loads, without one (its contacts' force and area
// are then the image's: frame/reconstructor.hpp).
TEST(CalibrationJson, LinearForceLawRoundTripsAndOldFilesLoadWithout) {
  const std::string dir = test::temp_folder("calibration_force_law");
  LinearCalibration linear{3.25, -0.875, -1.0 / 1.3};
  ImageForceLaw law;
  law.b1_V_mm2 = 41.0 / 3, law.b2 = -0.0123456789, law.b3 = -0.84, law.log_std = 0.031, law.indenter_radius_mm = 5.25;
  linear.force_law = law;
  write_calibration(dir + "/new.json", linear);
  const auto c = std::get<LinearCalibration>(load_calibration(dir + "/new.json"));
  ASSERT_TRUE(c.force_law.has_value());
  EXPECT_EQ(c.force_law->b1_V_mm2, law.b1_V_mm2);
  EXPECT_EQ(c.force_law->b2, law.b2);
  EXPECT_EQ(c.force_law->b3, law.b3);
  EXPECT_EQ(c.force_law->log_std, law.log_std);
  EXPECT_EQ(c.force_law->indenter_radius_mm, law.indenter_radius_mm);
  std::ofstream(dir + "/old.json") << R"({"a1": 3.25, "a2": -0.875, "a3": -0.8})";
  const auto old = std::get<LinearCalibration>(load_calibration(dir + "/old.json"));
  EXPECT_EQ(old.a1, 3.25);
  EXPECT_FALSE(old.force_law.has_value());
  write_calibration(dir + "/old_again.json", old);  // and written back as it was: no force law
  EXPECT_EQ(test::read_text(dir + "/old_again.json").find("force_law"), std::string::npos);
}

TEST(CalibrationJson, FitRoundTripKeepsTheSheetAndTheIndenter) {
  const std::string path = test::temp_folder("calibration_fit") + "/c.json";
  FitCalibration fit;
  fit.contact_law.alpha_ohm_mm2 = 1.7e5;
  fit.contact_law.gamma = -1.15;
  fit.indenter_radius_mm = 2.5;
  SheetCorrection sheet;
  sheet.lower_mm = {-1, 2};
  sheet.upper_mm = {31, 29.5};
  sheet.log_conductance = {0.1, -0.2, 0.03, 1.0 / 3, -0.05};
  fit.sheet_correction = sheet;
  write_calibration(path, fit);
  const Calibration read = load_calibration(path);
  ASSERT_TRUE(std::holds_alternative<FitCalibration>(read));
  const auto& c = std::get<FitCalibration>(read);
  EXPECT_EQ(c.contact_law.alpha_ohm_mm2, 1.7e5);
  EXPECT_EQ(c.contact_law.gamma, -1.15);
  EXPECT_EQ(c.indenter_radius_mm, 2.5);
  ASSERT_TRUE(c.sheet_correction.has_value());
  EXPECT_EQ(c.sheet_correction->lower_mm, sheet.lower_mm);
  EXPECT_EQ(c.sheet_correction->upper_mm, sheet.upper_mm);
  EXPECT_EQ(c.sheet_correction->log_conductance, sheet.log_conductance);
}

// Without an indenter or a sheet, neither is written, and they read back as none.
TEST(CalibrationJson, FitWithoutExtrasReadsBackWithout) {
  const std::string path = test::temp_folder("calibration_fit_plain") + "/c.json";
  FitCalibration law;
  law.contact_law = {2e5, -1.2, 0.002};
  write_calibration(path, law);
  const std::string text = test::read_text(path);
  EXPECT_EQ(text.find("indenter_radius_mm"), std::string::npos) << text;
  EXPECT_EQ(text.find("sheet_correction"), std::string::npos) << text;
  const auto c = std::get<FitCalibration>(load_calibration(path));
  EXPECT_EQ(c.contact_law.alpha_ohm_mm2, 2e5);
  EXPECT_FALSE(c.sheet_correction.has_value());
  EXPECT_EQ(c.indenter_radius_mm, 0.0);
}

TEST(CalibrationJson, MissingFileIsAnIoErrorNamingIt) {
  const std::string path = test::temp_folder("calibration_missing") + "/none.json";
  try {
    load_calibration(path);
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot open calibration file (No such file or directory)");
  }
}

struct BadFile {
  const char* what;
  const char* text;
  const char* message;  ///< after "<path>: "
};

void PrintTo(const BadFile& bad, std::ostream* os) { *os << bad.what; }

class CalibrationJsonBad : public ::testing::TestWithParam<BadFile> {};

TEST_P(CalibrationJsonBad, OneLineNamingTheKey) {
  const std::string path = test::temp_folder("calibration_bad") + "/c.json";
  std::ofstream(path) << GetParam().text;
  try {
    load_calibration(path);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message, path + ": " + GetParam().message);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Errors, CalibrationJsonBad,
    ::testing::Values(
        BadFile{"array", "[1, 2]", "must be a JSON object {\"a1\", \"a2\", \"a3\"} or {\"alpha_ohm_mm2\", \"gamma\"}"},
        BadFile{"missing a3", R"({"a1": 3.3, "a2": -1})", "a3: missing"},
        BadFile{"unknown linear key", R"({"a1": 3.3, "a2": -1, "a3": -0.8, "a4": 1})", "a4: unknown key"},
        BadFile{"text value", R"({"a1": "three", "a2": -1, "a3": -0.8})", "a1: must be a finite number"},
        BadFile{"missing gamma", R"({"alpha_ohm_mm2": 2e5})", "gamma: missing"},
        BadFile{"force law not an object", R"({"a1": 3.3, "a2": -1, "a3": -0.8, "force_law": 2})",
                "force_law: must be an object {\"b1_V_mm2\", \"b2\", \"b3\", \"log_std\", \"indenter_radius_mm\"}"},
        BadFile{
            "force law missing b3",
            R"({"a1": 3.3, "a2": -1, "a3": -0.8, "force_law": {"b1_V_mm2": 1, "b2": 0, "log_std": 0, "indenter_radius_mm": 5}})",
            "force_law: b3: missing"},
        BadFile{
            "force law unknown key",
            R"({"a1": 3.3, "a2": -1, "a3": -0.8, "force_law": {"b1_V_mm2": 1, "b2": 0, "b3": -1, "b4": 0, "log_std": 0, "indenter_radius_mm": 5}})",
            "force_law: b4: unknown key"},
        BadFile{
            "force law text",
            R"({"a1": 3.3, "a2": -1, "a3": -0.8, "force_law": {"b1_V_mm2": "x", "b2": 0, "b3": -1, "log_std": 0, "indenter_radius_mm": 5}})",
            "force_law: b1_V_mm2: must be a finite number"},
        BadFile{
            "force law positive b3",
            R"({"a1": 3.3, "a2": -1, "a3": -0.8, "force_law": {"b1_V_mm2": 1, "b2": 0, "b3": 1, "log_std": 0, "indenter_radius_mm": 5}})",
            "force_law: b3 must be negative (the force grows with the image)"},
        BadFile{
            "force law no indenter",
            R"({"a1": 3.3, "a2": -1, "a3": -0.8, "force_law": {"b1_V_mm2": 1, "b2": 0, "b3": -1, "log_std": 0, "indenter_radius_mm": 0}})",
            "force_law: indenter_radius_mm must be positive"},
        BadFile{"force law in a fit", R"({"alpha_ohm_mm2": 2e5, "gamma": -1.2, "force_law": {}})",
                "force_law: unknown key in a contact-fitting calibration"},
        BadFile{"linear key in a fit", R"({"alpha_ohm_mm2": 2e5, "gamma": -1.2, "a1": 3})",
                "a1: unknown key in a contact-fitting calibration"},
        BadFile{"positive gamma", R"({"alpha_ohm_mm2": 2e5, "gamma": 1.2})",
                "alpha_ohm_mm2 must be positive and gamma negative"},
        BadFile{"negative indenter", R"({"alpha_ohm_mm2": 2e5, "gamma": -1.2, "indenter_radius_mm": -1})",
                "indenter_radius_mm must be positive"},
        BadFile{"sheet not an object", R"({"alpha_ohm_mm2": 2e5, "gamma": -1.2, "sheet_correction": 1})",
                "sheet_correction: must be an object {\"box_mm\", \"log_conductance\"}"},
        BadFile{"sheet unknown key",
                R"({"alpha_ohm_mm2": 2e5, "gamma": -1.2, "sheet_correction": {"box_mm": [0, 0, 1, 1], "theta": 1}})",
                "sheet_correction: theta: unknown key"},
        BadFile{"sheet without box",
                R"({"alpha_ohm_mm2": 2e5, "gamma": -1.2, "sheet_correction": {"log_conductance": []}})",
                "sheet_correction: box_mm: missing"},
        BadFile{
            "sheet box too short",
            R"({"alpha_ohm_mm2": 2e5, "gamma": -1.2, "sheet_correction": {"box_mm": [0, 0, 1], "log_conductance": [0, 0, 0, 0, 0]}})",
            "sheet_correction.box_mm: must be an array of 4 numbers"},
        BadFile{
            "sheet theta text",
            R"({"alpha_ohm_mm2": 2e5, "gamma": -1.2, "sheet_correction": {"box_mm": [0, 0, 1, 1], "log_conductance": [0, 0, "x", 0, 0]}})",
            "sheet_correction.log_conductance: must hold finite numbers"},
        BadFile{
            "sheet box upside down",
            R"({"alpha_ohm_mm2": 2e5, "gamma": -1.2, "sheet_correction": {"box_mm": [0, 5, 1, 1], "log_conductance": [0, 0, 0, 0, 0]}})",
            "sheet_correction.box_mm: must be [x0, y0, x1, y1] with x1 > x0, y1 > y0"}),
    [](const auto& info) {
      std::string name = info.param.what;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

// Not JSON at all: the message names the file and says so (nlohmann's own words follow).
TEST(CalibrationJson, NotJsonNamesTheFile) {
  const std::string path = test::temp_folder("calibration_not_json") + "/c.json";
  std::ofstream(path) << "a1 = 3";
  try {
    load_calibration(path);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": not valid JSON (", 0), 0u) << e.what();
  }
}

// Found by tests/fuzz/calibration_json_fuzz.cpp: a number beyond a double's range made nlohmann
// throw out_of_range, which escaped load_calibration as a non-emit exception.
TEST(CalibrationJson, NumberBeyondADoubleNamesTheFile) {
  const std::string path = test::temp_folder("calibration_big_number") + "/c.json";
  std::ofstream(path) << R"({"a1": 1e400, "a2": -1, "a3": -0.8})";
  try {
    load_calibration(path);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": a number out of range (", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace emit
