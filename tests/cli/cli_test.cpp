// End to end: the emit CLI run as a user runs it, on good and on bad input.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/render/image.hpp"
#include "emit/render/pressure_map.hpp"
#include "emit/render/shaded_surface.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace fs = std::filesystem;
using test::run_emit;
using test::source_path;

std::string last_line_of(const std::string& text) {
  const std::string trimmed = text.substr(0, text.find_last_not_of('\n') + 1);
  return trimmed.substr(trimmed.find_last_of('\n') == std::string::npos ? 0 : trimmed.find_last_of('\n') + 1);
}

int occurrences(const std::string& text, const std::string& what) {
  int count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

TEST(Cli, SimulatesOnePress) {
  const std::string dir = test::temp_folder("cli_one");
  const auto r = run_emit("simulate --press 30,30,5,10 --exact --out " + dir + "/f.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto frames = read_frames_csv(dir + "/f.csv", 16);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].diagonal().cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(frames[0].maxCoeff(), 0.1);  // a 10 N press reads hundreds of mV
  const PressSequence truth = read_presses_csv(dir + "/f_presses.csv");
  ASSERT_EQ(truth.size(), 1u);
  EXPECT_EQ(truth[0][0].force_N, 10.0);
}

// A flat punch of another outline (sensor/press_outline.hpp): a bar and a ring in one frame, the
// truth with their outlines (README "Files"); each reads back with its area.
TEST(Cli, SimulatesOutlinePresses) {
  const std::string dir = test::temp_folder("cli_outline");
  const auto r =
      run_emit("simulate --press bar:20,40,20,6,30,8 --press ring:38,22,6,9,6 --exact --out " + dir + "/f.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto frames = read_frames_csv(dir + "/f.csv", 16);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_GT(frames[0].maxCoeff(), 0.1);  // 14 N read hundreds of mV
  const PressSequence truth = read_presses_csv(dir + "/f_presses.csv");
  ASSERT_EQ(truth.size(), 1u);
  ASSERT_EQ(truth[0].size(), 2u);
  EXPECT_NEAR(press_area_mm2(truth[0][0]), 120, 1e-6);  // vertices to 9 digits
  EXPECT_EQ(truth[0][1].outline_mm.size(), 2u);         // the ring's two circles
}

TEST(Cli, GridScriptWritesOneFramePerPressAndTheTruth) {
  const std::string dir = test::temp_folder("cli_grid");
  const auto r =
      run_emit("simulate --sensor " + source_path("examples/sensors/square30.json") +
               " --script grid --spacing-mm 10 --radius-mm 3 --out " + dir + "/g.csv --truth " + dir + "/t.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto frames = read_frames_csv(dir + "/g.csv", 16);
  const auto truth = read_presses_csv(dir + "/t.csv");
  EXPECT_EQ(frames.size(), 9u);  // 30 mm sheet, 10 mm pitch, 3 mm margin: a 3 × 3 grid
  EXPECT_EQ(truth.size(), frames.size());
}

TEST(Cli, TwoFingerAndMovingScripts) {
  const std::string dir = test::temp_folder("cli_scripts");
  auto r = run_emit("simulate --script two-finger --frames 3 --separation-mm 12,40 --force-N 5,20 --out " + dir +
                    "/two.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto two = read_presses_csv(dir + "/two_presses.csv");
  ASSERT_EQ(two.size(), 3u);
  for (const auto& frame : two) {
    ASSERT_EQ(frame.size(), 2u);
    const double separation = std::hypot(frame[0].x_mm - frame[1].x_mm, frame[0].y_mm - frame[1].y_mm);
    EXPECT_GE(separation, 12.0 - 1e-3);
    EXPECT_LE(separation, 40.0 + 1e-3);
  }
  r = run_emit("simulate --script moving --from 10,10 --to 50,50 --frames 5 --out " + dir + "/move.csv --images " +
               dir + "/img");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_frames_csv(dir + "/move.csv", 16).size(), 5u);
  EXPECT_GT(read_png(dir + "/img/frame_000004.png").width(), 100);
}

// A realistic sheet with three spherical fingers, and what it drew beside the frames.
TEST(Cli, RealisticSheetWithThreeFingers) {
  const std::string dir = test::temp_folder("cli_realistic");
  const auto r = run_emit("simulate --sensor " + source_path("examples/sensors/square30.json") +
                          " --realistic 5 --script three-finger --frames 2 --radius-mm 3 --profile spherical --exact "
                          "--out " +
                          dir + "/r.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("realistic sheet: Rs x"), std::string::npos) << r.err;
  const auto frames = read_frames_csv(dir + "/r.csv", 16);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].diagonal().cwiseAbs().maxCoeff(), 0.0);
  const PressSequence truth = read_presses_csv(dir + "/r_presses.csv");
  ASSERT_EQ(truth.size(), 2u);
  for (const auto& frame : truth) {
    ASSERT_EQ(frame.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(frame[i].profile, PressProfile::spherical);
      for (std::size_t j = 0; j < i; ++j)  // the default least separation, 12 mm
        EXPECT_GE(std::hypot(frame[i].x_mm - frame[j].x_mm, frame[i].y_mm - frame[j].y_mm), 12.0 - 1e-3);
    }
  }
  const auto sheet = nlohmann::json::parse(test::read_text(dir + "/r_sheet.json"));
  const double drive = sheet.at("drive_voltage_V").get<double>();
  EXPECT_GE(drive, 3.0);
  EXPECT_LE(drive, 3.3);
  // No reading above the drive: the sheet's potentials lie in [0, E] (maximum principle).
  EXPECT_LE(std::max(frames[0].maxCoeff(), frames[1].maxCoeff()), drive);
  ASSERT_EQ(sheet.at("electrode_shift_mm").size(), 16u);
  for (const auto& shift : sheet.at("electrode_shift_mm")) EXPECT_LE(std::abs(shift.get<double>()), 0.5 + 1e-12);
  for (const auto& ohm : sheet.at("series_resistance_ohm")) {
    EXPECT_GE(ohm.get<double>(), 0.0);
    EXPECT_LE(ohm.get<double>(), 300.0);
  }
  EXPECT_NEAR(sheet.at("sheet_scale").get<double>(), 1.0, 0.3 + 1e-12);
  // The same seed draws the same sheet: the same frames.
  ASSERT_EQ(run_emit(
                "simulate --sensor " + source_path("examples/sensors/square30.json") +
                " --realistic 5 --script three-finger --frames 2 --radius-mm 3 --profile spherical --exact --out " +
                dir + "/again.csv")
                .exit_code,
            0);
  EXPECT_EQ(test::read_text(dir + "/again.csv"), test::read_text(dir + "/r.csv"));
}

// A curved sheet as a user simulates it: the dome of the conformance frames, a press given by
// (x, y), its centre put on the surface (the truth file's z_mm), the frame the independent
// implementation's to the conformance 1 %.
TEST(Cli, SimulatesASphericalCap) {
  const std::string dir = test::temp_folder("cli_dome");
  const std::string dome = test::source_path("tests/data/conformance/dome25");
  const auto r =
      run_emit("simulate --sensor " + dome + "_sensor.json --press 8.034845,9.575556,4,10.053096 --exact --out " + dir +
               "/f.csv --images " + dir + "/img");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The potential drawn as the curved sheet's shaded two-panel picture, not the flat one (640 px).
  EXPECT_EQ(read_png(dir + "/img/frame_000000.png").width(), shaded_pressure_map_width_px);
  const PressSequence truth = read_presses_csv(dir + "/f_presses.csv");
  ASSERT_EQ(truth.size(), 1u);
  EXPECT_NEAR(truth[0][0].z_mm, 6.650635, 1e-4);  // the conformance file's, to the 4 decimals written
  const Frame frame = read_frames_csv(dir + "/f.csv", 16).at(0);
  const Frame reference = read_frames_csv(dome + "_frames.csv", 16).at(1);
  EXPECT_LE((frame - reference).cwiseAbs().maxCoeff(), 0.01 * reference.cwiseAbs().maxCoeff());
}

/// The contacts of a contacts file, frame by frame.
std::vector<std::vector<Contact>> read_contacts_file(const std::string& path) {
  std::vector<std::vector<Contact>> frames;
  std::istringstream lines(test::read_text(path));
  for (std::string line; std::getline(lines, line);) frames.push_back(parse_contacts_line(line));
  return frames;
}

/// The dome's reference frame: without a press its probing layer carries no current, so all 16 × 16
/// readings are 0 V.
void write_zero_reference(const std::string& path) {
  std::ofstream zeros(path);
  for (int i = 0; i < 256; ++i) zeros << (i ? ",0" : "0");
  zeros << "\n";
}

// A curved .msh is a sensor (sensor/height_field.hpp): the dome meshed to a file, pressed at
// (3, 4) and fitted, is found on the dome's surface there, z = √(25² − 25) − 15 = 9.49 mm (the
// file is both twin and reconstruction mesh: the bound is the curved sheets' target, 0.3 mm). The
// sleeve, whose sides are vertical and whose underside +z sees through its top, is refused in one
// line, naming where.
TEST(Cli, ACurvedMeshFileIsASensorAndAFoldedOneIsRefused) {
  const std::string dir = test::temp_folder("cli_curved_msh");
  for (const std::string sheet : {"dome25", "sleeve"})
    ASSERT_EQ(run_emit("mesh --sensor " + test::source_path("examples/sensors/" + sheet + ".json") + " --out " + dir +
                       "/" + sheet + ".msh")
                  .exit_code,
              0);
  std::ofstream(dir + "/dome_msh.json") << R"({"shape": {"type": "mesh", "file": "dome25.msh"}})";
  write_zero_reference(dir + "/zeros.csv");
  ASSERT_EQ(run_emit("simulate --sensor " + dir + "/dome_msh.json --press 3,4,4,10 --exact --out " + dir + "/f.csv")
                .exit_code,
            0);
  const auto fitted = run_emit("reconstruct --sensor " + dir + "/dome_msh.json --method fit --frames " + dir +
                               "/f.csv --reference " + dir + "/zeros.csv --contacts " + dir + "/c.jsonl");
  ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
  const auto frames = read_contacts_file(dir + "/c.jsonl");
  ASSERT_EQ(frames.size(), 1u);
  ASSERT_EQ(frames[0].size(), 1u);
  const Contact& c = frames[0][0];
  EXPECT_LT(std::hypot(c.x_mm - 3, c.y_mm - 4, c.z_mm - (std::sqrt(600.0) - 15)), 0.3);
  std::ofstream(dir + "/sleeve_msh.json") << R"({"shape": {"type": "mesh", "file": "sleeve.msh"}})";
  const auto r = run_emit("simulate --sensor " + dir + "/sleeve_msh.json --press 3,4,4,10 --out " + dir + "/g.csv");
  EXPECT_NE(r.exit_code, 0);
  // Its sides are vertical: a triangle there is seen edge-on, or past them its underside twice.
  const bool edge_on = r.err.find("sleeve.msh\": a triangle at (") != std::string::npos &&
                       r.err.find(" mm is seen edge-on from +z") != std::string::npos;
  const bool twice = r.err.find("sleeve.msh\": the surface covers (") != std::string::npos &&
                     r.err.find(" twice seen from +z") != std::string::npos;
  EXPECT_TRUE(edge_on || twice) << r.err;
  EXPECT_EQ(occurrences(r.err, "emit: "), 1) << r.err;
  EXPECT_EQ(last_line_of(r.err).rfind("emit: ", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/g.csv"));
}

// Contact fitting on a curved sheet, checked on frames nobody here simulated: the independent
// implementation's dome frames (80k triangles; without a press the probing layer carries no
// current, so the reference is all zeros). The targets: single presses within 0.3 mm in
// 3D on average, both of two presses within 2 mm. Measured: 0.009 and 0.13 mm; the pair 0.016
// and 0.46 mm (the weak 0.05 N/mm² press beside a 0.3 N/mm² one). Each contact is a point of the
// sphere with its outward normal.
TEST(Cli, FitsContactsOnTheDomesIndependentFrames) {
  const std::string dir = test::temp_folder("cli_dome_fit");
  const std::string dome = test::source_path("tests/data/conformance/dome25");
  write_zero_reference(dir + "/zero.csv");
  const auto r = run_emit("reconstruct --sensor " + dome + "_sensor.json --reference " + dir + "/zero.csv --frames " +
                          dome + "_frames.csv --contacts " + dir + "/c.jsonl --no-cache");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto contacts = read_contacts_file(dir + "/c.jsonl");
  const PressSequence truth = read_presses_csv(dome + "_presses.csv");
  ASSERT_EQ(contacts.size(), truth.size());
  const auto distance = [](const Contact& c, const Press& p) {
    return (Vector3(c.x_mm, c.y_mm, c.z_mm) - Vector3(p.x_mm, p.y_mm, p.z_mm)).norm();
  };
  double singles_mm = 0;
  for (std::size_t f = 0; f < 2; ++f) {
    ASSERT_EQ(contacts[f].size(), 1u) << "frame " << f;
    singles_mm += distance(contacts[f][0], truth[f][0]) / 2;
  }
  EXPECT_LE(singles_mm, 0.3);
  ASSERT_EQ(contacts[2].size(), 2u);
  for (const Press& p : truth[2])
    EXPECT_LE(std::min(distance(contacts[2][0], p), distance(contacts[2][1], p)), 2.0) << p.x_mm << ", " << p.y_mm;
  for (const auto& frame : contacts)
    for (const Contact& c : frame) {
      // On the sphere of radius 25 mm about (0, 0, −15), the normal along the radius (6 decimals).
      const Vector3 radius = Vector3(c.x_mm, c.y_mm, c.z_mm + 15);
      EXPECT_NEAR(radius.norm(), 25, 1e-4);
      EXPECT_NEAR((radius / 25 - Vector3(c.nx, c.ny, c.nz)).norm(), 0, 1e-5);
    }
}

// A sleeve as a user runs it: a press given with its z (the cylinder's underside, on the chart's
// seam) is simulated, and contact fitting finds it within the 0.3 mm target, on the cylinder with
// the radial normal; the truth file carries the press's z.
TEST(Cli, SimulatesAndFitsAPressUnderASleeve) {
  const std::string dir = test::temp_folder("cli_sleeve");
  const std::string sleeve = test::source_path("examples/sensors/sleeve.json");
  ASSERT_EQ(run_emit("simulate --sensor " + sleeve + " --script none --frames 1 --out " + dir + "/ref.csv").exit_code,
            0);
  const auto simulated = run_emit("simulate --sensor " + sleeve + " --press 8,0,-15,4,10 --out " + dir + "/frames.csv");
  ASSERT_EQ(simulated.exit_code, 0) << simulated.err;
  const PressSequence truth = read_presses_csv(dir + "/frames_presses.csv");
  ASSERT_EQ(truth.size(), 1u);
  EXPECT_NEAR(truth[0][0].z_mm, -15, 1e-4);
  const auto r = run_emit("reconstruct --sensor " + sleeve + " --reference " + dir + "/ref.csv --frames " + dir +
                          "/frames.csv --contacts " + dir + "/c.jsonl --no-cache");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto contacts = read_contacts_file(dir + "/c.jsonl");
  ASSERT_EQ(contacts.size(), 1u);
  ASSERT_EQ(contacts[0].size(), 1u);
  const Contact& c = contacts[0][0];
  EXPECT_LE((Vector3(c.x_mm, c.y_mm, c.z_mm) - Vector3(8, 0, -15)).norm(), 0.3);
  EXPECT_NEAR(std::hypot(c.y_mm, c.z_mm), 15, 1e-4);  // JSON Lines keep 6 decimals
  EXPECT_NEAR((Vector3(0, c.y_mm, c.z_mm) / 15 - Vector3(c.nx, c.ny, c.nz)).norm(), 0, 1e-5);
}

// --images on the dome: each frame's pressure map is the shaded two-panel picture (an oblique view
// and the top view), of the size its layout gives for the title emit writes.
TEST(Cli, ImagesOfTheDomeAreTheShadedTwoPanelPicture) {
  const std::string dir = test::temp_folder("cli_dome_images");
  const std::string dome = test::source_path("tests/data/conformance/dome25");
  write_zero_reference(dir + "/zero.csv");
  const auto r = run_emit("reconstruct --sensor " + dome + "_sensor.json --reference " + dir + "/zero.csv --frames " +
                          dome + "_frames.csv --contacts " + dir + "/c.jsonl --no-cache --images " + dir + "/img");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image image = read_png(dir + "/img/frame_000000.png");
  const Sensor sensor = load_sensor(dome + "_sensor.json");
  FieldImageOptions options;
  options.width_px = shaded_pressure_map_width_px;
  options.title = "frame 0: pressure (fit, uncalibrated), 1 contact";  // as reconstruct titles it
  options.unit = "N/mm2";
  const ShadedLayout layout = plan_shaded_layout(generate_mesh(sensor, reconstruction_mesh_options(sensor)), options);
  EXPECT_EQ(image.width(), layout.width_px);
  EXPECT_EQ(image.height(), layout.height_px);
  EXPECT_TRUE(fs::exists(dir + "/img/frame_000002.png"));
}

// Pictures of one run that compare (--pressure-range): a light press (3 N on a 5 mm disc) and a
// strong one (20 N) at one place, uncalibrated (the nominal contact law puts them at 0.13 and 0.90
// N/mm2 on 18 mm2), drawn to 0.3 N/mm2. The colour bar's top colour (colormap(1)) then marks
// pressure at or past 0.3: the strong press's picture holds it on the sheet as well as in the bar
// (about 160 pixels of its disc at 400 px), the light one's only in the bar. Drawn each to its own largest
// pressure (no --pressure-range), the light press reaches the top colour too: the two pictures
// did not compare. Names sort in frame order; --image-width sets the width.
TEST(Cli, ImagesOfARunShareTheirScaleWhenAskedAndSortInOrder) {
  const std::string dir = test::temp_folder("cli_image_scale");
  ASSERT_EQ(run_emit("simulate --script none --frames 3 --out " + dir + "/ref.csv").exit_code, 0);
  ASSERT_EQ(run_emit("simulate --press 30,30,5,3 --out " + dir + "/light.csv").exit_code, 0);
  ASSERT_EQ(run_emit("simulate --press 30,30,5,20 --out " + dir + "/strong.csv").exit_code, 0);
  std::ofstream(dir + "/both.csv") << test::read_text(dir + "/light.csv") << test::read_text(dir + "/strong.csv");
  const auto top_coloured = [](const Image& image) {
    const Rgb top = colormap(1);
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const Rgb p = image.get(x, y);
        n += std::abs(p.r - top.r) + std::abs(p.g - top.g) + std::abs(p.b - top.b) <= 6 ? 1 : 0;
      }
    return n;
  };
  const std::string run = "reconstruct --reference " + dir + "/ref.csv --frames " + dir + "/both.csv --contacts " +
                          dir + "/c.jsonl --no-cache --images ";
  auto r = run_emit(run + dir + "/fixed --pressure-range 0.3 --image-width 400");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image light = read_png(dir + "/fixed/frame_000000.png"), strong = read_png(dir + "/fixed/frame_000001.png");
  EXPECT_EQ(light.width(), 400);
  EXPECT_EQ(strong.width(), 400);
  const int bar_only = top_coloured(light);
  EXPECT_GT(bar_only, 0) << "the colour bar's top";
  EXPECT_GT(top_coloured(strong), bar_only + 50) << "the strong press past the range, on the sheet";
  r = run_emit(run + dir + "/own");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_png(dir + "/own/frame_000000.png").width(), 640);
  EXPECT_GT(top_coloured(read_png(dir + "/own/frame_000000.png")), bar_only + 5) << "the light press at its own top";
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir + "/own")) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"frame_000000.png", "frame_000001.png"}));
}

