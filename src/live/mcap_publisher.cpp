#include "emit/live/mcap_publisher.hpp"

#include "emit/io/ros2_messages.hpp"

namespace emit {

McapPublisher::McapPublisher(OutputFile file, const std::string& sensor_name, const Mesh& mesh,
                             const std::string& frame_id)
    : mcap_(std::move(file), sensor_name, mesh, unix_time_ns(), frame_id) {}

void McapPublisher::publish(const LiveFrame& frame) {
  if (frame.capturing_reference || frame.volts == nullptr) return;
  mcap_.write(frame.sequence, frame.host_time_ns, frame_view(*frame.volts), *frame.contacts, *frame.pressure_N_per_mm2,
              frame.board_time_s, frame.ended);
}

}  // namespace emit
