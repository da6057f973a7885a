#pragma once
/// \file ros2_messages.hpp
/// emit's frames, contacts, pressure images and mesh as ROS 2 messages: their definitions (the
/// `.msg` text, with every type they use, as ROS 2 bags and MCAP's "ros2msg" schemas carry them)
/// and their serialisation (CDR, little-endian, XCDR1 with its 4-byte encapsulation header: what
/// ROS 2's DDS layers put on the wire and in bags).
///
/// The messages are modelled on tactile_msgs (`TactileState`: a header and each sensor's name and
/// values; `TactileContact`: name, position, normal, wrench), in ROS's SI units (REP 103): metres,
/// newtons, pascals. emit's contacts are in mm and N/mm², so positions are × 1e-3, areas × 1e-6
/// and pressures × 1e6 here; angles are in radians. A contact's outline is the ellipse of its second
/// moments (semi_major_m, semi_minor_m, orientation_rad, with the 1σ area_std_m2 and
/// orientation_std_rad: JSON Lines' semi_major_mm, … in SI units), all 0 when it has none; and
/// its polygon, a geometry_msgs/Polygon `outline` (JSON Lines' outline_mm in m, float32 points
/// (x, y, 0) in the sheet's chart), empty when it has none.
///
///   emit_msgs/msg/TactileState     a raw frame: sensors[0] = {sensor name, N·N volts ground-major}
///   emit_msgs/msg/TactileContacts  a frame's contacts, strongest first (none: an empty list)
///   emit_msgs/msg/PressureImage    the pressure per triangle of the mesh [Pa]
///   shape_msgs/msg/Mesh            the reconstruction's mesh [m], once
///   sensor_msgs/msg/PointCloud2    the pressure as RViz shows it: a point per triangle at its
///                                  centroid [m] with the field "pressure" [Pa] (RViz's PointCloud2
///                                  display, colour transformer Intensity, channel "pressure")
///
/// Encoding reuses the caller's buffer: once it has grown to the largest message, it allocates
/// nothing (the per-frame path).
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/frame/contacts.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

/// The messages' header frame by default: the sheet's coordinate frame in a ROS graph (`emit live
/// --frame-id` names another; a static transform places it, README "ROS 2").
inline constexpr std::string_view ros2_frame_id = "emit_sheet";

/// \throw InvalidInput naming `option` unless `frame_id` is a tf2 frame id: letters, digits, _ and
/// /, not empty, not starting with / (tf2 refuses a leading slash).
void check_ros2_frame_id(const std::string& frame_id, const std::string& option = "--frame-id");

/// Nanoseconds since the Unix epoch, now (the host's system clock).
std::uint64_t unix_time_ns();

/// A message's time: ROS's builtin_interfaces/Time, from nanoseconds since the Unix epoch.
struct Ros2Stamp {
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
  static Ros2Stamp from_ns(std::uint64_t ns) {
    return {static_cast<std::int32_t>(ns / 1'000'000'000u), static_cast<std::uint32_t>(ns % 1'000'000'000u)};
  }
};

/// A message type: its ROS name ("emit_msgs/msg/TactileState") and its definition with every
/// type it uses, separated as ROS 2 bags do ("=====…\nMSG: pkg/Type\n").
struct Ros2MessageType {
  std::string name;
  std::string definition;
};

const Ros2MessageType& tactile_state_message();
const Ros2MessageType& tactile_contacts_message();
const Ros2MessageType& pressure_image_message();
const Ros2MessageType& mesh_message();
const Ros2MessageType& pressure_cloud_message();

/// A sensor_msgs/PointField: how the pressure cloud lays out each point's bytes.
struct PointFieldLayout {
  const char* name;
  std::uint32_t offset;
  std::uint8_t datatype;  ///< sensor_msgs/PointField's FLOAT32 = 7
  std::uint32_t count;
};
/// x, y, z [m] and pressure [Pa], float32 each, little-endian: 16 bytes a point.
inline constexpr std::array<PointFieldLayout, 4> pressure_cloud_fields{
    {{"x", 0, 7, 1}, {"y", 4, 7, 1}, {"z", 8, 7, 1}, {"pressure", 12, 7, 1}}};
inline constexpr std::size_t pressure_cloud_point_bytes = 16;
/// The cloud's points: each triangle's centroid [m], x, y, z after each other (offline, once).
std::vector<float> pressure_cloud_points_m(const Mesh& mesh);
/// The cloud's data bytes (pressure_cloud_point_bytes a point) into `data`, sized for every point.
void fill_pressure_cloud_data(std::span<std::uint8_t> data, std::span<const float> points_m,
                              const Vector& pressure_N_per_mm2);

/// A contact's fields as the messages carry them (emit_msgs/TactileContact), in SI units: the
/// one conversion of emit's contacts, for the CDR here and for DDS (live/dds_publisher.hpp).
struct Ros2Contact {
  /// "touch_<id>" when tracked (frame/contact_tracker.hpp), else "contact_<i>", i its rank in the
  /// frame (strongest first)
  std::array<char, 32> name;
  Vector3 position_m, normal, force_N;  ///< force: the press on the sheet, −force_N · normal
  double area_m2, pressure_Pa, peak_pressure_Pa, position_std_x_m, position_std_y_m, pressure_std_Pa, force_std_N;
  /// The outline's ellipse (frame/contacts.hpp; all 0 when it has none) and the 1σ of its area and
  /// angle; the angle from the chart's first axis, in (−π/2, π/2].
  double semi_major_m, semi_minor_m, orientation_rad, area_std_m2, orientation_std_rad;
  /// The outline's polygon [m] in the sheet's chart (frame/contact_outline.hpp), its first
  /// outline_size points; a geometry_msgs/Polygon's Point32s with z = 0.
  std::array<std::array<float, 2>, Outline::capacity> outline_m;
  std::uint32_t outline_size;
  Vector3 velocity_m_per_s;  ///< along the chart's axes, z = 0; 0 when not tracked
};
Ros2Contact ros2_contact(const Contact& contact, std::size_t rank);

/// Each fills `out` (cleared first) with the CDR bytes of one message.
void encode_tactile_state(std::vector<std::uint8_t>& out, Ros2Stamp stamp, std::string_view frame_id,
                          std::string_view sensor_name, const FrameView& volts);
/// `board_time_s`: the frame's time on the board's clock; `ended`: the touches that ended with it
/// (null: none).
void encode_tactile_contacts(std::vector<std::uint8_t>& out, Ros2Stamp stamp, std::string_view frame_id,
                             std::uint64_t frame, const std::vector<Contact>& contacts, double board_time_s = 0,
                             const std::vector<Contact>* ended = nullptr);
void encode_pressure_image(std::vector<std::uint8_t>& out, Ros2Stamp stamp, std::string_view frame_id,
                           std::uint64_t frame, const Vector& pressure_N_per_mm2);
/// `points_m`: pressure_cloud_points_m of the mesh whose triangles `pressure_N_per_mm2` covers.
void encode_pressure_cloud(std::vector<std::uint8_t>& out, Ros2Stamp stamp, std::string_view frame_id,
                           std::span<const float> points_m, const Vector& pressure_N_per_mm2);
void encode_mesh(std::vector<std::uint8_t>& out, const Mesh& mesh);

}  // namespace emit