// Four fingers, with the realistic sheet's sizes set one by one.
TEST(Cli, FourFingersOnASheetWithoutSeriesResistance) {
  const std::string dir = test::temp_folder("cli_four");
  const auto r = run_emit(
      "simulate --script four-finger --frames 2 --separation-mm 15 --exact --realistic --realistic-series-ohm 0 "
      "--realistic-blur-mm 0 --realistic-sheet-scale 0.1 --realistic-field 0.05 --realistic-shift-mm 0.2 "
      "--realistic-drive-V 3.1,3.2 --out " +
      dir + "/four.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const PressSequence truth = read_presses_csv(dir + "/four_presses.csv");
  ASSERT_EQ(truth.size(), 2u);
  EXPECT_EQ(truth[1].size(), 4u);
  EXPECT_EQ(test::read_text(dir + "/four_presses.csv").find("profile"), std::string::npos);  // flat: no column
  const auto sheet = nlohmann::json::parse(test::read_text(dir + "/four_sheet.json"));
  EXPECT_NEAR(sheet.at("drive_voltage_V").get<double>(), 3.15, 0.05 + 1e-12);
  EXPECT_NEAR(sheet.at("sheet_scale").get<double>(), 1.0, 0.1 + 1e-12);
  EXPECT_NEAR(sheet.at("field_factor_range")[1].get<double>(), 1.05, 0.05 + 1e-12);
  for (const auto& ohm : sheet.at("series_resistance_ohm")) EXPECT_EQ(ohm.get<double>(), 0.0);
  for (const auto& shift : sheet.at("electrode_shift_mm")) EXPECT_LE(std::abs(shift.get<double>()), 0.2 + 1e-12);
}

// A user's round: references, calibration presses, test presses; calibrate, reconstruct.
TEST(Cli, CalibrateThenReconstruct) {
  const std::string d = test::temp_folder("cli_reconstruct");
  const std::string cache = " --cache " + d + "/cache";
  ASSERT_EQ(run_emit("simulate --script none --frames 5 --out " + d + "/ref.csv").exit_code, 0);
  ASSERT_EQ(run_emit("simulate --script random --frames 12 --force-N 2,30 --seed 3 --out " + d + "/cal.csv").exit_code,
            0);
  ASSERT_EQ(run_emit("simulate --press 21,37,5,12 --out " + d + "/one.csv").exit_code, 0);
  const std::string calibrate =
      "calibrate --reference " + d + "/ref.csv --frames " + d + "/cal.csv --truth " + d + "/cal_presses.csv";
  // The twin's sheet is its description: the contact law alone (--no-sheet). Fitting the sheet
  // from the presses is CalibrationCorrectsANonUniformSheet's, and `emit eval --realistic`'s.
  auto r = run_emit(calibrate + " --no-sheet --out " + d + "/calib.json" + cache);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("alpha ="), std::string::npos) << "the default method, fit, calibrates the contact law";
  r = run_emit("reconstruct --reference " + d + "/ref.csv --frames " + d + "/one.csv --contacts " + d +
               "/c.jsonl --calibration " + d + "/calib.json --images " + d + "/img" + cache);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  long frame = -1;
  auto contacts = parse_contacts_line(test::read_text(d + "/c.jsonl"), &frame);
  EXPECT_EQ(frame, 0);
  ASSERT_EQ(contacts.size(), 1u);
  // Contact fitting: the targets, p95 0.6 mm and a pressure error of 0.02 N/mm².
  EXPECT_LE(std::hypot(contacts[0].x_mm - 21, contacts[0].y_mm - 37), 0.6);
  EXPECT_NEAR(contacts[0].pressure_N_per_mm2, 12 / (std::numbers::pi * 25), 0.02);
  // Reported with the calibration presses' indenter (radius 5 mm): the force is the press's, to
  // the same 0.02 N/mm² over its 78.5 mm².
  EXPECT_NEAR(contacts[0].area_mm2, std::numbers::pi * 25, 1e-3);  // contacts.jsonl keeps 6 digits
  EXPECT_NEAR(contacts[0].force_N, 12, 0.02 * std::numbers::pi * 25);
  // With its uncertainty: a 1σ between a hundredth and a few tenths of a millimetre (the fit's
  // errors on the twin are ~0.1 mm), and the frame's misfit near the 1 mV noise of the readings.
  EXPECT_GT(contacts[0].x_std_mm, 0.005);
  EXPECT_LT(contacts[0].x_std_mm, 0.3);
  const std::string line = test::read_text(d + "/c.jsonl");
  const auto misfit_at = line.find("\"fit_misfit_mV\": ");
  ASSERT_NE(misfit_at, std::string::npos) << line;
  EXPECT_LT(std::stod(line.substr(misfit_at + 17)), 3.0) << line;
  EXPECT_GT(read_png(d + "/img/frame_000000.png").width(), 100);
  // A second run loads the (seeding) operator from the cache.
  r = run_emit("reconstruct --reference " + d + "/ref.csv --frames " + d + "/one.csv --contacts " + d + "/c2.jsonl" +
               cache);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("operator from the cache"), std::string::npos) << r.err;

  // The paper's method: eq. 8; its error is a few mm (p95 ≈ 8 mm on the 60 mm sheet, emit eval).
  r = run_emit(calibrate + " --method paper --out " + d + "/calib_paper.json" + cache);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("a3 ="), std::string::npos);
  EXPECT_NE(r.out.find("fitted the force F = (b1/I + b2)^b3"), std::string::npos) << r.out;
  r = run_emit("reconstruct --method paper --reference " + d + "/ref.csv --frames " + d + "/one.csv --contacts " + d +
               "/c3.jsonl --calibration " + d + "/calib_paper.json" + cache);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  contacts = parse_contacts_line(test::read_text(d + "/c3.jsonl"), &frame);
  ASSERT_GE(contacts.size(), 1u);
  EXPECT_LE(std::hypot(contacts[0].x_mm - 21, contacts[0].y_mm - 37), 8.0);
  // Its force from the image's integral by the calibration's force law (model/force_law.hpp):
  // issue 31's 15 % (1 % measured), at the calibration indenter's area.
  EXPECT_NEAR(contacts[0].force_N, 12, 0.15 * 12);
  EXPECT_NEAR(contacts[0].area_mm2, std::numbers::pi * 25, 1e-3);
  // A file written before the force law (eq. 8 alone) still loads, with a warning that its
  // forces are the image's.
  std::ofstream(d + "/calib_old.json") << R"({"a1": 3.3, "a2": -1, "a3": -0.8})";
  r = run_emit("reconstruct --method paper --reference " + d + "/ref.csv --frames " + d + "/one.csv --contacts " + d +
               "/c5.jsonl --calibration " + d + "/calib_old.json" + cache);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("calib_old.json: no force_law"), std::string::npos) << r.err;
  // A calibration made for the other method is refused, naming the fix.
  r = run_emit("reconstruct --method paper --reference " + d + "/ref.csv --frames " + d + "/one.csv --contacts " + d +
               "/c4.jsonl --calibration " + d + "/calib.json" + cache);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("emit calibrate --method paper"), std::string::npos) << r.err;
}

