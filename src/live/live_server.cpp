#include "emit/live/live_server.hpp"

#include <array>
#include <mutex>
#include <set>
#include <thread>

#include <utility>  // before Boost 1.74's Asio, which uses std::exchange without it under C++20

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include "emit/core/errors.hpp"
#include "emit/live/viewer_messages.hpp"
#include "emit/live/viewer_page.hpp"

namespace emit {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;

namespace {

struct Message {
  std::string bytes;
  bool binary = false;
};
using MessagePtr = std::shared_ptr<const Message>;

constexpr auto http_timeout = std::chrono::seconds(30);

/// What the server serves over HTTP: the page, and three.js for its 3D view (viewer_page.hpp).
struct ViewerFile {
  std::string_view target;
  const char* content_type;
  std::string_view (*bytes)();
};

constexpr std::array<ViewerFile, 5> viewer_files{{
    {"/", "text/html; charset=utf-8", viewer_page},
    {"/index.html", "text/html; charset=utf-8", viewer_page},
    {"/three/three.module.js", "text/javascript; charset=utf-8", three_module_js},
    {"/three/three.core.js", "text/javascript; charset=utf-8", three_core_js},
    {"/three/addons/controls/OrbitControls.js", "text/javascript; charset=utf-8", three_orbit_controls_js},
}};

/// The file at `target`, or null: none there, or three.js left out of this build (empty).
const ViewerFile* find_viewer_file(std::string_view target) {
  for (const ViewerFile& file : viewer_files)
    if (file.target == target && !file.bytes().empty()) return &file;
  return nullptr;
}

}  // namespace

class WebSocketSession;

/// The state every session sees; lives until the server thread has stopped.
struct ServerState {
  MessagePtr mesh;
  std::function<void(const std::string&)> on_command;
  std::atomic<std::uint64_t> commands{0};
  std::atomic<std::size_t> client_count{0};
  std::set<std::shared_ptr<WebSocketSession>> sessions;  ///< touched on the server's thread only
};

/// One viewer: the mesh first, then frames, at most one waiting (newer frames replace it).
class WebSocketSession : public std::enable_shared_from_this<WebSocketSession> {
 public:
  WebSocketSession(tcp::socket socket, ServerState& state) : ws_(std::move(socket)), state_(state) {}

  void start(const http::request<http::string_body>& request) {  // async_accept reads it before returning
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.async_accept(request, [self = shared_from_this()](beast::error_code ec) {
      if (ec) return;
      self->state_.sessions.insert(self);
      self->state_.client_count = self->state_.sessions.size();
      self->offer(self->state_.mesh);
      self->read();
    });
  }

  /// Queue a message, replacing one still waiting (the client is slower than the frames).
  void offer(MessagePtr message) {
    pending_ = std::move(message);
    write_next();
  }

 private:
  void read() {
    ws_.async_read(input_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->forget();
      const std::string command = beast::buffers_to_string(self->input_.data());
      self->input_.consume(self->input_.size());
      if (command == "ack") {  // the client has the last frame: the next may go
        self->awaiting_ack_ = false;
        self->write_next();
        return self->read();
      }
      ++self->state_.commands;
      try {
        if (self->state_.on_command) self->state_.on_command(command);
      } catch (const std::exception&) {
        // A command that fails is the client's problem; the server keeps serving.
      }
      self->read();
    });
  }

  void write_next() {
    if (!pending_ || closed_ || writing_ || awaiting_ack_) return;
    current_ = std::move(pending_);
    pending_.reset();
    writing_ = true;
    awaiting_ack_ = current_->binary;  // frames are acknowledged; the mesh is not
    ws_.binary(current_->binary);
    ws_.async_write(net::buffer(current_->bytes), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      self->writing_ = false;
      self->current_.reset();
      if (ec) return self->forget();
      self->write_next();
    });
  }

  void forget() {
    closed_ = true;
    pending_.reset();
    state_.sessions.erase(shared_from_this());
    state_.client_count = state_.sessions.size();
  }

  websocket::stream<beast::tcp_stream> ws_;
  ServerState& state_;
  beast::flat_buffer input_;
  MessagePtr pending_, current_;
  bool writing_ = false, closed_ = false;
  bool awaiting_ack_ = false;  ///< a frame is out and the client has not said "ack" yet
};

