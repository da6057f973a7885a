#include "emit/io/tactile_mcap.hpp"

#include <utility>

#include "emit/io/ros2_messages.hpp"

namespace emit {

namespace {

std::uint16_t add_topic(McapWriter& mcap, const std::string& topic, const Ros2MessageType& type) {
  return mcap.add_channel(mcap.add_schema(type.name, "ros2msg", type.definition), topic, "cdr");
}

/// `value`, once the frame id is one tf2 takes (before a file is made for a path).
template <typename T>
T&& with_frame_id(T&& value, const std::string& frame_id) {
  check_ros2_frame_id(frame_id);
  return std::forward<T>(value);
}

}  // namespace

TactileMcap::TactileMcap(const std::string& path, std::string sensor_name, const Mesh& mesh,
                         std::uint64_t start_time_ns, const std::string& frame_id)
    : TactileMcap(OutputFile({"", with_frame_id(path, frame_id)}, {.partial = true}), std::move(sensor_name), mesh,
                  start_time_ns, frame_id) {}

TactileMcap::TactileMcap(OutputFile file, std::string sensor_name, const Mesh& mesh, std::uint64_t start_time_ns,
                         std::string frame_id)
    : mcap_(with_frame_id(std::move(file), frame_id), "ros2"),
      sensor_name_(std::move(sensor_name)),
      frame_id_(std::move(frame_id)) {
  const std::string prefix = "/emit";
  const std::uint16_t mesh_channel = add_topic(mcap_, prefix + "/mesh", mesh_message());
  frames_channel_ = add_topic(mcap_, prefix + "/frames", tactile_state_message());
  contacts_channel_ = add_topic(mcap_, prefix + "/contacts", tactile_contacts_message());
  pressure_channel_ = add_topic(mcap_, prefix + "/pressure", pressure_image_message());
  cloud_channel_ = add_topic(mcap_, prefix + "/pressure_cloud", pressure_cloud_message());
  cloud_points_m_ = pressure_cloud_points_m(mesh);
  encode_mesh(message_, mesh);
  mcap_.write_message(mesh_channel, 0, start_time_ns, start_time_ns, message_);
}

void TactileMcap::write(std::uint64_t frame, std::uint64_t time_ns, const FrameView& volts,
                        const std::vector<Contact>& contacts, const Vector& pressure_N_per_mm2, double board_time_s,
                        const std::vector<Contact>* ended) {
  const Ros2Stamp stamp = Ros2Stamp::from_ns(time_ns);
  const auto sequence = static_cast<std::uint32_t>(frames_);
  encode_tactile_state(message_, stamp, frame_id_, sensor_name_, volts);
  mcap_.write_message(frames_channel_, sequence, time_ns, time_ns, message_);
  encode_tactile_contacts(message_, stamp, frame_id_, frame, contacts, board_time_s, ended);
  mcap_.write_message(contacts_channel_, sequence, time_ns, time_ns, message_);
  encode_pressure_image(message_, stamp, frame_id_, frame, pressure_N_per_mm2);
  mcap_.write_message(pressure_channel_, sequence, time_ns, time_ns, message_);
  encode_pressure_cloud(message_, stamp, frame_id_, cloud_points_m_, pressure_N_per_mm2);
  mcap_.write_message(cloud_channel_, sequence, time_ns, time_ns, message_);
  ++frames_;
}

}  // namespace emit
