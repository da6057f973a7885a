#pragma once
/// \file dds_publisher.hpp
/// `emit live --dds PREFIX [--dds-domain N]`: every reconstructed frame published on DDS (Cyclone
/// DDS) the way ROS 2 publishes, so that a ROS 2 node with the Cyclone RMW subscribes to it with
/// no bridge: topics `rt/PREFIX/frames`, `rt/PREFIX/contacts`, `rt/PREFIX/pressure`,
/// `rt/PREFIX/pressure_cloud` (sensor_msgs/PointCloud2, for RViz) and `rt/PREFIX/mesh` (ROS's
/// `/PREFIX/…`), types `emit_msgs::msg::dds_::TactileState_` and so on (idl/emit_ros2.idl: the
/// messages MCAP recordings carry, io/ros2_messages.hpp), stamped with the host's clock as
/// published. QoS: reliable, transient-local, the last 100 frames kept (the mesh: the last one;
/// the pressure cloud: 10), so a ROS subscriber with the default QoS (reliable, volatile) matches, and one
/// that starts late, or asks for transient-local, still gets the recent frames and the mesh.
/// A skin spread over several computers is assembled the same way: each publishes under its
/// prefix, and DDS discovery finds them.
#include <memory>
#include <string>

#include "emit/io/ros2_messages.hpp"
#include "emit/live/live_loop.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

struct DdsOptions {
  std::string prefix = "emit";          ///< a ROS name: letters, digits, _ and /, not starting with a digit
  int domain = 0;                       ///< the DDS domain (ROS_DOMAIN_ID): 0 to 232
  std::string frame_id{ros2_frame_id};  ///< the messages' header frame (io/ros2_messages.hpp)
  /// \throw InvalidInput naming the option when the prefix is not a ROS name or the domain is out
  /// of range.
  void validate() const;
};

class DdsPublisher : public FramePublisher {
 public:
  /// Joins the domain and publishes the mesh. \throw InvalidInput (DdsOptions::validate), IoError
  /// when DDS cannot start (no network interface it can use).
  DdsPublisher(const DdsOptions& options, const std::string& sensor_name, const Mesh& mesh);
  ~DdsPublisher() override;
  DdsPublisher(const DdsPublisher&) = delete;
  DdsPublisher& operator=(const DdsPublisher&) = delete;

  /// A reconstructed frame's three messages (capture frames are left out). \throw IoError if
  /// DDS refuses a write.
  void publish(const LiveFrame& frame) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace emit
