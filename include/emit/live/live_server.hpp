#pragma once
/// \file live_server.hpp
/// The live viewer's server (HTTP + WebSocket, Boost.Beast) on a thread of its own. GET / serves
/// the viewer page; a WebSocket at /ws receives, on connecting, the mesh once (a JSON text
/// message, viewer_messages.hpp), then every frame the loop publishes (a binary message: a JSON
/// header and the pressure per triangle as float32). A client's text messages are commands
/// ("recapture"), handed to the callback; "ack" is the client saying it has the last frame. A
/// slow client never holds the loop up: each client has one frame in flight until it says "ack"
/// (so frames cannot pile up in the sockets' buffers) and at most one waiting, replaced by newer
/// ones (the older is dropped); a client that goes away is forgotten.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "emit/live/live_loop.hpp"
#include "emit/live/viewer_messages.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

class LiveServer : public FramePublisher {
 public:
  /// Listens on `address` ("HOST:PORT"; port 0 picks a free one) and starts serving.
  /// `on_command` is called on the server's thread with each command a client sends.
  /// \throw InvalidInput for a malformed address, IoError if it cannot listen (e.g. the port is in use).
  LiveServer(const std::string& address, const Mesh& mesh, const ViewerSheet& sheet,
             std::function<void(const std::string&)> on_command);
  ~LiveServer() override;
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  /// Sends the frame to every client (encoded here, written on the server's thread). Never blocks on a client.
  void publish(const LiveFrame& frame) override;

  std::string url() const;  ///< "http://HOST:PORT/"
  int port() const;         ///< the bound port
  std::size_t clients() const;
  std::uint64_t commands_received() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace emit