// A sheet 20 % more resistive on one side than the other (the reconstruction is told the nominal
// one): `emit calibrate` fits the variation from the calibration presses, and a press elsewhere
// is found within the 30 mm sheet's target of 0.2 mm; without the correction it is millimetres off.
// On the 30 mm sheet meshed at 1 mm instead of its 0.6 mm (a test's size: the twin still meshes
// it twice as finely, and the 0.2 mm holds there, 0.01-0.04 mm measured); the electrodes' places,
// whose fit slides the mesh and costs most, are fitted by `emit eval --realistic` (below).
TEST(Cli, CalibrationCorrectsANonUniformSheet) {
  const std::string d = test::temp_folder("cli_sheet");
  auto square30 = nlohmann::json::parse(test::read_text(source_path("examples/sensors/square30.json")));
  square30["mesh"]["element_size_mm"] = 1.0;
  std::ofstream(d + "/square30_coarse.json") << square30.dump();
  const std::string twin = " --sensor " + d + "/square30_coarse.json --sheet-variation 0.2";
  const std::string sensor = " --sensor " + d + "/square30_coarse.json --cache " + d + "/cache";
  ASSERT_EQ(run_emit("simulate" + twin + " --script none --frames 5 --out " + d + "/ref.csv").exit_code, 0);
  ASSERT_EQ(run_emit("simulate" + twin +
                     " --script random --frames 12 --force-N 0.5,8 --radius-mm 2.5 --seed 3 --out " + d + "/cal.csv")
                .exit_code,
            0);
  ASSERT_EQ(run_emit("simulate" + twin + " --press 9,20,2.5,3 --out " + d + "/one.csv").exit_code, 0);
  // The sheet alone (a quadratic field, as first calibrated): 12 presses pin its range.
  auto r = run_emit("calibrate" + sensor + " --reference " + d + "/ref.csv --frames " + d + "/cal.csv --truth " + d +
                    "/cal_presses.csv --out " + d +
                    "/calib.json --sheet-terms 5 --no-electrodes "
                    "--no-series-resistance --no-drive");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  double low = 0, high = 0;
  const auto at = r.out.find("sheet conductance ");
  ASSERT_NE(at, std::string::npos) << r.out;
  // NOLINTNEXTLINE(cert-err34-c): emit's own output, the field count checks its shape
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, "sheet conductance %lf to %lf", &low, &high), 2) << r.out;
  EXPECT_NEAR(low, 1 / 1.2, 0.02) << "the twin's sheet: 1/(1 ± 0.2) of the nominal conductance";
  EXPECT_NEAR(high, 1 / 0.8, 0.02);
  const auto error_mm = [&](const std::string& calibration) {
    const auto run = run_emit("reconstruct" + sensor + " --reference " + d + "/ref.csv --frames " + d +
                              "/one.csv --contacts " + d + "/c.jsonl" + calibration);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const auto contacts = parse_contacts_line(test::read_text(d + "/c.jsonl"), nullptr);
    return contacts.empty() ? 1e9 : std::hypot(contacts[0].x_mm - 9, contacts[0].y_mm - 20);
  };
  EXPECT_LT(error_mm(" --calibration " + d + "/calib.json"), 0.2);
  EXPECT_GT(error_mm(""), 1.0);
  // The sheet (cubic field), the series resistances and the drive (26 parameters from 12
  // presses): the press is found as well, and the file says which parameters the presses set.
  r = run_emit("calibrate" + sensor + " --reference " + d + "/ref.csv --frames " + d + "/cal.csv --truth " + d +
               "/cal_presses.csv --no-electrodes --out " + d + "/full.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_LT(error_mm(" --calibration " + d + "/full.json"), 0.2);
  const std::string full = test::read_text(d + "/full.json");
  EXPECT_NE(full.find("\"series_resistance_ohm\""), std::string::npos) << full;
  EXPECT_NE(full.find("\"determined\": true"), std::string::npos) << full;
}

