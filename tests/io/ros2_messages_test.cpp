// ROS 2 messages in CDR (io/ros2_messages.hpp): the bytes of a message laid out by hand from the
// format's rules (XCDR1: 4-byte encapsulation, each primitive aligned to its size after it,
// strings with their length and NUL, sequences with their count), and encoding that allocates
// nothing once the buffer has grown. @foxglove/rosmsg2-serialization decodes whole files in
// tests/mcap/read_back_test.mjs.
#include "emit/io/ros2_messages.hpp"

#include <cstring>
#include <numbers>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

template <typename T>
T read_at(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

TEST(Ros2Messages, APressureImageIsLaidOutAsCdr) {
  std::vector<std::uint8_t> out;
  Vector pressure(2);
  pressure << 1e-6, 0.25;  // N/mm², written in Pa as float32: 1 and 250000
  encode_pressure_image(out, Ros2Stamp::from_ns(3'000'000'005), "f", 7, pressure);
  // Offsets after the 4-byte encapsulation: sec 0, nanosec 4, frame_id's length 8 and "f\0" at
  // 12, padding to 16 for the uint64 frame, its count at 24, the floats at 28 and 32.
  ASSERT_EQ(out.size(), 4u + 36u);
  EXPECT_EQ(out[0], 0x00);
  EXPECT_EQ(out[1], 0x01);  // CDR_LE
  EXPECT_EQ(read_at<std::int32_t>(out, 4 + 0), 3);
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 4), 5u);
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 8), 2u);
  EXPECT_EQ(out[4 + 12], 'f');
  EXPECT_EQ(out[4 + 13], 0);
  EXPECT_EQ(read_at<std::uint64_t>(out, 4 + 16), 7u);
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 24), 2u);
  EXPECT_EQ(read_at<float>(out, 4 + 28), 1.0f);
  EXPECT_EQ(read_at<float>(out, 4 + 32), 250000.0f);
}

TEST(Ros2Messages, AContactIsInSiUnitsPressingAlongMinusTheNormal) {
  Contact c;
  c.x_mm = 12, c.y_mm = 34, c.force_N = 2.5, c.area_mm2 = 20, c.pressure_N_per_mm2 = 0.125;
  std::vector<std::uint8_t> out;
  encode_tactile_contacts(out, {}, "", 9, {c}, 0.25);
  // header (sec, nanosec, "" = length 1 and NUL) ends at 9; frame at 16; board time at 24; count
  // at 32; the name "contact_0" (length 10) at 36..49; the position's doubles from 56.
  EXPECT_EQ(read_at<std::uint64_t>(out, 4 + 16), 9u);
  EXPECT_EQ(read_at<double>(out, 4 + 24), 0.25);
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 32), 1u);
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 36), 10u);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(out.data() + 4 + 40)), "contact_0");
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 56), 0.012);     // x [m]
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 64), 0.034);     // y [m]
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 96), 1.0);       // normal z
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 120), -2.5);     // wrench force z [N]
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 152), 20e-6);    // area [m²]
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 160), 0.125e6);  // pressure [Pa]
  // After peak pressure (168) and the four 1σ (176 to 200): the outline's ellipse, SI and radians.
  c.semi_major_mm = 6, c.semi_minor_mm = 1.5, c.orientation_deg = 45, c.area_std_mm2 = 2, c.orientation_std_deg = 9;
  encode_tactile_contacts(out, {}, "", 9, {c});
  // The last double, orientation_std, at 240; the outline's count at 248; the velocity's three
  // doubles at 256..279; the ended touches' count at 280.
  ASSERT_EQ(out.size(), 4u + 284u);
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 208), 6e-3);                   // semi_major [m]
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 216), 1.5e-3);                 // semi_minor [m]
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 224), std::numbers::pi / 4);   // orientation [rad]
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 232), 2e-6);                   // area_std [m²]
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 240), std::numbers::pi / 20);  // orientation_std [rad]
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 248), 0u);                     // no outline: no points
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 280), 0u);                     // no touch ended
  // The outline: a geometry_msgs/Polygon, its count then each Point32's three float32 [m], z = 0.
  c.outline.push_back({10, 30});
  c.outline.push_back({14, 30});
  c.outline.push_back({12, 38});
  encode_tactile_contacts(out, {}, "", 9, {c});
  ASSERT_EQ(out.size(), 4u + 284u + 32u);  // 36 bytes of points, less the 4 that aligned the velocity before
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 248), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(read_at<float>(out, 4 + 252 + 12 * k), 1e-3f * c.outline.vertices_mm[k][0]);
    EXPECT_EQ(read_at<float>(out, 4 + 256 + 12 * k), 1e-3f * c.outline.vertices_mm[k][1]);
    EXPECT_EQ(read_at<float>(out, 4 + 260 + 12 * k), 0.0f);
  }
  EXPECT_NE(tactile_contacts_message().definition.find("geometry_msgs/Polygon outline\n"), std::string::npos);
  EXPECT_NE(tactile_contacts_message().definition.find("MSG: geometry_msgs/Point32\nfloat32 x\n"), std::string::npos);
  EXPECT_NE(tactile_contacts_message().definition.find("float64 orientation_rad "), std::string::npos);
  // Every definition names the types it uses once each, as ROS 2 bags carry them.
  for (const Ros2MessageType* type : {&tactile_state_message(), &tactile_contacts_message(), &pressure_image_message(),
                                      &mesh_message(), &pressure_cloud_message()}) {
    EXPECT_NE(type->name.find("/msg/"), std::string::npos);
    if (type != &mesh_message()) {
      EXPECT_NE(type->definition.find("MSG: std_msgs/Header"), std::string::npos) << type->name;
      EXPECT_NE(type->definition.find("MSG: builtin_interfaces/Time"), std::string::npos) << type->name;
    }
  }
}

