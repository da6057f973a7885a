#pragma once
/// \file tactile_mcap.hpp
/// A run recorded as an MCAP file with ROS 2's conventions (`emit reconstruct --mcap`, `emit live
/// --mcap`): per frame, its raw readings, its contacts and its pressure image, each on its own
/// topic as a ROS 2 message (io/ros2_messages.hpp), and the mesh the images are drawn on once at
/// the start. Profile "ros2", schemas "ros2msg", messages "cdr": `ros2 bag play` and Foxglove read
/// it as a bag.
///
///   /emit/frames    emit_msgs/msg/TactileState
///   /emit/contacts  emit_msgs/msg/TactileContacts
///   /emit/pressure  emit_msgs/msg/PressureImage
///   /emit/mesh      shape_msgs/msg/Mesh
///   /emit/pressure_cloud  sensor_msgs/msg/PointCloud2 (the pressure as RViz and Foxglove draw it)
///
/// Written through PATH.partial, renamed on close() (io/mcap_writer.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/frame/contacts.hpp"
#include "emit/io/mcap_writer.hpp"
#include "emit/io/ros2_messages.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

class TactileMcap {
 public:
  /// Into an output opened with OutputOptions::partial (core/output_paths.hpp's open_outputs);
  /// the mesh is written at `start_time_ns`. \throw IoError naming it.
  /// `frame_id`: the messages' header frame (io/ros2_messages.hpp).
  TactileMcap(OutputFile file, std::string sensor_name, const Mesh& mesh, std::uint64_t start_time_ns,
              std::string frame_id = std::string(ros2_frame_id));
  /// Opens PATH first. \throw IoError naming the file (a missing folder: before anything is written).
  TactileMcap(const std::string& path, std::string sensor_name, const Mesh& mesh, std::uint64_t start_time_ns,
              const std::string& frame_id = std::string(ros2_frame_id));

  /// One frame's three messages, at `time_ns` (ns since the Unix epoch: when the frame reached
  /// the host; the messages' header stamps and MCAP log times), taken by the board at
  /// `board_time_s` on its clock; `ended`: the tracked touches that ended with it (null: none).
  /// Allocates nothing once warm. \throw IoError.
  void write(std::uint64_t frame, std::uint64_t time_ns, const FrameView& volts, const std::vector<Contact>& contacts,
             const Vector& pressure_N_per_mm2, double board_time_s = 0, const std::vector<Contact>* ended = nullptr);
  /// \throw IoError. Without it, PATH.partial stays and PATH is untouched.
  void close() { mcap_.close(); }
  /// A whole file left at PATH.partial, PATH untouched (io/mcap_writer.hpp). \throw IoError.
  void close_partial() { mcap_.close_partial(); }

  const std::string& path() const { return mcap_.path(); }
  std::uint64_t frames() const { return frames_; }

 private:
  McapWriter mcap_;
  std::string sensor_name_, frame_id_;
  std::uint16_t frames_channel_ = 0, contacts_channel_ = 0, pressure_channel_ = 0, cloud_channel_ = 0;
  std::vector<float> cloud_points_m_;  ///< each triangle's centroid (pressure_cloud_points_m)
  std::vector<std::uint8_t> message_;
  std::uint64_t frames_ = 0;
};

}  // namespace emit
