// What the viewer reads (live/viewer_messages.hpp): the mesh as JSON, and a frame as a length,
// a JSON header padded to 4 bytes and a float32 per triangle, decoded here as the page decodes it.
#include "emit/live/viewer_messages.hpp"

#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace emit {
namespace {

// A 4 × 2 mm strip of 2 × 1 cells: 6 nodes, 4 triangles, 6 border edges; electrode 0 is the
// bottom side (nodes 0..2, centre (2, 0)), electrode 1 the top (centre (2, 2)).
TEST(ViewerMessages, MeshMessageHoldsTheMeshAndItsBorder) {
  const Mesh mesh = test::strip_mesh(4, 2, 2, 1);
  const auto j = nlohmann::json::parse(mesh_message(mesh, {"strip"}));
  EXPECT_EQ(j["type"], "mesh");
  EXPECT_EQ(j["name"], "strip");
  ASSERT_EQ(j["nodes_mm"].size(), 12u);
  EXPECT_EQ(j["nodes_mm"][2], 2.0);  // node 1 at (2, 0)
  ASSERT_EQ(j["triangles"].size(), 12u);
  for (int t = 0; t < 4; ++t)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(j["triangles"][3 * t + k], mesh.triangles(t, k));
  EXPECT_EQ(j["outline_mm"].size(), 6u * 4);  // six segments of two points
  ASSERT_EQ(j["electrodes"].size(), 2u);
  EXPECT_EQ(j["electrodes"][0]["x_mm"], 2.0);
  EXPECT_EQ(j["electrodes"][0]["y_mm"], 0.0);
  EXPECT_EQ(j["electrodes"][1]["y_mm"], 2.0);
  EXPECT_EQ(j["electrodes"][1]["segments_mm"].size(), 2u * 4);  // the top side's two edges
  EXPECT_EQ(j["calibrated"], false);                            // the page's "uncalibrated" badge
  EXPECT_EQ(j["pressure_range_N_per_mm2"], 0.0);
}

// What the page says about the sheet: calibrated or not, its colour bar's top, the ADC's full scale.
TEST(ViewerMessages, MeshMessageSaysWhetherCalibratedAndTheScales) {
  const Mesh mesh = test::strip_mesh(4, 2, 2, 1);
  const auto j = nlohmann::json::parse(mesh_message(mesh, {"strip", true, 0.25, 3.3}));
  EXPECT_EQ(j["calibrated"], true);
  EXPECT_EQ(j["pressure_range_N_per_mm2"], 0.25);
  EXPECT_EQ(j["adc_reference_V"], 3.3);
}

// A flat sheet's message is as it was before curved sheets: no heights, no 3D view.
TEST(ViewerMessages, FlatMeshHasNoHeights) {
  const Mesh mesh = test::strip_mesh(4, 2, 2, 1);
  EXPECT_FALSE(viewer_draws_in_3d(mesh));
  const auto j = nlohmann::json::parse(mesh_message(mesh, {"strip"}));
  std::vector<std::string> keys;
  for (const auto& [key, value] : j.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"adc_reference_V", "calibrated", "electrodes", "name", "nodes_mm",
                                            "outline_mm", "pressure_range_N_per_mm2", "triangles", "type"}));
  for (const auto& electrode : j["electrodes"]) EXPECT_EQ(electrode.size(), 3u);  // segments_mm, x_mm, y_mm
}