// The pressure as RViz draws it, a sensor_msgs/PointCloud2: a point per triangle at its centroid
// [m] with its pressure [Pa], fields x, y, z, pressure as float32 (datatype 7) at 0, 4, 8, 12.
TEST(Ros2Messages, APressureCloudIsAPointPerTriangleAtItsCentroid) {
  const Mesh mesh = test::strip_mesh(4, 2, 2, 1);  // 4 triangles
  Vector pressure(4);
  pressure << 0, 0.25, 0, 1e-6;
  std::vector<std::uint8_t> out;
  encode_pressure_cloud(out, {}, "f", pressure_cloud_points_m(mesh), pressure);
  // After the header (16 bytes): height 16, width 20, the fields' count 24, then each field's
  // name (length and text), offset (aligned to 4), datatype (1 byte) and count (aligned to 4):
  // "x" 28..47, "y" 48..67, "z" 68..87, "pressure" 88..115; is_bigendian 116, point_step 120,
  // row_step 124, the data's count 128 and its bytes from 132, is_dense after them.
  ASSERT_EQ(out.size(), 4u + 132u + 16u * 4u + 1u);
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 16), 1u);
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 20), 4u);
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 24), 4u);
  const std::array<std::pair<std::size_t, const char*>, 4> names{{{28, "x"}, {48, "y"}, {68, "z"}, {88, "pressure"}}};
  for (std::size_t f = 0; f < 4; ++f) {
    const auto [at, name] = names[f];
    EXPECT_EQ(read_at<std::uint32_t>(out, 4 + at), std::strlen(name) + 1);
    EXPECT_STREQ(reinterpret_cast<const char*>(out.data() + 4 + at + 4), name);
    const std::size_t offset_at = (at + 4 + std::strlen(name) + 1 + 3) / 4 * 4;
    EXPECT_EQ(read_at<std::uint32_t>(out, 4 + offset_at), 4 * f);
    EXPECT_EQ(out[4 + offset_at + 4], 7);  // FLOAT32
    EXPECT_EQ(read_at<std::uint32_t>(out, 4 + offset_at + 8), 1u);
  }
  EXPECT_EQ(out[4 + 116], 0);                            // little-endian
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 120), 16u);  // point_step
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 124), 64u);  // row_step
  EXPECT_EQ(read_at<std::uint32_t>(out, 4 + 128), 64u);  // the data's bytes
  for (Index t = 0; t < 4; ++t) {
    const Vector3 centroid_m = 1e-3 / 3 *
                               (mesh.nodes_mm.row(mesh.triangles(t, 0)) + mesh.nodes_mm.row(mesh.triangles(t, 1)) +
                                mesh.nodes_mm.row(mesh.triangles(t, 2)))
                                   .transpose();
    const std::size_t at = 4 + 132 + 16 * static_cast<std::size_t>(t);
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_EQ(read_at<float>(out, at + 4 * static_cast<std::size_t>(axis)), static_cast<float>(centroid_m[axis]));
    EXPECT_EQ(read_at<float>(out, at + 12), static_cast<float>(1e6 * pressure[t]));  // Pa
  }
  EXPECT_EQ(out.back(), 1);  // is_dense
  EXPECT_EQ(pressure_cloud_message().name, "sensor_msgs/msg/PointCloud2");
  EXPECT_NE(pressure_cloud_message().definition.find("MSG: sensor_msgs/PointField\n"), std::string::npos);
}