// emit eval as a user runs it, on one sheet: contact fitting meets the 30 mm
// sheet's target (0.2 mm) on the twin, and the plots are drawn.
TEST(Cli, EvalMeasuresContactFitting) {
  const std::string d = test::temp_folder("cli_eval");
  const auto r = run_emit("eval --quick --sheet 30 --methods fit --no-mismatches --plots " + d + "/plots");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto row = r.out.find("\n  fit ");
  ASSERT_NE(row, std::string::npos) << r.out;
  double mean_mm = -1, std_mm = -1;
  // NOLINTNEXTLINE(cert-err34-c): emit's own output, the field count checks its shape
  ASSERT_EQ(std::sscanf(r.out.c_str() + row, "\n  fit %*s %lf +/- %lf", &mean_mm, &std_mm), 2) << r.out;
  EXPECT_GE(mean_mm, 0.0);
  EXPECT_LT(mean_mm, 0.2) << r.out;
  // The rows of several presses and of false regions (issue 31): too few frames in --quick to bound.
  EXPECT_NE(r.out.find("three presses all found within 2 mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("false regions on single presses"), std::string::npos) << r.out;
}

/// The numbers after `label` on its line of `text` (read with `pattern`), or fewer if not found.
template <typename... Values>
int read_row(const std::string& text, const std::string& label, const char* pattern, Values*... values) {
  const std::size_t at = text.find("\n  " + label);
  if (at == std::string::npos) return 0;
  // NOLINTNEXTLINE(cert-err34-c): emit's own output, the field count checks its shape
  return std::sscanf(text.c_str() + at + 3 + label.size(), pattern, values...);
}

// emit eval --tracking as a user runs it (--quick, 2 crossings): the table's rows, each figure within
// its target (tests/eval/tracking_evaluation_test.cpp says why; emit eval --tracking measures 200 of
// 200 crossings without a swap, 0.035 mm of filtered jitter, no lag). 10-20 s in Release.
TEST(Cli, EvalTrackingReportsCrossingsJitterAndLag) {
  const auto r = run_emit("eval --tracking --quick --crossings 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("crossings, unfiltered: ids kept (no swap) in 2 of 2 = 100.0 %"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("crossings, filtered  : ids kept (no swap) in 2 of 2 = 100.0 %"), std::string::npos) << r.out;
  double raw_mm = -1, filtered_mm = -1;
  ASSERT_EQ(read_row(r.out, "still 5 N press: jitter", " %lf mm rms unfiltered, %lf mm filtered", &raw_mm,
                     &filtered_mm),
            2)
      << r.out;
  EXPECT_LE(filtered_mm, 0.05) << r.out;
  EXPECT_NE(r.out.find("step of 3 mm: within 10 % of it after 0 frames filtered"), std::string::npos) << r.out;
}

// emit eval --realistic as a user runs it (--quick): the README's round on realistic sheet 3 in one
// command, every figure beside its target, calibrated on the fewest presses a calibration takes
// (8: the presses fit the sheet's few dozen parameters, not a response per place). The bounds: the
// calibrated position meets its target, 0.3 mm mean and 0.6 mm p95 (it measures 0.093 and 0.191 mm
// here with 8 presses, 0.070 and 0.110 with 40; 0.069 and 0.160 with 8 presses and the full counts);
// the nominal file misplaces presses by more than 1 mm (2.6 mm measured: what the calibration
// fixes); the same indenter's force within the target of 10 % (1.4 % measured) and other indenters'
// within that of 15 % (10.1 %: their areas' (A_cal/A)^(1/6)); no false contact on single presses
// (none measured; one would be a regression). About 20 s in Release.
TEST(Cli, EvalRealisticRunsTheRoundAgainstTheTargets) {
  const auto r = run_emit("eval --realistic 3 --quick --calibration-presses 8");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("10 reference frames, 8 calibration and 3 test presses"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("60 x 60 mm sheet, 16 electrodes, realistic sheet 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| realistic sheet, seed 3"), std::string::npos) << r.out;  // what it drew
  EXPECT_EQ(r.out.find("30 x 30 mm sheet"), std::string::npos) << "only the 60 mm sheet by default";
  EXPECT_EQ(r.out.find("sleeve"), std::string::npos) << "\"60\" begins the 60 mm sheet's name, not the sleeve's";
  double nominal_mm = -1, calibrated_mm = -1, nominal_p95_mm = -1, calibrated_p95_mm = -1;
  ASSERT_EQ(read_row(r.out, "position, mean", " %lf mm %lf mm", &nominal_mm, &calibrated_mm), 2) << r.out;
  ASSERT_EQ(read_row(r.out, "position, p95", " %lf mm %lf mm", &nominal_p95_mm, &calibrated_p95_mm), 2) << r.out;
  EXPECT_LT(calibrated_mm, 0.3) << r.out;
  EXPECT_LT(calibrated_p95_mm, 0.6) << r.out;
  EXPECT_GT(nominal_mm, 1.0) << r.out;
  double nominal_force = -1, calibrated_force = -1, other_force = -1;
  ASSERT_EQ(read_row(r.out, "force, mean |relative error| (same indenter)", " %lf %% %lf %%", &nominal_force,
                     &calibrated_force),
            2)
      << r.out;
  EXPECT_LT(calibrated_force, 10.0) << r.out;
  ASSERT_EQ(read_row(r.out, "other indenters (3-10 mm), mean |force error|", " - %lf %%", &other_force), 1) << r.out;
  EXPECT_LT(other_force, 15.0) << r.out;
  int nominal_false = -1, nominal_single = -1, calibrated_false = -1, calibrated_single = -1;
  ASSERT_EQ(read_row(r.out, "false contacts (single presses, > 1 contact)", " %d of %d %d of %d", &nominal_false,
                     &nominal_single, &calibrated_false, &calibrated_single),
            4)
      << r.out;
  EXPECT_EQ(calibrated_false, 0) << r.out;
  EXPECT_EQ(calibrated_single, 3 + 10) << "the test presses and one of each other indenter";
  // Every figure is there, beside its target: too few frames in --quick to bound them here.
  for (const char* row : {"pressure, mean |error| (N/mm2)", "three presses >= 12 mm apart, all within 2 mm",
                          "four presses >= 12 mm apart, all within 2 mm", "calibration, wall time",
                          "contact fitting, a frame of one press", "  |force error| within 2 sigma"})
    EXPECT_NE(r.out.find(row), std::string::npos) << row << "\n" << r.out;
  EXPECT_NE(r.err.find("sensor calibration: iteration"), std::string::npos) << "progress on stderr";
}

/// A family's row of `method`'s block in `emit eval --outlines`' table: frames, Dice, |force
/// error| %, force ratio and (when it has one) the centroid's error; false if not found.
struct OutlineRow {
  int frames = -1;
  double dice = -1, force_error = -1, force_ratio = -1, centroid_mm = -1;
};
bool read_outline_row(const std::string& text, const std::string& method, const std::string& family, OutlineRow& row) {
  const std::size_t block = text.find("\n  " + method + " (");
  if (block == std::string::npos) return false;
  const std::size_t at = text.find("\n  " + family + " ", block);
  if (at == std::string::npos) return false;
  // NOLINTNEXTLINE(cert-err34-c): emit's own output, the field count checks its shape
  return std::sscanf(text.c_str() + at + 3 + family.size(), " %d %lf %lf %% x%lf %lf mm", &row.frames, &row.dice,
                     &row.force_error, &row.force_ratio, &row.centroid_mm) >= 4;
}

// emit eval --outlines as a user runs it (--quick: one frame of each of the eight outlines), for
// the paper's method and contact fitting, each calibrated on 16 disc presses (--quick; 40 in a full run). Bounds: every
// Dice in [0, 1]; contact fitting's regions are centred within 3 mm over all outlines (its fitted discs sit on the
// presses' centroids: 0.11 mm in issue 31's measurement); the paper's method's pressed region is not the outline (Dice
// below 0.3: its 50 % region is blurred to 2-5 times a contact's area, issue 31 measured 0.09) and below fit's on the
// 30 x 3 bar.
TEST(Cli, EvalOutlinesScoresEachMethodPerOutline) {
  const auto r = run_emit("eval --outlines --quick --methods paper,fit");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("60 x 60 mm sheet, 16 electrodes"), std::string::npos) << r.out;
  OutlineRow paper, fit, paper_bar, fit_bar;
  ASSERT_TRUE(read_outline_row(r.out, "paper", "all", paper)) << r.out;
  ASSERT_TRUE(read_outline_row(r.out, "fit", "all", fit)) << r.out;
  ASSERT_TRUE(read_outline_row(r.out, "paper", "bar 30x3", paper_bar)) << r.out;
  ASSERT_TRUE(read_outline_row(r.out, "fit", "bar 30x3", fit_bar)) << r.out;
  EXPECT_EQ(paper.frames, 8);
  EXPECT_EQ(fit.frames, 8);
  for (const OutlineRow& row : {paper, fit, paper_bar, fit_bar}) {
    EXPECT_GE(row.dice, 0) << r.out;
    EXPECT_LE(row.dice, 1) << r.out;
  }
  EXPECT_LT(fit.centroid_mm, 3.0) << r.out;
  EXPECT_LT(paper.dice, 0.3) << r.out;
  EXPECT_LT(paper_bar.dice, fit_bar.dice) << r.out;
  for (const char* family :
       {"bar 20x6", "ellipse 24x12", "ring 12-18", "disc r12", "L 20x4", "two bars 20x3", "stylus r2"})
    EXPECT_NE(r.out.find(std::string("\n  ") + family + " "), std::string::npos) << family << "\n" << r.out;
}

/// The `area` ratio and the two coverage cells ("60/100 %" or "-") at the end of a family's row of
/// `method`'s block in `emit eval --outlines`/`--indenters`' table; false if not found.
struct CoverageRow {
  double force_error = -1, area_ratio = -1;
  std::string area, force;  ///< "A1/A2 %", "-"
};
bool read_coverage_row(const std::string& text, const std::string& method, const std::string& family,
                       CoverageRow& row) {
  const std::size_t block = text.find("\n  " + method + " (");
  if (block == std::string::npos) return false;
  const std::size_t at = text.find("\n  " + family + " ", block);
  if (at == std::string::npos) return false;
  const std::string line = text.substr(at + 3, text.find('\n', at + 3) - at - 3);
  std::istringstream in(line.substr(family.size()));
  std::vector<std::string> fields;
  for (std::string f; in >> f;) fields.push_back(f);
  // frames Dice err % xF centroid mm orient. [deg] regions right % xA cov [%] cov [%]
  if (fields.size() < 12) return false;
  row.force_error = std::strtod(fields[2].c_str(), nullptr);
  std::size_t i = fields.size();
  const auto take = [&] {  // a coverage cell from the end: "-" or "a/b" "%"
    if (fields[i - 1] == "-") return fields[--i];
    i -= 2;
    return fields[i];
  };
  row.force = take();
  row.area = take();
  row.area_ratio = std::strtod(fields[i - 1].c_str() + 1, nullptr);  // "x6.25"
  return true;
}

/// The two fractions of a coverage cell "a/b", in %.
std::pair<double, double> coverage_of(const std::string& cell) {
  const std::size_t slash = cell.find('/');
  if (slash == std::string::npos) return {-1, -1};
  return {std::strtod(cell.c_str(), nullptr), std::strtod(cell.c_str() + slash + 1, nullptr)};
}

// emit eval --indenters --quick for the contact shapes, calibrated on 5 mm discs (issue 31's
// indenter targets): a 2 mm disc's area is held at the calibration's 78.5 mm2 (x6.25) unless
// declared, so its force is 6.25^(1 + 1/gamma) = +36 % off (gamma -1.2), inside the prior's 2
// sigma; declared (--contact-radius-mm 2), its area is the true one and its force within the
// target's 15 % (measured 6.5 %: the contact law's own error at another size). Every disc's
// area lies within the undeclared prior's 2 sigma (radii 1.66-15 mm about 5).
TEST(Cli, EvalIndentersCoversAreaAndForceAndADeclaredRadiusHelps) {
  const auto r = run_emit("eval --indenters --quick --methods shapes");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  CoverageRow held, declared, all;
  ASSERT_TRUE(read_coverage_row(r.out, "shapes", "disc r2", held)) << r.out;
  ASSERT_TRUE(read_coverage_row(r.out, "shapes, declared", "disc r2", declared)) << r.out;
  ASSERT_TRUE(read_coverage_row(r.out, "shapes", "all", all)) << r.out;
  EXPECT_NEAR(held.area_ratio, 6.25, 0.01) << r.out;
  EXPECT_NEAR(held.force_error, 36, 8) << r.out;
  EXPECT_NEAR(declared.area_ratio, 1.0, 0.01) << r.out;
  EXPECT_LT(declared.force_error, 15) << r.out;
  EXPECT_EQ(coverage_of(all.area).second, 100) << r.out;
  EXPECT_EQ(coverage_of(all.force).second, 100) << r.out;
}

// A disconnected electrode: a one-line warning, its measurements left out, contacts still found.
TEST(Cli, ReconstructLeavesOutADeadElectrode) {
  const std::string d = test::temp_folder("cli_dead");
  ASSERT_EQ(run_emit("simulate --script none --frames 3 --out " + d + "/ref.csv").exit_code, 0);
  ASSERT_EQ(run_emit("simulate --script grid --spacing-mm 20 --dead-electrode 9 --out " + d + "/f.csv").exit_code, 0);
  const auto r = run_emit("reconstruct --reference " + d + "/ref.csv --frames " + d + "/f.csv --contacts " + d +
                          "/c.jsonl --no-cache");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("emit: warning: electrode 9 reads 0 V as the sensed electrode"), std::string::npos) << r.err;
  EXPECT_EQ(occurrences(test::read_text(d + "/c.jsonl"), "\"frame\""), 9);
}

// A board's glitches in a frames file: `nan` for a dropped reading, a value at the ADC's top code
// (3.3 V: clipped), a grounding that failed for one frame (its row at full scale). Masked: one line
// counts them, and each frame's press is where the clean file's is (a tenth of the paper method's
// 3.3 mm error on this sheet); before, the row stopped the run ("was electrode 7 grounded?").
TEST(Cli, ReconstructMasksDroppedAndClippedReadings) {
  const std::string d = test::temp_folder("cli_masked");
  ASSERT_EQ(run_emit("simulate --script none --frames 3 --out " + d + "/ref.csv").exit_code, 0);
  ASSERT_EQ(run_emit("simulate --press 34,24,5,10 --out " + d + "/f.csv").exit_code, 0);
  std::string line = test::read_text(d + "/f.csv");
  line = line.substr(0, line.find('\n'));
  std::vector<std::string> values;
  std::istringstream fields(line);
  for (std::string v; std::getline(fields, v, ',');) values.push_back(v);
  ASSERT_EQ(values.size(), 256u);
  const auto glitched = [&](const std::vector<std::pair<int, std::string>>& changes) {
    std::vector<std::string> copy = values;
    for (const auto& [index, value] : changes) copy[static_cast<std::size_t>(index)] = value;
    std::string out;
    for (const std::string& v : copy) out += (out.empty() ? "" : ",") + v;
    return out + "\n";
  };
  std::vector<std::pair<int, std::string>> row;
  for (int m = 0; m < 16; ++m)
    if (m != 7) row.emplace_back(7 * 16 + m, "3.3");
  {
    std::ofstream clean(d + "/clean.csv"), bad(d + "/bad.csv");
    clean << line << "\n" << line << "\n" << line << "\n";
    bad << glitched({{2 * 16 + 9, "nan"}, {11 * 16 + 4, "NaN"}}) << glitched({{5 * 16 + 6, "3.3"}}) << glitched(row);
  }
  const std::string common = " --reference " + d + "/ref.csv --method paper --no-cache --contacts ";
  const auto c = run_emit("reconstruct --frames " + d + "/clean.csv" + common + d + "/clean.jsonl");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_EQ(c.out.find("readings:"), std::string::npos) << c.out;
  const auto r = run_emit("reconstruct --frames " + d + "/bad.csv" + common + d + "/bad.jsonl");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("readings: 18 masked in 3 of 3 frames"), std::string::npos) << r.out;
  const auto clean = read_contacts_file(d + "/clean.jsonl"), bad = read_contacts_file(d + "/bad.jsonl");
  ASSERT_EQ(clean.size(), 3u);
  ASSERT_EQ(bad.size(), 3u);
  for (std::size_t f = 0; f < 3; ++f) {
    ASSERT_EQ(clean[f].size(), 1u);
    ASSERT_EQ(bad[f].size(), 1u) << "frame " << f;
    EXPECT_LT(std::hypot(bad[f][0].x_mm - clean[f][0].x_mm, bad[f][0].y_mm - clean[f][0].y_mm), 0.33) << "frame " << f;
  }
}

