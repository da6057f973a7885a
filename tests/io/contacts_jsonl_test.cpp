// Contacts as JSON Lines (io/contacts_jsonl.hpp), beside tests/frame/contacts_test.cpp's round
// trips: the documented line byte for byte, unknown keys ignored, and the exact message for each
// way a line is not contacts.
#include "emit/io/contacts_jsonl.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

Contact linear_contact() {
  Contact c;
  c.x_mm = 21.5;
  c.y_mm = 37.25;
  c.area_mm2 = 78.5;
  c.pressure_N_per_mm2 = 0.125;
  c.peak_pressure_N_per_mm2 = 0.25;
  c.force_N = 9.8125;
  return c;
}

// The README's format, byte for byte: the values above have at most 6 significant digits, so %.6g
// prints them as they are.
TEST(ContactsJsonl, WritesTheDocumentedLine) {
  std::ostringstream out;
  write_contacts_line(out, 7, {linear_contact()});
  EXPECT_EQ(out.str(),
            "{\"frame\": 7, \"contacts\": [{\"x_mm\": 21.5, \"y_mm\": 37.25, \"area_mm2\": 78.5, "
            "\"pressure_N_per_mm2\": 0.125, \"peak_pressure_N_per_mm2\": 0.25, \"force_N\": 9.8125}]}\n");
  std::ostringstream empty;
  write_contacts_line(empty, 0, {});
  EXPECT_EQ(empty.str(), "{\"frame\": 0, \"contacts\": []}\n");
}

// On a curved sheet a contact is a point of the surface with its normal: z and the normal follow
// (x, y); a flat sheet's line has neither (above), and reads back as z = 0, normal +z.
TEST(ContactsJsonl, WritesAndReadsACurvedSheetsPointAndNormal) {
  Contact c = linear_contact();
  c.z_mm = 6.5, c.nx = 0.6, c.ny = 0, c.nz = 0.8;
  std::ostringstream out;
  write_contacts_line(out, 3, {c});
  EXPECT_EQ(out.str(),
            "{\"frame\": 3, \"contacts\": [{\"x_mm\": 21.5, \"y_mm\": 37.25, \"z_mm\": 6.5, \"nx\": 0.6, \"ny\": 0, "
            "\"nz\": 0.8, \"area_mm2\": 78.5, \"pressure_N_per_mm2\": 0.125, \"peak_pressure_N_per_mm2\": 0.25, "
            "\"force_N\": 9.8125}]}\n");
  const auto curved = parse_contacts_line(out.str());
  ASSERT_EQ(curved.size(), 1u);
  EXPECT_EQ(Vector3(curved[0].nx, curved[0].ny, curved[0].nz), Vector3(0.6, 0, 0.8));
  EXPECT_EQ(curved[0].z_mm, 6.5);
  std::ostringstream flat_line;
  write_contacts_line(flat_line, 3, {linear_contact()});
  const auto flat = parse_contacts_line(flat_line.str());
  EXPECT_EQ(Vector3(flat[0].nx, flat[0].ny, flat[0].nz), Vector3::UnitZ());
  EXPECT_EQ(flat[0].z_mm, 0.0);
}

// The outline's polygon: written last as [[x, y], …] to 6 digits, read back to within them (its
// vertices are floats, 7 digits), in order; a line without it reads back without one.
TEST(ContactsJsonl, OutlineRoundTrips) {
  Contact c = linear_contact();
  c.outline.push_back({21.5, 30.25});
  c.outline.push_back({25.125, 37.25});
  c.outline.push_back({-1.5, 40});
  std::ostringstream out;
  write_contacts_line(out, 9, {c});
  EXPECT_NE(out.str().find(R"("force_N": 9.8125, "outline_mm": [[21.5, 30.25], [25.125, 37.25], [-1.5, 40]]})"),
            std::string::npos)
      << out.str();
  Contact polygon = linear_contact();
  ellipse_outline({21.5, 37.25}, 12.345678, 3.21, 33.3, polygon.outline);
  std::ostringstream line;
  write_contacts_line(line, 10, {polygon, linear_contact()});
  const auto read = parse_contacts_line(line.str());
  ASSERT_EQ(read.size(), 2u);
  ASSERT_EQ(read[0].outline.size, polygon.outline.size);
  for (int k = 0; k < polygon.outline.size; ++k)
    EXPECT_LE((read[0].outline.vertex_mm(k) - polygon.outline.vertex_mm(k)).norm(), 1e-4) << k;  // 6 digits of ~30
  EXPECT_NEAR(read[0].outline.area_mm2(), polygon.outline.area_mm2(), 1e-3);
  EXPECT_TRUE(read[1].outline.empty());
}

