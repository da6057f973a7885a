// The viewer's server (live/live_server.hpp) with a small mesh and no loop: the page over HTTP
// (and 404 elsewhere) on one kept-alive connection, three.js; over the WebSocket the mesh message, frames
// one at a time with a newer waiting frame replacing an older one, and commands, a failing one
// included; addresses that are not HOST:PORT refused naming the part.
#include "emit/live/live_server.hpp"

#include <atomic>
#include <cstring>
#include <stdexcept>
#include <thread>

#include <utility>  // before Boost 1.74's Asio, which uses std::exchange without it under C++20

// g++ 12 at -O2 with the sanitizers warns, wrongly, that a boost::optional in Beast's HTTP response
// parser (basic_parser::content_length_unchecked, reached by the WebSocket client's handshake)
// may be used uninitialised; the warning is Boost's, not this file's.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/asio.hpp>
#include <boost/beast.hpp>
#pragma GCC diagnostic pop
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/live/viewer_messages.hpp"
#include "emit/live/viewer_page.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace beast = boost::beast;
namespace net = boost::asio;
using tcp = net::ip::tcp;

// three.js for the page's 3D view, at the paths its import map and its own relative import name
// (viewer/index.html): three.module.js imports ./three.core.js, OrbitControls imports 'three'.
TEST(LiveServer, ServesThreeJs) {
  if (three_module_js().empty())
    GTEST_SKIP() << "this build left three.js out (CMake warned: not installed in viewer/)";
  EXPECT_NE(three_module_js().find("from './three.core.js'"), std::string_view::npos);
  EXPECT_NE(three_orbit_controls_js().find("from 'three'"), std::string_view::npos);
  const Mesh mesh = test::strip_mesh(4, 2, 2, 1);
  LiveServer server("127.0.0.1:0", mesh, {"strip"}, {});
  const std::pair<const char*, std::string_view> files[] = {{"/three/three.module.js", three_module_js()},
                                                            {"/three/three.core.js", three_core_js()},
                                                            {"/three/addons/controls/OrbitControls.js",
                                                             three_orbit_controls_js()}};
  for (const auto& [target, bytes] : files) {
    net::io_context io;
    tcp::socket socket(io);
    socket.connect({net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(server.port())});
    net::write(socket,
               net::buffer("GET " + std::string(target) + " HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n"));
    std::string text;
    beast::error_code ec;
    net::read(socket, net::dynamic_buffer(text), ec);
    EXPECT_EQ(text.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << target;
    const auto body = text.find("\r\n\r\n");
    ASSERT_NE(body, std::string::npos) << target;
    EXPECT_NE(text.substr(0, body).find("Content-Type: text/javascript; charset=utf-8\r\n"), std::string::npos)
        << target;
    EXPECT_TRUE(text.substr(body + 4) == bytes) << target;  // not EXPECT_EQ: a megabyte printed on failure
  }
}

// Two requests on one connection, the second asking to close it: the page, then 404, read as the
// raw bytes the server sends.
TEST(LiveServer, ServesThePageAndNotFoundOnOneConnection) {
  const Mesh mesh = test::strip_mesh(4, 2, 2, 1);
  LiveServer server("localhost:0", mesh, {"strip"}, {});
  EXPECT_EQ(server.url(), "http://localhost:" + std::to_string(server.port()) + "/");
  net::io_context io;
  tcp::socket socket(io);
  socket.connect({net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(server.port())});
  net::write(socket,
             net::buffer(std::string("GET / HTTP/1.1\r\nHost: localhost\r\n\r\n"
                                     "GET /favicon.ico HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n")));
  std::string text;
  beast::error_code ec;
  net::read(socket, net::dynamic_buffer(text), ec);  // until the server closes the connection
  EXPECT_EQ(ec, net::error::eof);
  EXPECT_EQ(text.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << text.substr(0, 200);
  const auto page = text.find(viewer_page());
  ASSERT_NE(page, std::string::npos);
  EXPECT_NE(text.substr(0, page).find("Content-Type: text/html; charset=utf-8\r\n"), std::string::npos);
  const std::string rest = text.substr(page + viewer_page().size());
  EXPECT_EQ(rest.rfind("HTTP/1.1 404 Not Found\r\n", 0), 0u) << rest;
  const std::string body = "\r\n\r\nnot found: /favicon.ico\n";
  EXPECT_EQ(rest.substr(rest.size() - std::min(rest.size(), body.size())), body) << rest;
  EXPECT_EQ(server.clients(), 0u);  // HTTP clients are not viewers
}

// A viewer: the mesh exactly as mesh_message writes it; then a frame; while it is unacknowledged
// A viewer that acknowledges each frame at once gets them at the loop's pace. Frames are sent in
// WebSocket fragments of a few kB; were Nagle's algorithm left on, each frame's last fragment would
// wait for the viewer's delayed TCP ACK (40 ms on Linux): at most 25 frames/s, whatever the loop
// does. Published every 2 ms for 1 s, the viewer must get well over that: 100 (a loaded machine's
// scheduling may cost half of the 500).
TEST(LiveServer, AViewerThatAcknowledgesAtOnceKeepsUpWithTheLoop) {
  const Mesh mesh = test::strip_mesh(60, 60, 40, 40);  // 3200 triangles: 12.8 kB of pressure a frame
  LiveServer server("127.0.0.1:0", mesh, {"strip"}, {});
  net::io_context io;
  tcp::socket socket(io);
  socket.connect({net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(server.port())});
  beast::websocket::stream<tcp::socket> ws(std::move(socket));
  ws.handshake("127.0.0.1", "/ws");
  beast::flat_buffer buffer;
  ws.read(buffer);  // the mesh
  ASSERT_TRUE(ws.got_text());
  std::atomic<bool> done{false};
  std::thread loop([&] {
    const std::vector<Contact> contacts;
    const Vector pressure = Vector::Zero(mesh.triangle_count());
    LiveFrame frame;
    frame.contacts = &contacts;
    frame.pressure_N_per_mm2 = &pressure;
    for (frame.index = 0; !done; ++frame.index) {
      server.publish(frame);
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  });
  int frames = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  ws.text(true);
  while (std::chrono::steady_clock::now() < end) {
    buffer.consume(buffer.size());
    ws.read(buffer);
    ++frames;
    ws.write(net::buffer(std::string("ack")));
  }
  done = true;
  loop.join();
  std::printf("%d frames in 1 s\n", frames);
  EXPECT_GT(frames, 100);
  ws.close(beast::websocket::close_code::normal);
}

// two more are published, and after "ack" only the newer comes (the older was replaced).
TEST(LiveServer, OneFrameInFlightAndTheNewestWaiting) {
  const Mesh mesh = test::strip_mesh(4, 2, 2, 1);
  std::atomic<int> commands{0};
  LiveServer server("127.0.0.1:0", mesh, {"strip"}, [&](const std::string& command) {
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
  EXPECT_EQ(beast::buffers_to_string(buffer.data()), mesh_message(mesh, {"strip"}));
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
      LiveServer server(address, mesh, {"strip"}, {});
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
