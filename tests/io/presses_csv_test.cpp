// Ground truth as CSV (io/presses_csv.hpp): simultaneous presses share a frame, frames without a
// press stay empty, and a malformed file names its line.
#include "emit/io/presses_csv.hpp"

#include <fstream>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

// Positions with 4 decimals and forces with 6 are written exactly for these values (binary
// fractions), so they read back equal.
TEST(PressesCsv, RoundTripKeepsFramesAndSimultaneousPresses) {
  const std::string path = test::temp_folder("presses_csv") + "/p.csv";
  const PressSequence sequence = {{{10.5, 20.25, 5, 12.5}}, {}, {{1, 2, 3, 4}, {5.75, 6, 2.5, 0.5}}};
  write_presses_csv(path, sequence);
  const std::string text = test::read_text(path);
  EXPECT_EQ(text.substr(0, text.find('\n')), "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2");
  // The pressure column is force / (π r²): 12.5 / (25π) = 0.159155 to 6 decimals.
  EXPECT_NE(text.find("0,10.5000,20.2500,5.0000,12.500000,0.159155\n"), std::string::npos) << text;
  const PressSequence read = read_presses_csv(path);
  ASSERT_EQ(read.size(), 3u);
  ASSERT_EQ(read[0].size(), 1u);
  EXPECT_TRUE(read[1].empty());
  ASSERT_EQ(read[2].size(), 2u);
  EXPECT_EQ(read[2][1].x_mm, 5.75);
  EXPECT_EQ(read[2][1].radius_mm, 2.5);
  EXPECT_EQ(read[2][1].force_N, 0.5);
  EXPECT_EQ(read[0][0].y_mm, 20.25);
  EXPECT_NEAR(read[0][0].pressure_N_per_mm2(), 12.5 / (std::numbers::pi * 25), 1e-15);
}

// Outlines go in an 8th column, vertices to 9 significant digits: they read back as written
// (these values are exact to 9 digits), a disc beside them with an empty one.
TEST(PressesCsv, RoundTripKeepsOutlines) {
  const std::string path = test::temp_folder("presses_csv_outline") + "/p.csv";
  const Press ring = ring_press({30, 30}, 6, 9, 8);
  const Press triangle = polygon_press({20, 25}, {{{0, 0}, {4.5, 0}, {0, 3.25}}}, 5);
  const PressSequence sequence = {{triangle, Press{10, 10, 2, 1}}, {ring}};
  write_presses_csv(path, sequence);
  const std::string text = test::read_text(path);
  EXPECT_EQ(text.substr(0, text.find('\n')), "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2,profile,outline");
  EXPECT_NE(text.find(",flat,0 0;4.5 0;0 3.25\n"), std::string::npos) << text;
  EXPECT_NE(text.find(",flat,\n"), std::string::npos) << text;
  const PressSequence read = read_presses_csv(path);
  ASSERT_EQ(read.size(), 2u);
  ASSERT_EQ(read[0].size(), 2u);
  EXPECT_EQ(read[0][0].outline_mm, triangle.outline_mm);
  EXPECT_TRUE(read[0][1].outline_mm.empty());
  ASSERT_EQ(read[1][0].outline_mm.size(), 2u);  // the ring's two circles
  EXPECT_NEAR(press_area_mm2(read[1][0]), press_area_mm2(ring), 1e-6 * press_area_mm2(ring));
  EXPECT_DOUBLE_EQ(read[0][0].pressure_N_per_mm2(), 5 / 7.3125);
  const std::string bad = test::temp_folder("presses_csv_outline") + "/bad.csv";
  std::ofstream(bad)
      << "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2,profile,outline\n0,1,2,3,4,0.1,flat,0 0;1 x\n";
  EXPECT_EQ(test::error_of([&] { read_presses_csv(bad); }),
            bad + ":2: outline vertex \"1 x\" is not two numbers \"u v\"");
  std::ofstream(bad)
      << "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2,profile,outline\n0,1,2,3,4,0.1,flat,0 0;1 1\n";
  EXPECT_EQ(test::error_of([&] { read_presses_csv(bad); }),
            bad + ":2: outline polygon 0 has 2 vertices, 3 or more needed");
}