TEST(Cli, MeshWritesAFileAndReportsQuality) {
  const std::string dir = test::temp_folder("cli_mesh");
  const auto r =
      run_emit("mesh --sensor " + source_path("examples/sensors/circle40.json") + " --out " + dir + "/c.msh");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("triangles"), std::string::npos);
  EXPECT_NE(r.out.find("min angle"), std::string::npos);
  EXPECT_EQ(read_msh(dir + "/c.msh").electrode_count(), 16);
}

// `emit bench` times each stage in a process of its own: one row per case, the mesh sized as
// asked, the operator's rank that of a truncated R (below M), the stages adding up to the frame.
TEST(Cli, BenchPrintsARowPerCase) {
  // Under AddressSanitizer (the test build) the peak would also hold ASan's quarantine of freed
  // blocks, 256 MiB by default, which is not emit's memory: the bench runs with a 16 MiB one
  // (measured at 3k: 347 MiB with the default, 133 MiB with 16, 35 MiB in a Release build).
  const auto r = run_emit("bench --sizes 3k --electrodes 16 --no-baselines",
                          "ASAN_OPTIONS=\"$ASAN_OPTIONS:quarantine_size_mb=16\"");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string row = last_line_of(r.out);
  long triangles = 0;
  int electrodes = 0, rank = 0;
  double mesh_s, assembly_s, factor_s, jacobian_s, operator_s, offline_s, load_ms, product_us, pressure_us, contacts_us,
      frame_us, read_us, peak_MiB;
  // NOLINTNEXTLINE(cert-err34-c): emit's own output, the field count checks its shape
  ASSERT_EQ(std::sscanf(row.c_str(), "%ld %d %d | %lf %lf %lf %lf %lf %lf %lf | %lf %lf %lf %lf %lf | %lf", &triangles,
                        &electrodes, &rank, &mesh_s, &assembly_s, &factor_s, &jacobian_s, &operator_s, &offline_s,
                        &load_ms, &product_us, &pressure_us, &contacts_us, &frame_us, &read_us, &peak_MiB),
            16)
      << row;
  // The correction aims at 5 %, but counts come in steps (the frontal mesher's layers: 2840, then
  // 3228 on the default sensor near 3k), so the closest can be a step away: 8 % holds both.
  EXPECT_NEAR(static_cast<double>(triangles), 3000.0, 0.08 * 3000);
  EXPECT_EQ(electrodes, 16);
  EXPECT_GT(rank, 0);
  EXPECT_LT(rank, 240);
  EXPECT_NEAR(offline_s, mesh_s + jacobian_s + operator_s, 0.002);  // rounding of three printed figures
  // The times themselves are the benchmark's to judge, not a test's; here only that each was taken.
  for (double us : {product_us, pressure_us, contacts_us, frame_us, read_us}) EXPECT_GT(us, 0.0);
  // A 3k-triangle case holds a few MB of matrices; the process's peak includes Gmsh and the libraries.
  EXPECT_LT(peak_MiB, 300.0);
}

// `emit bench` on a current-injection skin times its own job (the complete electrode model, the
// relative Jacobian, NOSER): one row, its 16 electrodes, a rank at most the 120 independent readings.
TEST(Cli, BenchTimesACurrentInjectionSkin) {
  const auto r = run_emit("bench --sensor " + test::source_path("examples/sensors/hydrogel_hardman.json") +
                              " --sizes 2k --no-baselines",
                          "ASAN_OPTIONS=\"$ASAN_OPTIONS:quarantine_size_mb=16\"");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("current-injection EIT difference imaging"), std::string::npos) << r.out;
  long triangles = 0;
  int electrodes = 0, rank = 0;
  // NOLINTNEXTLINE(cert-err34-c): emit's own output, the field count checks its shape
  ASSERT_EQ(std::sscanf(last_line_of(r.out).c_str(), "%ld %d %d", &triangles, &electrodes, &rank), 3) << r.out;
  EXPECT_EQ(electrodes, 16);
  EXPECT_GT(rank, 0);
  EXPECT_LE(rank, 120);
}