// The strip bent into a ramp, z = x / 2: the heights beside the (x, y) pairs, one per point.
TEST(ViewerMessages, CurvedMeshCarriesTheHeights) {
  Mesh mesh = test::strip_mesh(4, 2, 2, 1);
  mesh.nodes_mm.col(2) = 0.5 * mesh.nodes_mm.col(0);
  EXPECT_TRUE(viewer_draws_in_3d(mesh));
  const auto j = nlohmann::json::parse(mesh_message(mesh, {"ramp"}));
  ASSERT_EQ(j["nodes_z_mm"].size(), 6u);
  for (std::size_t v = 0; v < 6; ++v) EXPECT_EQ(j["nodes_z_mm"][v], 0.5 * j["nodes_mm"][2 * v].get<double>());
  ASSERT_EQ(j["outline_z_mm"].size(), j["outline_mm"].size() / 2);
  for (std::size_t i = 0; i < j["outline_z_mm"].size(); ++i)
    EXPECT_EQ(j["outline_z_mm"][i], 0.5 * j["outline_mm"][2 * i].get<double>());
  for (const auto& electrode : j["electrodes"]) {
    ASSERT_EQ(electrode["segments_z_mm"].size(), electrode["segments_mm"].size() / 2);
    EXPECT_EQ(electrode["z_mm"], 1.0);  // both sides' nodes at x = 0, 2, 4: mean z = 1
  }
}

// On a curved sheet each contact carries its height and normal; on a flat one, neither.
TEST(ViewerMessages, CurvedFrameContactsCarryHeightAndNormal) {
  std::vector<Contact> contacts(1);
  contacts[0].z_mm = 8.5;
  contacts[0].nx = 0.6;
  contacts[0].nz = 0.8;
  const Vector pressure = Vector::Zero(2);
  LiveFrame frame;
  frame.contacts = &contacts;
  frame.pressure_N_per_mm2 = &pressure;
  auto header_of = [](const std::string& message) {
    std::uint32_t bytes = 0;
    std::memcpy(&bytes, message.data(), 4);
    return nlohmann::json::parse(message.substr(4, bytes));
  };
  const auto curved = header_of(frame_message(frame, 0, true))["contacts"][0];
  EXPECT_EQ(curved["z_mm"], 8.5);
  EXPECT_EQ(curved["normal"], (nlohmann::json{0.6, 0.0, 0.8}));
  const auto flat = header_of(frame_message(frame, 0))["contacts"][0];
  EXPECT_FALSE(flat.contains("z_mm"));
  EXPECT_FALSE(flat.contains("normal"));
  EXPECT_EQ(flat.size(), 6u);  // id, x_mm, y_mm, area_mm2, pressure_N_per_mm2, force_N
}

// A contact with an outline carries its ellipse under the JSON Lines' names; one without, none.
TEST(ViewerMessages, AContactsOutlineIsItsEllipse) {
  std::vector<Contact> contacts(2);
  contacts[0].semi_major_mm = 7.5, contacts[0].semi_minor_mm = 1.25, contacts[0].orientation_deg = -30;
  ellipse_outline({20, 30}, 7.5, 1.25, -30, contacts[0].outline);
  const Vector pressure = Vector::Zero(2);
  LiveFrame frame;
  frame.contacts = &contacts;
  frame.pressure_N_per_mm2 = &pressure;
  const std::string message = frame_message(frame, 0);
  std::uint32_t bytes = 0;
  std::memcpy(&bytes, message.data(), 4);
  const auto listed = nlohmann::json::parse(message.substr(4, bytes))["contacts"];
  EXPECT_EQ(listed[0]["semi_major_mm"], 7.5);
  EXPECT_EQ(listed[0]["semi_minor_mm"], 1.25);
  EXPECT_EQ(listed[0]["orientation_deg"], -30.0);
  // And its polygon, [[x, y], …] as in the JSON Lines.
  ASSERT_EQ(listed[0]["outline_mm"].size(), static_cast<std::size_t>(contacts[0].outline.size));
  for (int k = 0; k < contacts[0].outline.size; ++k) {
    EXPECT_EQ(listed[0]["outline_mm"][k][0].get<double>(), contacts[0].outline.vertex_mm(k).x());
    EXPECT_EQ(listed[0]["outline_mm"][k][1].get<double>(), contacts[0].outline.vertex_mm(k).y());
  }
  EXPECT_FALSE(listed[1].contains("outline_mm"));
  EXPECT_FALSE(listed[1].contains("semi_major_mm"));
  EXPECT_EQ(listed[1].size(), 6u);
}