std::string error_of(const std::string& path) {
  try {
    read_presses_csv(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(PressesCsv, ErrorsNameTheLine) {
  const std::string dir = test::temp_folder("presses_csv_bad");
  std::ofstream(dir + "/header.csv") << "x,y\n";
  EXPECT_EQ(error_of(dir + "/header.csv"), dir +
                                               "/header.csv:1: expected the header "
                                               "\"frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2\" (or with z_mm "
                                               "after y_mm), got \"x,y\"");
  const std::string expected = ": expected frame,x_mm,y_mm,radius_mm,force_N[,pressure_N_per_mm2], got ";
  std::ofstream(dir + "/row.csv") << "frame,x_mm,y_mm,radius_mm,force_N\n0,1,2,3,4\n\n1,1,2,three,4\n";
  EXPECT_EQ(error_of(dir + "/row.csv"), dir + "/row.csv:4" + expected + "\"1,1,2,three,4\"");
  std::ofstream(dir + "/negative.csv") << "frame,x_mm,y_mm,radius_mm,force_N\n-1,1,2,3,4\n";
  EXPECT_EQ(error_of(dir + "/negative.csv"), dir + "/negative.csv:2" + expected + "\"-1,1,2,3,4\"");
  // A seventh column used to be read as if it were not there.
  std::ofstream(dir + "/extra.csv") << "frame,x_mm,y_mm,radius_mm,force_N\n0,1,2,3,4,0.14,99\n";
  EXPECT_EQ(error_of(dir + "/extra.csv"), dir + "/extra.csv:2" + expected + "\"0,1,2,3,4,0.14,99\"");
  // Fuzzing (tests/fuzz/corpus/presses_csv_fuzz/accepted_nan_negative.csv): NaN, infinity and a
  // negative radius were read as a press.
  std::ofstream(dir + "/nan.csv") << "frame,x_mm,y_mm,radius_mm,force_N\n0,nan,inf,-3,-4\n";
  EXPECT_EQ(error_of(dir + "/nan.csv"),
            dir + "/nan.csv:2: a press needs a finite place, a radius > 0 and a force >= 0, got \"0,nan,inf,-3,-4\"");
  // Fuzzing (finding_frame_index_saturates.csv): strtol's LONG_MAX sized the sequence.
  std::ofstream(dir + "/max.csv") << "frame,x_mm,y_mm,radius_mm,force_N\n9223372036854775807,1,1,3,4,0.1\n";
  EXPECT_EQ(error_of(dir + "/max.csv"),
            dir + "/max.csv:2: frame 9223372036854775807 is beyond the 1000000 frames it describes");
  // A frame index far beyond the file's frames is an error, not a vector of 10^15 frames.
  std::ofstream(dir + "/far.csv") << "frame,x_mm,y_mm,radius_mm,force_N\n1000000000000000,1,2,3,4\n";
  EXPECT_EQ(error_of(dir + "/far.csv"),
            dir + "/far.csv:2: frame 1000000000000000 is beyond the 1000000 frames it describes");
  EXPECT_EQ(error_of(dir + "/none.csv"), dir + "/none.csv: cannot open presses file (No such file or directory)");
}

// The profile column: written only when a press is not flat (so files of flat presses are as
// before), read back, and a row without it is flat.
TEST(PressesCsv, ProfileColumnWhenSomePressIsNotFlat) {
  const std::string dir = test::temp_folder("presses_csv_profile");
  PressSequence sequence = {{{10.5, 20.25, 5, 12.5}}, {{1, 2, 3, 4}, {5.75, 6, 2.5, 0.5, PressProfile::spherical}}};
  write_presses_csv(dir + "/p.csv", sequence);
  const std::string text = test::read_text(dir + "/p.csv");
  EXPECT_EQ(text.substr(0, text.find('\n')), "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2,profile");
  EXPECT_NE(text.find("0,10.5000,20.2500,5.0000,12.500000,0.159155,flat\n"), std::string::npos) << text;
  const PressSequence read = read_presses_csv(dir + "/p.csv");
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0][0].profile, PressProfile::flat);
  EXPECT_EQ(read[1][1].profile, PressProfile::spherical);
  EXPECT_EQ(read[1][1].radius_mm, 2.5);
  sequence[1][1].profile = PressProfile::flat;
  write_presses_csv(dir + "/flat.csv", sequence);
  EXPECT_EQ(test::read_text(dir + "/flat.csv").find("profile"), std::string::npos);
  std::ofstream(dir + "/mixed.csv") << "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2,profile\n"
                                    << "0,1,2,3,4\n0,1,2,3,4,0.14,spherical \n";
  const PressSequence mixed = read_presses_csv(dir + "/mixed.csv");
  ASSERT_EQ(mixed[0].size(), 2u);
  EXPECT_EQ(mixed[0][0].profile, PressProfile::flat);
  EXPECT_EQ(mixed[0][1].profile, PressProfile::spherical);
  std::ofstream(dir + "/round.csv") << "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2,profile\n"
                                    << "0,1,2,3,4,0.14,flat\n0,1,2,3,4,0.14,round\n";
  EXPECT_EQ(error_of(dir + "/round.csv"), dir + "/round.csv:3: profile \"round\" is not flat or spherical");
  std::ofstream(dir + "/eighth.csv") << "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2,profile\n"
                                     << "0,1,2,3,4,0.14,flat,9\n";
  EXPECT_EQ(error_of(dir + "/eighth.csv"), dir + "/eighth.csv:2: profile \"flat,9\" is not flat or spherical");
}

// On a curved sheet a press's centre has a height: a z_mm column after y_mm, only when some press
// has one (flat sheets' files stay as they were); read back to the written 4 decimals.
TEST(PressesCsv, HeightColumnWhenSomePressIsOffThePlane) {
  const std::string dir = test::temp_folder("presses_csv_z");
  PressSequence sequence = {{{1, 2, 4, 10}}, {{8.25, -3.5, 4, 6}}};
  sequence[1][0].z_mm = 6.650635;
  write_presses_csv(dir + "/z.csv", sequence);
  const std::string text = test::read_text(dir + "/z.csv");
  EXPECT_EQ(text.substr(0, text.find('\n')), "frame,x_mm,y_mm,z_mm,radius_mm,force_N,pressure_N_per_mm2");
  const PressSequence read = read_presses_csv(dir + "/z.csv");
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0][0].z_mm, 0.0);
  EXPECT_NEAR(read[1][0].z_mm, 6.6506, 1e-12);
  EXPECT_EQ(read[1][0].radius_mm, 4.0);
  EXPECT_EQ(read[1][0].force_N, 6.0);
  std::ofstream(dir + "/short.csv") << "frame,x_mm,y_mm,z_mm,radius_mm,force_N\n0,1,2,3,4\n";
  EXPECT_EQ(
      error_of(dir + "/short.csv"),
      dir + "/short.csv:2: expected frame,x_mm,y_mm,z_mm,radius_mm,force_N[,pressure_N_per_mm2], got \"0,1,2,3,4\"");
}

}  // namespace