// Touch over time: a tracked contact's id and phase first, its velocity after the other numbers;
// the frame's board and host times after its number; the touches that ended in "ended", phase
// "up". Byte for byte (the README's format), then read back.
TEST(ContactsJsonl, WritesAndReadsTrackedTouchesAndTheFramesTimes) {
  Contact moving = linear_contact();
  moving.id = 12, moving.phase = TouchPhase::move, moving.vx_mm_per_s = 40.5, moving.vy_mm_per_s = -3.25;
  Contact ended = linear_contact();
  ended.id = 11, ended.phase = TouchPhase::up;
  const std::vector<Contact> ended_list{ended};
  std::ostringstream out;
  write_contacts_line(out, 8, {moving}, -1, {12.34, 1795000000.123456}, &ended_list);
  EXPECT_EQ(out.str(),
            "{\"frame\": 8, \"board_time_s\": 12.34, \"host_time_s\": 1795000000.123456, \"contacts\": [{\"id\": 12, "
            "\"phase\": \"move\", \"x_mm\": 21.5, \"y_mm\": 37.25, \"area_mm2\": 78.5, \"pressure_N_per_mm2\": 0.125, "
            "\"peak_pressure_N_per_mm2\": 0.25, \"force_N\": 9.8125, \"vx_mm_per_s\": 40.5, \"vy_mm_per_s\": -3.25}], "
            "\"ended\": [{\"id\": 11, \"phase\": \"up\", \"x_mm\": 21.5, \"y_mm\": 37.25, \"area_mm2\": 78.5, "
            "\"pressure_N_per_mm2\": 0.125, \"peak_pressure_N_per_mm2\": 0.25, \"force_N\": 9.8125, \"vx_mm_per_s\": "
            "0, "
            "\"vy_mm_per_s\": 0}]}\n");
  const ContactsLine read = parse_contacts_record(out.str());
  EXPECT_EQ(read.frame, 8);
  EXPECT_EQ(read.times.board_s, 12.34);
  EXPECT_NEAR(read.times.host_unix_s, 1795000000.123456, 1e-6);  // µs: what a host's receive time means
  ASSERT_EQ(read.contacts.size(), 1u);
  EXPECT_EQ(read.contacts[0].id, 12);
  EXPECT_EQ(read.contacts[0].phase, TouchPhase::move);
  EXPECT_EQ(read.contacts[0].vx_mm_per_s, 40.5);
  ASSERT_EQ(read.ended.size(), 1u);
  EXPECT_EQ(read.ended[0].id, 11);
  EXPECT_EQ(read.ended[0].phase, TouchPhase::up);
  // An untracked line reads back untracked and without times.
  std::ostringstream plain;
  write_contacts_line(plain, 8, {linear_contact()});
  const ContactsLine untracked = parse_contacts_record(plain.str());
  EXPECT_EQ(untracked.contacts[0].id, -1);
  EXPECT_EQ(untracked.contacts[0].phase, TouchPhase::none);
  EXPECT_TRUE(std::isnan(untracked.times.board_s) && std::isnan(untracked.times.host_unix_s));
  EXPECT_TRUE(untracked.ended.empty());
}