TEST(ViewerMessages, FrameMessageIsLengthHeaderAndFloats) {
  std::vector<Contact> contacts(1);
  contacts[0].x_mm = 12.5;
  contacts[0].force_N = 3.25;
  contacts[0].id = 4;
  Vector pressure(3);
  pressure << 0.0, 0.125, 0.1;
  Frame volts(2, 2);  // ground l (row), sense m (column)
  volts << 0.0, 1.5, 0.25, 0.0;
  const std::vector<DeadElectrode> dead{{1, "reads 0 V as the sensed electrode in all 25 frames with signal"}};
  const std::vector<SwappedElectrodes> swapped{{0, 1, "their readings fit each other's places"}};
  LiveFrame frame;
  frame.volts = &volts;
  frame.dead_electrodes = &dead;
  frame.swapped_electrodes = &swapped;
  frame.frames_missed = 3;
  frame.misfit_mV = 0.75;
  frame.board_time_s = 12.5;
  frame.index = 41;
  frame.sequence = 1234;
  frame.reference_captures = 1;
  frame.contacts = &contacts;
  frame.pressure_N_per_mm2 = &pressure;
  frame.frames_per_s = 50;
  frame.latency_s = 0.002;
  const std::string message = frame_message(frame, 7);
  std::uint32_t header_bytes = 0;
  std::memcpy(&header_bytes, message.data(), 4);
  EXPECT_EQ(header_bytes % 4, 0u);
  ASSERT_EQ(message.size(), 4 + header_bytes + 4 * (3u + 4u));                 // 3 triangles, 2 × 2 readings
  const auto header = nlohmann::json::parse(message.substr(4, header_bytes));  // trailing spaces are JSON whitespace
  EXPECT_EQ(header["type"], "frame");
  EXPECT_EQ(header["index"], 41);
  EXPECT_EQ(header["sequence"], 1234);
  EXPECT_EQ(header["capturing_baseline"], false);
  EXPECT_EQ(header["commands"], 7);
  EXPECT_DOUBLE_EQ(header["latency_ms"].get<double>(), 2.0);
  EXPECT_EQ(header["max_pressure_N_per_mm2"], 0.125);
  ASSERT_EQ(header["contacts"].size(), 1u);
  EXPECT_EQ(header["contacts"][0]["x_mm"], 12.5);
  EXPECT_EQ(header["contacts"][0]["force_N"], 3.25);
  EXPECT_EQ(header["contacts"][0]["id"], 4);
  EXPECT_EQ(header["board_time_s"], 12.5);
  EXPECT_EQ(header["frames_missed"], 3);
  EXPECT_EQ(header["misfit_mV"], 0.75);
  EXPECT_EQ(header["electrode_count"], 2);
  ASSERT_EQ(header["dead_electrodes"].size(), 1u);
  EXPECT_EQ(header["dead_electrodes"][0]["electrode"], 1);
  EXPECT_EQ(header["dead_electrodes"][0]["reason"], dead[0].reason);
  ASSERT_EQ(header["swapped_electrodes"].size(), 1u);
  EXPECT_EQ(header["swapped_electrodes"][0]["electrodes"], (nlohmann::json{0, 1}));
  EXPECT_EQ(header["swapped_electrodes"][0]["reason"], swapped[0].reason);
  float values[7];
  std::memcpy(values, message.data() + 4 + header_bytes, sizeof values);
  EXPECT_EQ(values[0], 0.0f);
  EXPECT_EQ(values[1], 0.125f);
  EXPECT_EQ(values[2], 0.1f);  // float32: the value rounded once
  EXPECT_EQ(values[3], 0.0f);  // then the readings, row by row
  EXPECT_EQ(values[4], 1.5f);
  EXPECT_EQ(values[5], 0.25f);
  EXPECT_EQ(values[6], 0.0f);
}

}  // namespace
}  // namespace emit