// A tracked touch (frame/contact_tracker.hpp) is named by its id, which stays while the touch
// lasts, and carries its velocity [m/s]; a touch that ended comes in `ended` with its last state.
TEST(Ros2Messages, ATrackedTouchIsNamedByItsIdWithItsVelocityAndEndedTouchesFollow) {
  Contact c;
  c.x_mm = 12, c.y_mm = 34, c.id = 17, c.phase = TouchPhase::move, c.vx_mm_per_s = 40, c.vy_mm_per_s = -20;
  EXPECT_EQ(std::string(ros2_contact(c, 3).name.data()), "touch_17");
  EXPECT_EQ(ros2_contact(c, 3).velocity_m_per_s, Vector3(0.04, -0.02, 0));
  Contact ended = c;
  ended.id = 5, ended.phase = TouchPhase::up;
  const std::vector<Contact> ended_list{ended};
  std::vector<std::uint8_t> out;
  encode_tactile_contacts(out, {}, "", 9, {c}, 1.5, &ended_list);
  // One contact of 284 − 32 − 4 bytes with its 9-byte name "touch_17" (one byte shorter than
  // "contact_0", which the alignment before the position absorbs): the ended list's count at 280.
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(out.data() + 4 + 40)), "touch_17");
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 256), 0.04);   // velocity x [m/s]
  EXPECT_DOUBLE_EQ(read_at<double>(out, 4 + 264), -0.02);  // velocity y
  ASSERT_EQ(read_at<std::uint32_t>(out, 4 + 280), 1u);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(out.data() + 4 + 288)), "touch_5");
  EXPECT_NE(tactile_contacts_message().definition.find("float64 board_time"), std::string::npos);
  EXPECT_NE(tactile_contacts_message().definition.find("emit_msgs/TactileContact[] ended"), std::string::npos);
}

TEST(Ros2Messages, EncodingAFrameAllocatesNothingOnceWarm) {
  Frame volts = Frame::Constant(16, 16, 0.5);
  std::vector<Contact> contacts(3);
  const Vector pressure = Vector::Constant(5000, 0.01);
  const std::vector<float> cloud_points(std::size_t{3} * 5000, 0.01f);
  std::vector<std::uint8_t> out;
  encode_tactile_state(out, {}, "emit_sheet", "default 60 mm", frame_view(volts));
  encode_pressure_cloud(out, {}, "emit_sheet", cloud_points, pressure);  // the largest: the buffer grows to it
  const test::AllocationCounter counter;
  encode_tactile_state(out, {}, "emit_sheet", "default 60 mm", frame_view(volts));
  encode_tactile_contacts(out, {}, "emit_sheet", 1, contacts);
  encode_pressure_image(out, {}, "emit_sheet", 1, pressure);
  encode_pressure_cloud(out, {}, "emit_sheet", cloud_points, pressure);
  EXPECT_EQ(counter.count(), 0);
}

}  // namespace
}  // namespace emit