// A sensor whose shape is a mesh file written by `emit mesh` simulates like the original.
TEST(Cli, MeshFileSensor) {
  const std::string dir = test::temp_folder("cli_mesh_sensor");
  ASSERT_EQ(run_emit("mesh --element-size-mm 2 --out " + dir + "/sheet.msh").exit_code, 0);
  std::ofstream(dir + "/sensor.json") << R"({"shape": {"type": "mesh", "file": "sheet.msh"}})";
  const auto r =
      run_emit("simulate --sensor " + dir + "/sensor.json --press 30,30,5,10 --exact --out " + dir + "/f.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_frames_csv(dir + "/f.csv", 16).size(), 1u);
}

TEST(Cli, DemoWritesFramesAndPicturesThenGoesLive) {
  const std::string dir = test::temp_folder("cli_demo");
  const auto r = run_emit("demo --out " + dir + "/demo --serve 127.0.0.1:0 --seconds 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The live part: the viewer's address, and the frames it reconstructed, written and recorded.
  EXPECT_NE(r.out.find("viewer: http://127.0.0.1:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("latency mean"), std::string::npos) << r.out;
  EXPECT_FALSE(test::read_text(dir + "/demo/live_contacts.jsonl").empty());
  EXPECT_TRUE(std::filesystem::exists(dir + "/demo/live.emitrec"));
  EXPECT_EQ(read_frames_csv(dir + "/demo/frames.csv", 16).size(), 4u);
  for (int f = 0; f < 4; ++f)
    EXPECT_GT(read_png(dir + "/demo/" + frame_image_name(static_cast<std::size_t>(f))).height(), 100);
  // It found every press, two fingers included, within the target (p95 0.6 mm).
  const PressSequence truth = read_presses_csv(dir + "/demo/presses.csv");
  std::istringstream lines(test::read_text(dir + "/demo/contacts.jsonl"));
  std::string line;
  for (std::size_t f = 0; std::getline(lines, line); ++f) {
    long frame = -1;
    const auto contacts = parse_contacts_line(line, &frame);
    ASSERT_LT(f, truth.size());
    EXPECT_EQ(contacts.size(), truth[f].size()) << "frame " << f;
    for (const Press& p : truth[f]) {
      double nearest = 1e9;
      for (const Contact& c : contacts) nearest = std::min(nearest, std::hypot(c.x_mm - p.x_mm, c.y_mm - p.y_mm));
      EXPECT_LT(nearest, 0.6) << "frame " << f << ", press at " << p.x_mm << ", " << p.y_mm;
    }
  }
}

// A live session recorded, then replayed from the file as fast as it goes: the baseline's 10
// capture frames and the 20 reconstructed ones are all in the recording, and the replay finds the
// press where the simulator held it (live_loop_test's 0.5 mm), ending by itself at the file's end.
TEST(Cli, LiveRecordsAndReplaysAFile) {
  const std::string d = test::temp_folder("cli_live_record");
  auto r = run_emit("live --source sim:fixed:20,40 --frames 20 --fps 0 --record " + d + "/r.emitrec --cache " + d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("recorded 30 frames"), std::string::npos) << r.out;
  r = run_emit("live --source file:" + d + "/r.emitrec --fps 0 --contacts " + d + "/c.jsonl --cache " + d +
               " --record " + d + "/again.emitrec");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("live: 20 frames"), std::string::npos) << r.out;
  // The replay recorded again holds the packets it read, byte for byte (recorded what the board
  // sent, not volts quantised again); only the header's start time differs.
  const std::string first = test::read_text(d + "/r.emitrec"), again = test::read_text(d + "/again.emitrec");
  ASSERT_EQ(first.size(), again.size());
  EXPECT_EQ(first.substr(0, 24), again.substr(0, 24));
  EXPECT_TRUE(first.substr(32) == again.substr(32)) << "the packets differ";
  std::istringstream lines(test::read_text(d + "/c.jsonl"));
  std::string line;
  int pressed = 0;
  while (std::getline(lines, line))
    for (const Contact& c : parse_contacts_line(line)) {
      EXPECT_LT(std::hypot(c.x_mm - 20, c.y_mm - 40), 0.5) << line;
      ++pressed;
    }
  EXPECT_GE(pressed, 10);  // the script holds the press from its 16th frame on (frames 15..29)
}

// A press held and lifted, as a user's traces: the CSV of tracks has one row per pressed frame, all of
// one touch (one id), "down" first then "move"; the JSON Lines carry the same id and the frame's
// frame's board time and host receive time.
TEST(Cli, LiveWritesTracksAsCsv) {
  const std::string d = test::temp_folder("cli_tracks");
  auto r = run_emit("live --source sim:fixed:20,40 --frames 20 --fps 0 --method paper --tracks " + d +
                    "/t.csv --contacts " + d + "/c.jsonl --cache " + d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream rows(test::read_text(d + "/t.csv"));
  std::string row;
  ASSERT_TRUE(std::getline(rows, row));
  EXPECT_EQ(row, "time_s,frame,id,phase,x_mm,y_mm,z_mm,force_N,area_mm2,pressure_N_per_mm2,vx_mm_per_s,vy_mm_per_s");
  int count = 0;
  std::set<std::string> ids;
  while (std::getline(rows, row)) {
    std::vector<std::string> cells;
    for (std::istringstream cells_of(row); std::getline(cells_of, cells.emplace_back(), ',');) {
    }
    cells.pop_back();
    ASSERT_EQ(cells.size(), 12u) << row;
    ids.insert(cells[2]);
    EXPECT_EQ(cells[3], count == 0 ? "down" : "move") << row;
    EXPECT_LT(std::hypot(std::stod(cells[4]) - 20, std::stod(cells[5]) - 40), 8.05) << row;  // paper's p95
    ++count;
  }
  EXPECT_EQ(count, 15);  // the twin presses from its 16th frame on (frames 15..29 of 10..29)
  EXPECT_EQ(ids.size(), 1u);
  std::istringstream lines(test::read_text(d + "/c.jsonl"));
  for (std::string line; std::getline(lines, line);) {
    const ContactsLine read = parse_contacts_record(line);
    EXPECT_GE(read.times.board_s, 0);
    EXPECT_GT(read.times.host_unix_s, 1.7e9);  // a Unix time of this century
    for (const Contact& c : read.contacts) EXPECT_EQ(std::to_string(c.id), *ids.begin());
  }
}

// A 20-frame recording replayed in a loop for 100 frames: five passes and more, the contacts'
// "frame" counting on by one from the first reconstructed frame (10, after the baseline's capture)
// to the last, no gap at the seams; the twin cannot loop.
TEST(Cli, LiveLoopsARecordingWithFrameNumbersGoingOn) {
  const std::string d = test::temp_folder("cli_live_loop");
  auto r = run_emit("live --source sim:fixed:20,40 --frames 10 --fps 0 --method paper --record " + d +
                    "/r.emitrec --cache " + d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_emit("live --source file:" + d + "/r.emitrec --loop --fps 0 --frames 100 --method paper --contacts " + d +
               "/c.jsonl --cache " + d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("(20 frames, as fast as possible, in a loop)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("live: 100 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("; 0 missed"), std::string::npos) << r.out;
  // Each stage's time per frame, and the one that sets the rate: a recording read as fast as it
  // goes makes nothing on a thread of its own.
  EXPECT_NE(r.out.find("time per frame: source "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("made in"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("; the bottleneck: "), std::string::npos) << r.out;
  std::istringstream lines(test::read_text(d + "/c.jsonl"));
  std::string line;
  long expected = 10, frame = -1;
  for (; std::getline(lines, line); ++expected) {
    parse_contacts_line(line, &frame);
    ASSERT_EQ(frame, expected) << line;
  }
  EXPECT_EQ(expected, 110);
  r = run_emit("live --source sim --loop --frames 1 --cache " + d);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("only a recording (file:PATH) can be replayed in a loop"), std::string::npos) << r.err;
}

// emit live on the simulator holding one press: one JSON line per reconstructed frame (the
// baseline's 10 capture frames write none), numbered by the source; no contact while the script
// leaves the sheet untouched (its first 15 frames), then one within live_loop_test's 0.5 mm.
TEST(Cli, LiveWritesTheScriptedPressAsJsonLines) {
  const std::string d = test::temp_folder("cli_live");
  const auto r =
      run_emit("live --source sim:fixed:20,40 --frames 20 --fps 0 --contacts " + d + "/c.jsonl --cache " + d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("live: 20 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("latency mean"), std::string::npos) << r.out;
  std::istringstream lines(test::read_text(d + "/c.jsonl"));
  std::string line;
  long count = 0, frame = -1;
  for (; std::getline(lines, line); ++count) {
    const auto contacts = parse_contacts_line(line, &frame);
    EXPECT_EQ(frame, 10 + count);
    if (frame < 15) {
      EXPECT_TRUE(contacts.empty()) << line;
    } else {
      ASSERT_EQ(contacts.size(), 1u) << line;
      EXPECT_LT(std::hypot(contacts[0].x_mm - 20, contacts[0].y_mm - 40), 0.5) << line;
    }
  }
  EXPECT_EQ(count, 20);
}

// Bad input: one line on stderr that starts with "emit: ", a non-zero exit, and the output
// file — here one that already holds good data — left exactly as it was.
struct BadRun {
  const char* what;
  std::string arguments;  // OUT stands for the output file
  const char* message_contains;
};

void PrintTo(const BadRun& run, std::ostream* os) { *os << run.what; }

class CliBadInput : public ::testing::TestWithParam<BadRun> {};

TEST_P(CliBadInput, OneLineErrorAndNothingOverwritten) {
  const std::string dir = test::temp_folder("cli_bad");
  const std::string out = dir + "/out.csv";
  std::ofstream(out) << "GOOD\n";
  std::ofstream(dir + "/unknown_key.json")
      << R"({"shape": {"type": "circle", "radius_mm": 20}, "electrodes": {"count": 8, "width_mm": 2}, "colour": 1})";
  std::ofstream(dir + "/bad.msh") << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\ngarbage\n";
  std::ofstream(dir + "/msh_sensor.json") << R"({"shape": {"type": "mesh", "file": "bad.msh"}})";
  auto csv_row = [](int count, const std::string& special, int at) {
    std::string row;
    for (int i = 0; i < count; ++i) row += (i ? "," : "") + (i == at ? special : std::string("0.1"));
    return row + "\n";
  };
  std::ofstream(dir + "/ref.csv") << csv_row(256, "0", -1);
  std::ofstream(dir + "/text.csv") << csv_row(256, "volts", 3);
  std::ofstream(dir + "/short.csv") << csv_row(255, "0", -1);
  std::ofstream(dir + "/ref8.csv") << csv_row(64, "0", -1);
  // Inputs emit once mishandled (docs/bad-input.md says what it does now).
  std::ofstream(dir + "/selfx.json")
      << R"({"shape":{"type":"polygon","points_mm":[[0,0],[60,0],[60,60],[30,-20],[0,60]]},"electrodes":{"count":8,"width_mm":3}})";
  std::ofstream(dir + "/huge.json")
      << R"({"shape":{"type":"rectangle","width_mm":100000,"height_mm":100000},"electrodes":{"count":16,"width_mm":3}})";
  std::ofstream(dir + "/wide.json")
      << R"({"shape":{"type":"rectangle","width_mm":60,"height_mm":60},"electrodes":{"count":16,"width_mm":1e300}})";
  std::ofstream(dir + "/empty.csv") << "";
  std::ofstream(dir + "/semicolons.csv") << std::string(4096, ';') << "\n";
  std::ofstream(dir + "/millivolts.csv") << csv_row(256, "1200", 5);
  std::ofstream(dir + "/truth.csv") << "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2\n0,30,30,5,10,0.127,1\n";
  std::ofstream(dir + "/pairs.csv") << "pressure_N_per_mm2,resistance_ohm\n0.1,2000\n0.2,-5\n";
  std::ofstream(dir + "/a_file") << "not a folder";
  // Sheets' files emit once handed to Gmsh unchecked, and descriptions it once took too long over.
  const std::string stl_electrodes =
      R"("electrodes":[{"at_mm":[1,0,0],"width_mm":0.5},{"at_mm":[2,1,0],"width_mm":0.5},{"at_mm":[1,2,0],"width_mm":0.5}])";
  std::ofstream(dir + "/nan.stl") << "solid s\nfacet normal 0 0 1\nouter loop\nvertex nan 0 0\nvertex 2 0 0\n"
                                     "vertex 2 2 0\nendloop\nendfacet\nendsolid s\n";
  std::ofstream(dir + "/nan_stl.json") << R"({"shape":{"type":"mesh","file":"nan.stl"},)" << stl_electrodes << "}";
  {
    std::ofstream big(dir + "/big.stl", std::ios::binary);
    big << std::string(80, ' ');
    const std::uint32_t count = 1200000;
    big.write(reinterpret_cast<const char*>(&count), 4);
  }
  std::filesystem::resize_file(dir + "/big.stl", 84 + 50 * 1200000UL);  // sparse: nothing but the header
  std::ofstream(dir + "/big_stl.json") << R"({"shape":{"type":"mesh","file":"big.stl"},)" << stl_electrodes << "}";
  std::ofstream(dir + "/grid.msh") << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n"
                                      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n$Elements\n1 2 1 2\n2 1 2 2\n"
                                      "1 1 2 3\n2 1 3 4\n$EndElements\n";
  std::ofstream(dir + "/grid_msh.json") << R"({"shape":{"type":"mesh","file":"grid.msh"}})";
  std::ofstream(dir + "/dome1000.json")
      << R"({"name":"dome","shape":{"type":"spherical_cap","sphere_radius_mm":25,"base_radius_mm":20},)"
      << R"("electrodes":{"count":1000,"width_mm":0.1},"mesh":{"element_size_mm":0.9}})";
  std::ofstream(dir + "/long_name.json") << R"({"shape":{"type":"mesh","file":")" << std::string(5000, 'a')
                                         << R"(.step"},"electrodes":[{"at_mm":[0,0,0]},{"at_mm":[1,0,0]}]})";
  std::ofstream(dir + "/dome.json")
      << R"({"shape": {"type": "spherical_cap", "sphere_radius_mm": 25, "base_radius_mm": 20}, "electrodes": {"count": 16, "width_mm": 3}})";
  std::ofstream(dir + "/obj.json")
      << R"({"shape":{"type":"mesh","file":"sheet.obj"},"electrodes":[{"at_mm":[0,0,0]}]})";
  std::ofstream(dir + "/closed.json")
      << R"({"shape":{"type":"mesh","file":")" << test::source_path("tests/data/cad/closed_sphere.step")
      << R"("},"electrodes":[{"at_mm":[10,0,0]},{"at_mm":[0,10,0]},{"at_mm":[-10,0,0]}]})";
  const auto with_paths = [&](std::string text) {
    for (auto [from, to] : {std::pair<std::string, std::string>{"OUT", out}, {"DIR", dir}})
      for (std::size_t at; (at = text.find(from)) != std::string::npos;) text.replace(at, from.size(), to);
    return text;
  };
  const std::string arguments = with_paths(GetParam().arguments);
  const auto r = run_emit(arguments);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(r.exit_code == 1 || r.exit_code == 2) << "1: bad input, 2: bad command line; got " << r.exit_code;
  // Progress lines may come first; the error is the last line and the only one saying "emit: ".
  const std::string last_line = last_line_of(r.err);
  EXPECT_EQ(last_line.rfind("emit: ", 0), 0u) << r.err;
  EXPECT_EQ(occurrences(r.err, "emit: "), 1) << r.err;
  EXPECT_NE(last_line.find(with_paths(GetParam().message_contains)), std::string::npos) << r.err;
  EXPECT_EQ(test::read_text(out), "GOOD\n");
  EXPECT_FALSE(fs::exists(dir + "/out_presses.csv"));
}

INSTANTIATE_TEST_SUITE_P(
    Errors, CliBadInput,
    ::testing::Values(
        BadRun{"missing sensor file", "simulate --sensor DIR/none.json --press 30,30,5,10 --out OUT", "none.json"},
        BadRun{"unknown key", "simulate --sensor DIR/unknown_key.json --press 20,20,5,10 --out OUT",
               "colour: unknown key"},
        BadRun{"press off the sheet", "simulate --press 70,30,5,10 --out OUT", "off the sheet"},
        BadRun{"press not numbers", "simulate --press 30,thirty,5,10 --out OUT", "\"thirty\" is not a number"},
        BadRun{"negative force", "simulate --press 30,30,5,-1 --out OUT", "force must not be negative"},
        BadRun{"malformed msh", "simulate --sensor DIR/msh_sensor.json --press 30,30,5,10 --out OUT", "bad.msh"},
        BadRun{"missing msh", "mesh --sensor DIR/none.json --out OUT", "none.json"},
        BadRun{"unknown script", "simulate --script zigzag --out OUT", "unknown script"},
        BadRun{"realistic size without realistic", "simulate --realistic-field 0.1 --press 30,30,5,10 --out OUT",
               "--realistic-field requires --realistic"},
        BadRun{"realistic seed not a number", "simulate --realistic abc --press 30,30,5,10 --out OUT",
               "--realistic: the seed must be a whole number 0 or larger, got \"abc\""},
        BadRun{"realistic field too large", "simulate --realistic --realistic-field 1.5 --press 30,30,5,10 --out OUT",
               "--realistic-field: must be a fraction from 0 up to (not including) 1, got \"1.5\""},
        BadRun{"realistic series negative",
               "simulate --realistic --realistic-series-ohm -3 --press 30,30,5,10 --out OUT",
               "--realistic-series-ohm: must be a number 0 or larger, got \"-3\""},
        BadRun{"realistic drive reversed",
               "simulate --realistic --realistic-drive-V 3.3,3.0 --press 30,30,5,10 --out OUT",
               "--realistic-drive-V: give LOW,HIGH volts with 0 < LOW <= HIGH"},
        BadRun{"unknown profile", "simulate --profile round --press 30,30,5,10 --out OUT", "--profile: round"},
        BadRun{"unknown outline", "simulate --press star:30,30,5,10 --out OUT", "\"star\" is not an outline"},
        BadRun{"outline on a dome", "simulate --sensor DIR/dome.json --press bar:0,0,10,4,0,5 --out OUT",
               "an outline press needs a flat sheet"},
        BadRun{"spherical outline", "simulate --profile spherical --press bar:30,30,10,4,0,5 --out OUT",
               "an outline press must be flat"},
        BadRun{"realistic eval seed negative", "eval --realistic -1 --quick",
               "--realistic: the seed must be a whole number 0 or larger, got \"-1\""},
        BadRun{"realistic eval seed not a number", "eval --realistic x --quick",
               "--realistic: the seed must be a whole number 0 or larger, got \"x\""},
        BadRun{"realistic eval on no sheet", "eval --realistic --sheet 45 --quick",
               "--sheet \"45\": no sheet's name begins with it (60, 30, circle, 120, dome, sleeve, fingertip)"},
        BadRun{"frame id tf2 refuses", "live --source sim --frames 1 --frame-id /palm --mcap OUT",
               "--frame-id \"/palm\": a frame id is letters, digits, _ and /, not starting with / (as tf2 takes it)"},
        BadRun{"calibration presses with neither data set", "eval --calibration-presses 8 --quick",
               "--calibration-presses: give it with --real or --realistic"},
        BadRun{"too few presses to calibrate a realistic sheet", "eval --realistic --calibration-presses 7 --quick",
               "--calibration-presses: a sheet's calibration takes 8 presses or more, got 7"},
        BadRun{"eval on no sheet", "eval --sheet 45 --quick",
               "--sheet \"45\": no sheet's name begins with it (60, 30, circle, 120, dome, sleeve, fingertip)"},
        BadRun{"fingers that do not fit", "simulate --script four-finger --separation-mm 55 --frames 1 --out OUT",
               "no room on the sheet for 4 presses 55 mm apart"},
        BadRun{"output folder missing", "simulate --press 30,30,5,10 --out DIR/no/such/folder.csv", "does not exist"},
        BadRun{"unknown option", "simulate --pres 30,30,5,10 --out OUT", "--pres"},
        BadRun{"text in a frame", "reconstruct --reference DIR/ref.csv --frames DIR/text.csv --contacts OUT --no-cache",
               "text.csv:1: value 4 \"volts\" is not a number"},
        BadRun{"wrong value count",
               "reconstruct --reference DIR/ref.csv --frames DIR/short.csv --contacts OUT --no-cache",
               "short.csv:1: 255 values, expected 256"},
        BadRun{"reference from another sensor",
               "reconstruct --reference DIR/ref8.csv --frames DIR/ref.csv --contacts OUT --no-cache",
               "ref8.csv:1: 64 values, expected 256"},
        BadRun{"calibrate without truth", "calibrate --reference DIR/ref.csv --frames DIR/ref.csv --out OUT",
               "needs --reference, --frames, --truth and --out"},
        BadRun{"bench size not a count", "bench --sizes 6kk", "--sizes: \"6kk\" is not a triangle count"},
        BadRun{"no threads", "--threads 0 mesh --out OUT",
               "--threads: must be a whole number from 1 to 256 (threads beyond the cores only cost memory), got "
               "\"0\""},
        // Runs that used to lose data.
        BadRun{"contacts over the frames", "reconstruct --reference DIR/ref.csv --frames OUT --contacts OUT --no-cache",
               "is the same file as --frames"},
        BadRun{"truth over the frames", "simulate --script none --frames 2 --out OUT --truth OUT",
               "--out and --truth are the same file"},
        BadRun{"calibration over the truth",
               "calibrate --reference DIR/ref.csv --frames DIR/ref.csv --truth OUT --out OUT",
               "--out OUT is the same file as --truth OUT"},
        BadRun{"recording over itself", "live --source file:OUT --contacts OUT --fps 0",
               "is the same file as --source"},
        BadRun{"empty frames file",
               "reconstruct --reference DIR/ref.csv --frames DIR/empty.csv --contacts OUT --no-cache",
               "empty.csv: no frames"},
        BadRun{"empty reference",
               "reconstruct --reference DIR/empty.csv --frames DIR/ref.csv --contacts OUT --no-cache",
               "empty.csv: no frames"},
        // Crashes and runaway resources.
        BadRun{"self-intersecting polygon", "mesh --sensor DIR/selfx.json --out OUT", "must not cross or touch itself"},
        BadRun{"self-intersecting polygon simulated", "simulate --sensor DIR/selfx.json --press 30,30,5,10 --out OUT",
               "must not cross or touch itself"},
        BadRun{"tiny elements", "mesh --element-size-mm 1e-6 --out OUT", "beyond the limit of 1e+06"},
        BadRun{"a 100 m sheet", "simulate --sensor DIR/huge.json --press 30,30,5,10 --out OUT", "beyond the limit"},
        BadRun{"threads beyond the limit", "--threads 1000000000 mesh --out OUT",
               "--threads: must be a whole number from 1 to 256 (threads beyond the cores only cost memory), got "
               "\"1000000000\""},
        BadRun{"threads beyond an int", "--threads 99999999999 mesh --out OUT",
               "--threads: must be a whole number from 1 to 256 (threads beyond the cores only cost memory), got "
               "\"99999999999\""},
        BadRun{"frames beyond memory", "simulate --script none --frames 1000000000 --out OUT",
               "--frames 1000000000: 1000000000 frames of 16 electrodes, beyond the 131072 a run holds in memory (256 "
               "MiB of readings); simulate them in several runs (--seed)"},
        BadRun{"grid beyond memory", "simulate --script grid --spacing-mm 0.0078125 --out OUT",
               "--spacing-mm 0.0078125 (a grid over the sheet): 58997761 frames of 16 electrodes, beyond the 131072 a "
               "run holds in memory (256 MiB of readings); give a larger spacing"},
        BadRun{"bench size not finite", "bench --sizes inf", "--sizes: \"inf\" is not a triangle count"},
        BadRun{"bench size beyond the mesh limit", "bench --sizes 1.5k,2000k",
               "--sizes 2000000: a triangle count must be from 1 to the sensor's mesh.max_triangles, 1e+06"},
        BadRun{"curve beyond any folder", "eval --real DIR --sensor DIR/none.json --curve 20,99999999999999999999",
               "--curve: give numbers or none; each must be a whole number of presses from 1 to 134217728 (the most a "
               "folder holds), got \"99999999999999999999\""},
        BadRun{"plots over a file", "eval --sheet 30 --quick --plots DIR/a_file",
               "--plots DIR/a_file: cannot create the folder"},
        BadRun{"NaN corner in an STL", "mesh --sensor DIR/nan_stl.json --out OUT",
               "nan.stl\": triangle 0 (line 2): corner 0 is (nan, 0, 0), not finite numbers"},
        BadRun{"STL of 1.2 M triangles", "mesh --sensor DIR/big_stl.json --out OUT",
               "big.stl\": a binary STL of 1200000 triangles (its header says), beyond the limit of 1e+06 triangles"},
        BadRun{"msh beyond max triangles", "mesh --sensor DIR/grid_msh.json --max-triangles 1 --out OUT",
               "grid.msh\": line 18, $Elements: 2 triangles or more (an element block's header), beyond the limit of 1 "
               "triangles"},
        BadRun{"1000 electrodes on a dome", "mesh --sensor DIR/dome1000.json --out OUT",
               "beyond the limit of 1e+06 triangles: use fewer or wider-spaced electrodes, or fewer polygon points"},
        BadRun{"a CAD file name of 5000 characters", "mesh --sensor DIR/long_name.json --out OUT",
               "\": the CAD file's name is too long for the file system (5"},
        BadRun{"an obj sheet", "mesh --sensor DIR/obj.json --out OUT",
               "shape.file: \"sheet.obj\" is a \".obj\" file: a sheet's file is a Gmsh mesh (.msh), an STL surface "
               "(.stl) or CAD (.step, .stp, .iges, .igs)"},
        BadRun{"a closed STEP solid", "mesh --sensor DIR/closed.json --out OUT",
               "closed_sphere.step\": the CAD surface is closed"},
        BadRun{"frames from dev zero",
               "reconstruct --reference DIR/ref.csv --frames /dev/zero --contacts OUT --no-cache",
               "/dev/zero:1: line longer than 1024 KiB"},
        // Accepted without a word before.
        BadRun{"millivolts",
               "reconstruct --reference DIR/ref.csv --frames DIR/millivolts.csv --contacts OUT --no-cache",
               "millivolts.csv:1: ground 0, sense 5 reads 1200 V, outside the ADC's 0 to 3.3 V"},
        BadRun{"dead electrode beyond the sensor", "simulate --press 30,30,5,10 --dead-electrode 99 --out OUT",
               "--dead-electrode 99: the sensor has 16 electrodes, 0 to 15"},
        BadRun{"truth with an extra column",
               "calibrate --reference DIR/ref.csv --frames DIR/ref.csv --truth DIR/truth.csv --out OUT",
               "truth.csv:2: expected frame,x_mm,y_mm,radius_mm,force_N[,pressure_N_per_mm2], got"},
        // Poor messages before.
        BadRun{"misspelled command", "reconstuct --frames x",
               "unknown command \"reconstuct\" (did you mean \"reconstruct\"?)"},
        BadRun{"negative lambda",
               "reconstruct --reference DIR/ref.csv --frames DIR/ref.csv --contacts OUT --lambda2 -1",
               "--lambda2: must be 0 (the method's) or positive, got -1"},
        BadRun{"negative contact radius",
               "reconstruct --reference DIR/ref.csv --frames DIR/ref.csv --contacts OUT --contact-radius-mm -3",
               "--contact-radius-mm: must be 0 or more, got -3"},
        BadRun{"zero tracking gate",
               "reconstruct --reference DIR/ref.csv --frames DIR/ref.csv --contacts OUT --track-gate-mm 0",
               "--track-gate-mm: must be positive, got 0"},
        BadRun{"negative coast frames", "live --source sim --frames 1 --track-coast-frames -1",
               "--track-coast-frames: must be a whole number 0 or larger, got \"-1\""},
        BadRun{"contact radius for a linear method",
               "reconstruct --reference DIR/ref.csv --frames DIR/ref.csv --contacts OUT --method paper "
               "--contact-radius-mm 3",
               "a declared contact radius is for contact fitting (fit, shapes), which holds a contact's area; paper's "
               "comes from its image"},
        BadRun{"lambda not a number",
               "calibrate --reference DIR/ref.csv --frames DIR/ref.csv --truth DIR/truth.csv --out OUT --lambda2 nan",
               "--lambda2: must be 0 (the method's) or positive, got nan"},
        BadRun{"zero element size", "mesh --element-size-mm 0 --out OUT",
               "--element-size-mm: must be a positive number, got \"0\""},
        BadRun{"images where a file is",
               "reconstruct --reference DIR/ref.csv --frames DIR/ref.csv --contacts OUT --images DIR/a_file/x "
               "--no-cache",
               "--images DIR/a_file/x: cannot create the folder"},
        BadRun{"pairs with a negative resistance", "calibrate --contact-law DIR/pairs.csv",
               "pairs.csv:3: pressure and resistance must be positive, got \"0.2,-5\""},
        BadRun{"a line of semicolons",
               "reconstruct --reference DIR/ref.csv --frames DIR/semicolons.csv --contacts OUT --no-cache",
               "semicolons.csv:1: value 1 \";;;;;;;;;;;;;;;;;;;;;;;;;;;;;;;;;;;;;;;;...\" is not a number"},
        BadRun{"electrodes wider than the sheet", "mesh --sensor DIR/wide.json --out OUT",
               "longer than the whole border"},
        BadRun{"calibration to a missing folder",
               "calibrate --reference DIR/ref.csv --frames DIR/ref.csv --truth DIR/truth.csv --out DIR/no/c.json",
               "--out DIR/no/c.json: cannot write: folder DIR/no does not exist"},
        BadRun{"unknown live source", "live --source zigzag --frames 1", "source \"zigzag\": unknown"},
        BadRun{"live serve address without a port", "live --serve 127.0.0.1 --frames 1 --cache DIR/cache",
               "is not HOST:PORT"},
        BadRun{"dds domain out of range", "live --dds emit --dds-domain 233 --frames 1 --cache DIR/cache",
               "--dds-domain 233: a DDS domain is a whole number from 0 to 232"},
        BadRun{"dds prefix not a ROS name", "live --dds a//b --frames 1 --cache DIR/cache",
               "--dds \"a//b\": a topic prefix is a ROS name"},
        BadRun{"mcap in a missing folder", "live --mcap DIR/no/live.mcap --frames 1 --cache DIR/cache",
               "does not exist"}),
    [](const auto& info) {
      std::string name = info.param.what;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

}  // namespace
}  // namespace emit

namespace emit {
namespace {

/// The real hydrogel skin's presses (../shared/real, not in the repository), or "" when absent.
std::string hydrogel_folder() {
  const std::string dir = test::real_data_dir() + "/hardman_hydrogel";
  return std::ifstream(dir + "/frames.csv").good() ? dir : "";
}

// emit eval --real as a user runs it on the real hydrogel skin (Hardman et al. 2023): calibrated on
// its first 100 presses, the held-out presses 440–549 are located within the target of
// 4 mm mean (3.91 mm measured, with the drift tracked; the data set's kNN floor is 8.1 mm with 440
// presses, the authors' own method 11–14 mm); every later press is written as a contact, and the
// curve is drawn.
TEST(Cli, EvalRealLocatesTheHydrogelSkinsPresses) {
  const std::string data = hydrogel_folder();
  if (data.empty()) GTEST_SKIP() << "no real data at " << test::real_data_dir() << " (cmake -DEMIT_REAL_DATA_DIR=...)";
  const std::string d = test::temp_folder("cli_eval_real");
  const std::string sensor = test::source_path("examples/sensors/hydrogel_hardman.json");
  const auto r = run_emit("eval --real " + data + " --sensor " + sensor + " --calibration-presses 100 --curve 50 " +
                          "--contacts " + d + "/contacts.jsonl --plots " + d + "/plots");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  double mean_mm = -1;
  ASSERT_EQ(read_row(r.out, "held-out presses, position error", " %lf", &mean_mm), 1) << r.out;
  EXPECT_LT(mean_mm, 4.0) << r.out;
  EXPECT_GT(mean_mm, 0.0) << r.out;
  // Each press's σ covers its error as a σ should (the target: 68 % within 1σ, 95 % within 2σ;
  // 72 % and 98 % measured, its scale set on the calibration presses alone).
  double k_mm = -1, sigma_mm = -1, within_1 = -1, within_2 = -1;
  ASSERT_EQ(read_row(r.out, "their sigma (k sqrt(1 - explained + u0), k",
                     " %lf mm set on the calibration): mean %lf mm; error within 1 sigma %lf %%, 2 sigma %lf", &k_mm,
                     &sigma_mm, &within_1, &within_2),
            4)
      << r.out;
  EXPECT_GE(within_1, 68) << r.out;
  EXPECT_GE(within_2, 95) << r.out;
  EXPECT_NE(r.out.find("   50 presses:"), std::string::npos) << r.out;
  const std::string contacts = test::read_text(d + "/contacts.jsonl");
  EXPECT_EQ(std::count(contacts.begin(), contacts.end(), '\n'), 450);
  long frame = -1;
  const std::vector<Contact> first = parse_contacts_line(contacts.substr(0, contacts.find('\n')), &frame);
  EXPECT_EQ(frame, 100);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_LT(std::hypot(first[0].x_mm, first[0].y_mm), 72.0);  // within the presses' reach
  EXPECT_TRUE(std::ifstream(d + "/plots/real_error_vs_calibration.png").good());

  // A board that glitches: 11 frames of 550 (2 %) each with one reading dropped to 0, not a number,
  // or clipped at a rail of 1e5 (in 6 frames, so the survey finds it). The evaluation masks them,
  // names the worst channels, and places the held-out presses within 0.2 mm of the clean data's.
  const std::string glitchy = d + "/glitchy";
  std::filesystem::create_directories(glitchy);
  for (const char* name : {"references_per_frame.csv", "truth.csv"})
    std::filesystem::copy_file(data + "/" + name, glitchy + "/" + name);
  {
    std::istringstream in(test::read_text(data + "/frames.csv"));
    std::ofstream out(glitchy + "/frames.csv");
    int row = 0, glitch = 0;
    for (std::string line; std::getline(in, line); ++row) {
      if (row % 50 == 7) {  // frames 7, 57, …, 507: 4 of them held out or calibrating
        std::vector<std::string> values;
        std::stringstream fields(line);
        for (std::string v; std::getline(fields, v, ',');) values.push_back(v);
        values[static_cast<std::size_t>((37 * row) % 192)] = glitch < 3 ? "0" : glitch < 5 ? "nan" : "100000";
        ++glitch;
        line.clear();
        for (std::size_t k = 0; k < values.size(); ++k) line += (k ? "," : "") + values[k];
      }
      out << line << '\n';
    }
  }
  const auto bad =
      run_emit("eval --real " + glitchy + " --sensor " + sensor + " --calibration-presses 100 --curve none --plots ''");
  ASSERT_EQ(bad.exit_code, 0) << bad.err;
  EXPECT_NE(bad.out.find("readings: 11 masked in 11 of 550 frames; rail found at 100000"), std::string::npos)
      << bad.out;
  EXPECT_NE(bad.err.find("emit: warning: readings that cannot be used"), std::string::npos) << bad.err;
  double glitchy_mm = -1;
  ASSERT_EQ(read_row(bad.out, "held-out presses, position error", " %lf", &glitchy_mm), 1) << bad.out;
  EXPECT_LT(glitchy_mm, mean_mm + 0.2) << bad.out;

  // A sensor without a protocol, and an EMIT command given the current-injection skin: one line each.
  const auto emit_sheet = run_emit("eval --real " + data + " --sensor " +
                                   test::source_path("examples/sensors/circle40.json") + " --curve none --plots ''");
  EXPECT_EQ(emit_sheet.exit_code, 1);
  EXPECT_NE(emit_sheet.err.find("circle40.json: has no \"excitation\""), std::string::npos) << emit_sheet.err;
  const auto simulate = run_emit("simulate --sensor " + sensor + " --press 0,0,3,1 --out " + d + "/f.csv");
  EXPECT_EQ(simulate.exit_code, 1);
  EXPECT_NE(simulate.err.find("is a current-injection skin"), std::string::npos) << simulate.err;
  EXPECT_FALSE(std::ifstream(d + "/f.csv").good());
  const auto alone = run_emit("eval --contacts " + d + "/c.jsonl");
  EXPECT_EQ(alone.exit_code, 2);
  EXPECT_NE(alone.err.find("--contacts requires --real"), std::string::npos) << alone.err;
}

}  // namespace
}  // namespace emit
