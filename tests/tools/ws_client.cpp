// emit_ws_client: viewers that come and go, for the soak test of `emit live --serve`
// (scripts/soak.sh, tests/tools/soak_short_test.sh). A tool, not part of the library: it speaks to
// the server over the network only (live/live_server.hpp, the messages of live/viewer_messages.hpp).
//
//   emit_ws_client HOST:PORT [--seconds S] [--stay-s S] [--pause-s S] [--stall] [--latency-log FILE]
//
// A reader (the default) connects to ws://HOST:PORT/ws, reads the mesh and then frames for
// --stay-s seconds, answering each frame "ack" as the viewer page does, and leaves: politely (a
// WebSocket close) and abruptly (the socket shut) in turn; then it waits --pause-s and comes again,
// until --seconds have passed (a visit ends then too) or SIGINT/SIGTERM. It checks each visit: the mesh first (text),
// then frames (binary) whose sequence numbers only go up. --latency-log writes a line per frame: the Unix time [s], the
// loop's latency the frame reports ("latency_ms", emit's own measurement of the frame before it) and its sequence
// number. With --stall it connects and never reads (a stuck browser tab) for --stay-s, then drops the connection, and
// again.
//
// At the end one line on standard output, e.g.
//   ws_client reader: 120 visits, 0 failed, 35012 messages, 1834567890 bytes, frames per visit min 210 max 402
// Exit status 0 if every visit succeeded (a reader: got the mesh and at least one frame, in order).
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

#include <utility>  // before Boost 1.74's Asio, which uses std::exchange without it under C++20

#include <boost/asio.hpp>
#include <boost/beast.hpp>
#include <nlohmann/json.hpp>

namespace {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using Clock = std::chrono::steady_clock;

std::atomic<bool> stop_requested{false};
extern "C" void request_stop(int) { stop_requested = true; }

/// A frame that does not come within this long means the server is stuck (frames come every few ms
/// at full speed; 50 frames/s paced is 20 ms).
constexpr auto read_timeout = std::chrono::seconds(5);

struct Options {
  std::string host, port;
  double seconds = 60, stay_s = 3, pause_s = 0.5;
  bool stall = false;
  std::string latency_log;
};

struct Totals {
  std::uint64_t visits = 0, failed = 0, messages = 0, bytes = 0;
  std::uint64_t min_frames = UINT64_MAX, max_frames = 0;
};

/// Runs `start(handler)`'s one asynchronous operation to completion (or the stream's timeout).
template <class Start>
beast::error_code run_one(net::io_context& io, Start start) {
  beast::error_code result;
  start([&result](beast::error_code ec, auto&&...) { result = ec; });
  io.restart();
  io.run();
  return result;
}

/// The frame's sequence number and reported latency from its JSON header (a uint32 length, then the JSON).
bool frame_header(const beast::flat_buffer& buffer, std::uint64_t& sequence, double& latency_ms) {
  const auto* bytes = static_cast<const unsigned char*>(buffer.data().data());
  const std::size_t size = buffer.size();
  if (size < 4) return false;
  const std::uint32_t length =
      bytes[0] | (bytes[1] << 8) | (bytes[2] << 16) | (static_cast<std::uint32_t>(bytes[3]) << 24);
  if (length > size - 4) return false;
  const auto header = nlohmann::json::parse(bytes + 4, bytes + 4 + length, nullptr, false);
  if (header.is_discarded() || !header.contains("sequence") || !header.contains("latency_ms")) return false;
  sequence = header["sequence"].get<std::uint64_t>();
  latency_ms = header["latency_ms"].get<double>();
  return true;
}

/// One visit. \return an empty string, or what went wrong.
std::string visit(const Options& options, Clock::time_point end, bool polite, Totals& totals, std::FILE* latency_log) {
  net::io_context io;
  websocket::stream<beast::tcp_stream> ws(io);
  tcp::resolver resolver(io);
  beast::error_code ec;
  const auto endpoints = resolver.resolve(options.host, options.port, ec);
  if (ec) return "resolve: " + ec.message();
  beast::get_lowest_layer(ws).expires_after(read_timeout);
  ec = run_one(io, [&](auto handler) { beast::get_lowest_layer(ws).async_connect(endpoints, handler); });
  if (ec) return "connect: " + ec.message();
  beast::get_lowest_layer(ws).socket().set_option(tcp::no_delay(true), ec);  // as browsers do
  ec = run_one(io, [&](auto handler) { ws.async_handshake(options.host, "/ws", handler); });
  if (ec) return "handshake: " + ec.message();
  const auto leave_at = std::min(end, Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                         std::chrono::duration<double>(options.stay_s)));
  if (options.stall) {  // connected, reading nothing
    while (Clock::now() < leave_at && !stop_requested) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    beast::get_lowest_layer(ws).socket().close(ec);
    return {};
  }
  beast::flat_buffer buffer;
  std::uint64_t frames = 0, last_sequence = 0;
  bool got_mesh = false;
  while (Clock::now() < leave_at && !stop_requested) {
    beast::get_lowest_layer(ws).expires_after(read_timeout);
    buffer.clear();
    ec = run_one(io, [&](auto handler) { ws.async_read(buffer, handler); });
    if (ec) return "read after " + std::to_string(frames) + " frames: " + ec.message();
    ++totals.messages;
    totals.bytes += buffer.size();
    if (ws.got_text()) {
      if (got_mesh) return "a second text message (the mesh comes once)";
      got_mesh = true;
      continue;
    }
    if (!got_mesh) return "a frame before the mesh";
    std::uint64_t sequence = 0;
    double latency_ms = 0;
    if (!frame_header(buffer, sequence, latency_ms)) return "a frame without a readable header";
    if (latency_log)
      std::fprintf(latency_log, "%.3f %.3f %llu\n",
                   std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count(),
                   latency_ms, static_cast<unsigned long long>(sequence));
    if (frames > 0 && sequence <= last_sequence)
      return "frame " + std::to_string(sequence) + " after frame " + std::to_string(last_sequence);
    last_sequence = sequence;
    ++frames;
    ws.text(true);
    ec = run_one(io, [&](auto handler) { ws.async_write(net::buffer(std::string_view("ack")), handler); });
    if (ec) return "ack: " + ec.message();
  }
  totals.min_frames = std::min(totals.min_frames, frames);
  totals.max_frames = std::max(totals.max_frames, frames);
  if (frames == 0 && leave_at != end)
    return "no frame while connected";  // (a visit cut short by the end may have none)
  if (polite) {
    beast::get_lowest_layer(ws).expires_after(read_timeout);
    // The close handshake: frames still in flight are read and dropped until the server's close.
    ec = run_one(io, [&](auto handler) { ws.async_close(websocket::close_code::normal, handler); });
    if (ec) return "close: " + ec.message();
  } else {
    beast::get_lowest_layer(ws).socket().close(ec);
  }
  return {};
}