// Calibration without a robot (issue 33): a press whose place was not measured leaves x_mm and
// y_mm empty, one whose force was not measured force_N and its pressure; they read back as NaN
// where the reader takes them (calibration) and are refused by name, file and line elsewhere.
TEST(PressesCsv, EmptyPlaceAndForceRoundTripForCalibrationAndAreRefusedElsewhere) {
  const std::string dir = test::temp_folder("presses_csv_unknown");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PressSequence sequence = {{{nan, nan, 5, nan}}, {}, {{nan, nan, 5, 2}}, {{10.5, 20.25, 5, 12.5}}};
  write_presses_csv(dir + "/p.csv", sequence);
  const std::string text = test::read_text(dir + "/p.csv");
  EXPECT_EQ(text,
            "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2\n0,,,5.0000,,\n2,,,5.0000,2.000000,0.025465\n"
            "3,10.5000,20.2500,5.0000,12.500000,0.159155\n");
  const PressSequence read = read_presses_csv(dir + "/p.csv", default_max_press_frames, UnknownPresses::allowed);
  ASSERT_EQ(read.size(), 4u);
  ASSERT_EQ(read[0].size(), 1u);
  EXPECT_FALSE(place_known(read[0][0]));
  EXPECT_FALSE(force_known(read[0][0]));
  EXPECT_EQ(read[0][0].radius_mm, 5.0);
  EXPECT_FALSE(place_known(read[2][0]));
  EXPECT_EQ(read[2][0].force_N, 2.0);  // a weight of known force put down anywhere
  EXPECT_EQ(read[3][0].x_mm, 10.5);
  // Written again, the same text: the round trip is exact.
  write_presses_csv(dir + "/again.csv", read);
  EXPECT_EQ(test::read_text(dir + "/again.csv"), text);
  // Everything but calibration needs the place and the force.
  EXPECT_EQ(error_of(dir + "/p.csv"),
            dir + "/p.csv:2: place unknown: only emit calibrate takes presses without a place");
  std::ofstream(dir + "/force.csv") << "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2\n0,1,2,5,,\n";
  EXPECT_EQ(error_of(dir + "/force.csv"),
            dir + "/force.csv:2: force unknown: only emit calibrate takes presses without a force");
  // x and y are empty together or not at all; no other field may be empty.
  std::ofstream(dir + "/half.csv") << "frame,x_mm,y_mm,radius_mm,force_N\n0,1,,5,2\n";
  EXPECT_EQ(test::error_of([&] { read_presses_csv(dir + "/half.csv", 10, UnknownPresses::allowed); }),
            dir +
                "/half.csv:2: x_mm and y_mm are empty together (a place not measured) or both given, got \"0,1,,5,2\"");
  std::ofstream(dir + "/radius.csv") << "frame,x_mm,y_mm,radius_mm,force_N\n0,,,,2\n";
  EXPECT_EQ(test::error_of([&] { read_presses_csv(dir + "/radius.csv", 10, UnknownPresses::allowed); }),
            dir +
                "/radius.csv:2: only x_mm,y_mm (a place not measured) and force_N (a force not measured) may be "
                "empty, got \"0,,,,2\"");
  // The twin refuses such a press by name (simulate, the sim source: sensor/press.hpp).
  EXPECT_EQ(test::error_of([&] { validate_press(default_sensor(), read[0][0], "frame 0, press 0"); }),
            "frame 0, press 0: place unknown: only emit calibrate takes presses without a place");
}

}  // namespace emit
