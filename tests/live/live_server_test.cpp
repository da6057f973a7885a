// The viewer's server (live/live_server.hpp) with a small mesh and no loop: the page over HTTP
// (and 404 elsewhere) on one kept-alive connection; over the WebSocket the mesh message, frames
// one at a time with a newer waiting frame replacing an older one, and commands, a failing one
// included; addresses that are not HOST:PORT refused naming the part.
#include "emit/live/live_server.hpp"

#include <atomic>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <thread>

#include <utility>  // before Boost 1.74's Asio, which uses std::exchange without it under C++20

#include <boost/asio.hpp>
#include <boost/beast.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/live/viewer_messages.hpp"
#include "emit/live/viewer_page.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;

TEST(LiveServer, ServesThePageAndNotFoundOnOneConnection) {
  const Mesh mesh = test::strip_mesh(4, 2, 2, 1);
  LiveServer server("localhost:0", mesh, "strip", {});
  EXPECT_EQ(server.url(), "http://localhost:" + std::to_string(server.port()) + "/");
  net::io_context io;
  beast::tcp_stream stream(io);
  stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(server.port())));
  auto get = [&](const std::string& target) {
    http::request<http::empty_body> request(http::verb::get, target, 11);
    request.set(http::field::host, "localhost");
    request.keep_alive(true);
    http::write(stream, request);
    beast::flat_buffer buffer;
    http::response<http::string_body> response;
    http::read(stream, buffer, response);
    return response;
  };
  const auto page = get("/");
  EXPECT_EQ(page.result(), http::status::ok);
  EXPECT_EQ(page[http::field::content_type], "text/html; charset=utf-8");
  EXPECT_EQ(page.body(), std::string(viewer_page()));
  const auto missing = get("/favicon.ico");  // the same connection, kept alive
  EXPECT_EQ(missing.result(), http::status::not_found);
  EXPECT_EQ(missing.body(), "not found: /favicon.ico\n");
  EXPECT_EQ(server.clients(), 0u);  // HTTP clients are not viewers
}

// A viewer: the mesh exactly as mesh_message writes it; then a frame; while it is unacknowledged
// two more are published, and after "ack" only the newer comes (the older was replaced).
TEST(LiveServer, OneFrameInFlightAndTheNewestWaiting) {
  const Mesh mesh = test::strip_mesh(4, 2, 2, 1);
  std::atomic<int> commands{0};
  LiveServer server("127.0.0.1:0", mesh, "strip", [&](const std::string& command) {
    ++commands;
    if (command == "fail") throw std::runtime_error("a command that fails");
  });
  net::io_context io;
  tcp::socket socket(io);
  socket.connect({net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(server.port())});
  beast::websocket::stream<tcp::socket> ws(std::move(socket));
  ws.handshake("127.0.0.1", "/ws");
  beast::flat_buffer buffer;
  ws.read(buffer);
  EXPECT_TRUE(ws.got_text());
  EXPECT_EQ(beast::buffers_to_string(buffer.data()), mesh_message(mesh, "strip"));
  buffer.consume(buffer.size());
  EXPECT_EQ(server.clients(), 1u);  // counted before the mesh was sent

  const std::vector<Contact> contacts;
  const Vector pressure = Vector::Zero(mesh.triangle_count());
  LiveFrame frame;
  frame.contacts = &contacts;
  frame.pressure_N_per_mm2 = &pressure;
  auto index_of_next = [&] {
    ws.read(buffer);
    EXPECT_TRUE(ws.got_binary());
    const std::string bytes = beast::buffers_to_string(buffer.data());
    buffer.consume(buffer.size());
    std::uint32_t header = 0;
    std::memcpy(&header, bytes.data(), 4);
    return nlohmann::json::parse(bytes.substr(4, header))["index"].get<int>();
  };
  frame.index = 1;
  server.publish(frame);
  EXPECT_EQ(index_of_next(), 1);
  frame.index = 2;
  server.publish(frame);
  frame.index = 3;
  server.publish(frame);
  ws.text(true);
  ws.write(net::buffer(std::string("ack")));
  EXPECT_EQ(index_of_next(), 3);

  // Commands reach the callback; one that throws leaves the server serving the next.
  ws.write(net::buffer(std::string("fail")));
  ws.write(net::buffer(std::string("recapture")));
  for (int wait = 0; wait < 500 && commands < 2; ++wait) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(commands, 2);
  EXPECT_EQ(server.commands_received(), 2u);
  ws.write(net::buffer(std::string("ack")));
  frame.index = 4;
  server.publish(frame);
  EXPECT_EQ(index_of_next(), 4);
  ws.close(beast::websocket::close_code::normal);
}

TEST(LiveServer, AddressErrorsNameThePart) {
  const Mesh mesh = test::strip_mesh(4, 2, 2, 1);
  auto error_of = [&](const std::string& address) -> std::string {
    try {
      LiveServer server(address, mesh, "strip", {});
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(error_of(":8080"), "--serve: \":8080\" is not HOST:PORT (e.g. 127.0.0.1:8080)");
  EXPECT_EQ(error_of("127.0.0.1:80x"), "--serve: port \"80x\" is not a number from 0 to 65535");
  EXPECT_EQ(error_of("127.0.0.1:http"), "--serve: port \"http\" is not a number from 0 to 65535");
  EXPECT_EQ(error_of("sheet.local:0"), "--serve: \"sheet.local\" is not an IP address (e.g. 127.0.0.1 or 0.0.0.0)");
}

}  // namespace
}  // namespace emit