/// A number, all of `text`.
bool number(const char* text, double& value) {
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0';
}

bool parse(int argc, char** argv, Options& options) {
  if (argc < 2) return false;
  const std::string address = argv[1];
  const auto colon = address.rfind(':');
  if (colon == std::string::npos) return false;
  options.host = address.substr(0, colon);
  options.port = address.substr(colon + 1);
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--stall") options.stall = true;
    else if (arg == "--seconds" && has_value) {
      if (!number(argv[++i], options.seconds)) return false;
    } else if (arg == "--stay-s" && has_value) {
      if (!number(argv[++i], options.stay_s)) return false;
    } else if (arg == "--pause-s" && has_value) {
      if (!number(argv[++i], options.pause_s)) return false;
    } else if (arg == "--latency-log" && has_value) options.latency_log = argv[++i];
    else return false;
  }
  return options.seconds > 0 && options.stay_s > 0 && options.pause_s >= 0;
}

int run(const Options& options) {
  std::FILE* latency_log = nullptr;
  if (!options.latency_log.empty() && !(latency_log = std::fopen(options.latency_log.c_str(), "w"))) {
    std::fprintf(stderr, "ws_client: cannot write %s\n", options.latency_log.c_str());
    return 2;
  }
  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
  Totals totals;
  const auto end =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.seconds));
  while (Clock::now() < end && !stop_requested) {
    ++totals.visits;
    const std::string error = visit(options, end, totals.visits % 2 == 1, totals, latency_log);
    if (!error.empty() && !stop_requested) {
      ++totals.failed;
      std::fprintf(stderr, "ws_client: visit %llu: %s\n", static_cast<unsigned long long>(totals.visits),
                   error.c_str());
    }
    const auto resume =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.pause_s));
    while (Clock::now() < resume && Clock::now() < end && !stop_requested)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::printf("ws_client %s: %llu visits, %llu failed, %llu messages, %llu bytes, frames per visit min %llu max %llu\n",
              options.stall ? "stalled" : "reader", static_cast<unsigned long long>(totals.visits),
              static_cast<unsigned long long>(totals.failed), static_cast<unsigned long long>(totals.messages),
              static_cast<unsigned long long>(totals.bytes),
              static_cast<unsigned long long>(totals.min_frames == UINT64_MAX ? 0 : totals.min_frames),
              static_cast<unsigned long long>(totals.max_frames));
  if (latency_log) std::fclose(latency_log);
  return totals.failed == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (!parse(argc, argv, options)) {
    std::fprintf(stderr,
                 "usage: emit_ws_client HOST:PORT [--seconds S] [--stay-s S] [--pause-s S] [--stall] "
                 "[--latency-log FILE]\n");
    return 2;
  }
  try {
    return run(options);
  } catch (const std::exception& e) {  // a malformed frame header, out of memory: the tool's own failure
    std::fprintf(stderr, "ws_client: %s\n", e.what());
    return 2;
  }
}