/// One HTTP connection: the page at / and three.js (viewer_files), the WebSocket at /ws, 404 elsewhere.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket socket, ServerState& state) : stream_(std::move(socket)), state_(state) {}

  void read() {
    request_ = {};
    stream_.expires_after(http_timeout);
    http::async_read(stream_, buffer_, request_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return;
      self->answer();
    });
  }

 private:
  void answer() {
    const std::string target(request_.target());
    if (websocket::is_upgrade(request_) && target == "/ws") {
      stream_.expires_never();
      std::make_shared<WebSocketSession>(stream_.release_socket(), state_)->start(request_);
      return;
    }
    const ViewerFile* file = find_viewer_file(target);
    auto response =
        std::make_shared<http::response<http::string_body>>(file ? http::status::ok : http::status::not_found,
                                                            request_.version());
    response->set(http::field::server, "emit live");
    response->set(http::field::content_type, file ? file->content_type : "text/plain");
    response->set(http::field::cache_control, "no-store");
    response->body() = file ? std::string(file->bytes()) : "not found: " + target + "\n";
    response->keep_alive(request_.keep_alive());
    response->prepare_payload();
    http::async_write(stream_, *response, [self = shared_from_this(), response](beast::error_code ec, std::size_t) {
      if (ec) return;
      if (response->keep_alive()) return self->read();
      beast::error_code ignored;
      self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
    });
  }

  beast::tcp_stream stream_;
  ServerState& state_;
  beast::flat_buffer buffer_;
  http::request<http::string_body> request_;
};

struct LiveServer::Impl {
  ServerState state;  // first: destroyed after the io_context and the handlers holding sessions
  net::io_context io{1};
  tcp::acceptor acceptor{io};
  std::string host;
  int port = 0;
  bool curved = false;  ///< the mesh is drawn in 3D: contacts carry z and the normal
  std::thread thread;

  void accept() {
    acceptor.async_accept([this](beast::error_code ec, tcp::socket socket) {
      if (!acceptor.is_open()) return;
      if (!ec) {
        // Frames go out in WebSocket fragments of a few kB: with Nagle's algorithm each frame's
        // last one would wait for the viewer's delayed ACK (40 ms), capping a viewer at 25 frames/s.
        beast::error_code ignored;
        socket.set_option(tcp::no_delay(true), ignored);
        std::make_shared<HttpSession>(std::move(socket), state)->read();
      }
      accept();
    });
  }
};

namespace {

tcp::endpoint parse_address(const std::string& address, std::string& host) {
  const auto colon = address.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == address.size())
    throw InvalidInput("--serve: \"" + address + "\" is not HOST:PORT (e.g. 127.0.0.1:8080)");
  host = address.substr(0, colon);
  const std::string port_text = address.substr(colon + 1);
  int port = -1;
  try {
    std::size_t used = 0;
    port = std::stoi(port_text, &used);
    if (used != port_text.size()) port = -1;
  } catch (const std::exception&) {
  }
  if (port < 0 || port > 65535)
    throw InvalidInput("--serve: port \"" + port_text + "\" is not a number from 0 to 65535");
  beast::error_code ec;
  const auto ip = net::ip::make_address(host == "localhost" ? "127.0.0.1" : host, ec);
  if (ec) throw InvalidInput("--serve: \"" + host + "\" is not an IP address (e.g. 127.0.0.1 or 0.0.0.0)");
  return {ip, static_cast<unsigned short>(port)};
}

}  // namespace

LiveServer::LiveServer(const std::string& address, const Mesh& mesh, const ViewerSheet& sheet,
                       std::function<void(const std::string&)> on_command)
    : impl_(std::make_unique<Impl>()) {
  const tcp::endpoint endpoint = parse_address(address, impl_->host);
  impl_->state.mesh = std::make_shared<const Message>(Message{mesh_message(mesh, sheet), false});
  impl_->curved = viewer_draws_in_3d(mesh);
  impl_->state.on_command = std::move(on_command);
  beast::error_code ec;
  auto& acceptor = impl_->acceptor;
  acceptor.open(endpoint.protocol(), ec);
  if (!ec) acceptor.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) acceptor.bind(endpoint, ec);
  if (!ec) acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) throw IoError("cannot serve on " + address + ": " + ec.message());
  impl_->port = acceptor.local_endpoint().port();
  impl_->accept();
  impl_->thread = std::thread([this] { impl_->io.run(); });
}

LiveServer::~LiveServer() {
  net::post(impl_->io, [this] {
    beast::error_code ignored;
    impl_->acceptor.close(ignored);
    impl_->state.sessions.clear();
    impl_->io.stop();
  });
  impl_->thread.join();
}

void LiveServer::publish(const LiveFrame& frame) {
  if (impl_->state.client_count == 0) return;  // nobody watching: nothing to encode
  auto message =
      std::make_shared<const Message>(Message{frame_message(frame, impl_->state.commands, impl_->curved), true});
  net::post(impl_->io, [this, message] {
    for (const auto& session : impl_->state.sessions) session->offer(message);
  });
}

std::string LiveServer::url() const { return "http://" + impl_->host + ":" + std::to_string(port()) + "/"; }
int LiveServer::port() const { return impl_->port; }
std::size_t LiveServer::clients() const { return impl_->state.client_count; }
std::uint64_t LiveServer::commands_received() const { return impl_->state.commands; }

}  // namespace emit
