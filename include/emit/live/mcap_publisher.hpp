#pragma once
/// \file mcap_publisher.hpp
/// `emit live --mcap FILE`: every reconstructed frame (its readings, contacts and pressure image)
/// into an MCAP recording with ROS 2's messages (io/tactile_mcap.hpp), stamped with the host's
/// clock as it is published. The reference's capture frames are left out (they have no contacts;
/// `--record` keeps every frame as the board sent it). A write that fails (a full disk) throws
/// from publish() and ends the run.
#include <string>

#include "emit/io/tactile_mcap.hpp"
#include "emit/live/live_loop.hpp"

namespace emit {

class McapPublisher : public FramePublisher {
 public:
  /// Into an output opened with OutputOptions::partial. \throw IoError naming it.
  McapPublisher(OutputFile file, const std::string& sensor_name, const Mesh& mesh,
                const std::string& frame_id = std::string(ros2_frame_id));
  void publish(const LiveFrame& frame) override;
  /// Renames PATH.partial to PATH (io/mcap_writer.hpp). \throw IoError.
  void close() { mcap_.close(); }
  /// After a failed run: a whole file at PATH.partial, PATH untouched. \throw IoError.
  void close_partial() { mcap_.close_partial(); }

 private:
  TactileMcap mcap_;
};

}  // namespace emit