// A non-finite contact field is tests/frame/contacts_test.cpp's; a non-finite misfit is refused too.
TEST(ContactsJsonl, RefusesANonFiniteMisfit) {
  std::ostringstream out;
  try {
    write_contacts_line(out, 4, {}, std::numeric_limits<double>::infinity());
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "contacts of frame 4: the fit's misfit is not finite");
  }
  EXPECT_TRUE(out.str().empty()) << "no half line";
}

// A reader keeps working when the format gains a key.
TEST(ContactsJsonl, UnknownKeysAreIgnored) {
  const auto read = parse_contacts_line(
      R"({"frame": 2, "new": true, "contacts": [{"x_mm": 1, "y_mm": 2, "area_mm2": 3, "pressure_N_per_mm2": 4, "peak_pressure_N_per_mm2": 5, "force_N": 6, "colour": "red"}]})");
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read[0].force_N, 6.0);
}

class ContactsJsonlBad : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(ContactsJsonlBad, SaysWhatIsWrong) {
  try {
    parse_contacts_line(GetParam().first);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), GetParam().second);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Errors, ContactsJsonlBad,
    ::testing::Values(
        std::pair{"[1]", "contacts line: not a JSON object"},
        std::pair{R"({"contacts": []})", "contacts line: missing \"frame\""},
        std::pair{R"({"frame": 1.5, "contacts": []})", "contacts line: \"frame\" is not an integer"},
        std::pair{R"({"frame": 1})", "contacts line: missing \"contacts\""},
        std::pair{R"({"frame": 1, "contacts": {}})", "contacts line: \"contacts\" is not an array"},
        std::pair{R"({"frame": 1, "contacts": [3]})", "contacts line: contact 0 is not an object"},
        std::pair{R"({"frame": 1, "contacts": [{"x_mm": 1}]})", "contacts line: contact 0: missing \"y_mm\""},
        std::pair{R"({"frame": 1, "contacts": [{"x_mm": "1"}]})",
                  "contacts line: contact 0: \"x_mm\" is not a finite number"},
        std::pair{
            R"({"frame": 1, "contacts": [{"x_mm": 1, "y_mm": 2, "area_mm2": 3, "pressure_N_per_mm2": 4, "peak_pressure_N_per_mm2": 5, "force_N": 6, "outline_mm": [[0, 0], [1, 0]]}]})",
            "contacts line: contact 0: \"outline_mm\" is not a list of 3 to 64 vertices"},
        std::pair{
            R"({"frame": 1, "contacts": [{"x_mm": 1, "y_mm": 2, "area_mm2": 3, "pressure_N_per_mm2": 4, "peak_pressure_N_per_mm2": 5, "force_N": 6, "outline_mm": [[0, 0], [1, 0], [1]]}]})",
            "contacts line: contact 0: \"outline_mm\" vertex 2 is not [x, y], finite numbers"},
        std::pair{
            R"({"frame": 1, "contacts": [{"x_mm": 1, "y_mm": 2, "area_mm2": 3, "pressure_N_per_mm2": 4, "peak_pressure_N_per_mm2": 5, "force_N": 6, "id": -2}]})",
            "contacts line: contact 0: \"id\" is not a non-negative integer"},
        std::pair{
            R"({"frame": 1, "contacts": [{"x_mm": 1, "y_mm": 2, "area_mm2": 3, "pressure_N_per_mm2": 4, "peak_pressure_N_per_mm2": 5, "force_N": 6, "id": 2, "phase": "hover"}]})",
            "contacts line: contact 0: \"phase\" is not one of \"down\", \"move\", \"up\""},
        std::pair{R"({"frame": 1, "board_time_s": "now", "contacts": []})",
                  "contacts line: \"board_time_s\" is not a finite number"},
        // The sensor JSON's fuzz finding, here too: nlohmann's out_of_range escaped.
        std::pair{R"({"frame": 1e999, "contacts": []})",
                  "contacts line: a number out of range ([json.exception.out_of_range.406] number "
                  "overflow parsing '1e999')"}));

}  // namespace
}  // namespace emit
