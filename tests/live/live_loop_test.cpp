// The live path end to end in one process: the simulator's frames through the reference and the
// fit to contacts at the scripted presses; the server's WebSocket delivers the mesh, frames and
// commands; a port in use is a clear error.
#include "emit/live/live_loop.hpp"

#include <cmath>
#include <cstring>
#include <sstream>
#include <thread>

#include <utility>  // before Boost 1.74's Asio, which uses std::exchange without it under C++20

#include <gtest/gtest.h>
#include <boost/asio.hpp>
#include <boost/beast.hpp>
#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/live/live_server.hpp"
#include "emit/live/open_source.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/sim_source.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// contact_fitter_test's bound for a press tracked frame to frame is 0.2 mm (the cold fit's
/// accuracy is ~0.1 mm, README); a moving finger tracked at 50 frames/s gets the same margin
/// again: 0.5 mm.
constexpr double live_fit_tolerance_mm = 0.5;

struct LiveBench {
  Sensor sensor = default_sensor();
  Pipeline pipeline{sensor, {.method = Method::fit, .cache_dir = test::temp_folder("live_cache"), .excluded = {}}};
};

LiveBench& bench() {
  static LiveBench b;
  return b;
}

SourceOptions unpaced() {
  SourceOptions options;
  options.frames_per_s = 0;  // as fast as the twin goes; the script keeps its 50 frames/s clock
  return options;
}

TEST(SimSource, ScriptsStartUntouchedAndStayOnTheSheet) {
  const Sensor sensor = default_sensor();
  SourceOptions options = unpaced();
  SimSource loop(sensor, parse_sim_script("sim"), options);
  for (std::uint64_t s = 0; s < static_cast<std::uint64_t>(options.untouched_frames); ++s)
    EXPECT_TRUE(loop.presses_of(s).empty());
  int pressed = 0;
  for (std::uint64_t s = options.untouched_frames; s < 1000; ++s)  // 20 s: the figure-eight and its lift-offs
    for (const Press& p : loop.presses_of(s)) {
      ++pressed;
      EXPECT_NO_THROW(validate_press(sensor, p, "frame " + std::to_string(s)));
    }
  EXPECT_GT(pressed, 700);  // 6 s pressed of every 7
  EXPECT_LT(pressed, 1000 - options.untouched_frames);
  SourceFrame frame;
  ASSERT_TRUE(loop.next(frame, std::chrono::seconds(30)));
  EXPECT_EQ(frame.sequence, 0u);
  EXPECT_EQ(frame.volts.rows(), 16);
}

TEST(SimSource, BadSpecsNameThemselves) {
  const Sensor sensor = default_sensor();
  EXPECT_THROW(parse_sim_script("sim:zigzag"), InvalidInput);
  EXPECT_THROW(parse_sim_script("sim:fixed:30"), InvalidInput);
  try {
    parse_sim_script("sim:fixed:30,abc");
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("\"abc\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(SimSource(sensor, parse_sim_script("sim:fixed:80,30"), unpaced()), InvalidInput);  // off the sheet
  EXPECT_THROW(open_source("serial", sensor, unpaced()), InvalidInput);
}

// The live reference is the mean of its 10 captured frames, and the significance floor counts
// them: σ·√(1 + 1/10), not a single frame's σ·√2 (35 % higher, what the loop used to set). Each
// untouched frame after that moves the reference by the drift rate, and the floor follows the
// average's count (frame/reference.hpp): 1/(0.99²/10 + 0.01²) = 10.19 frames after one.
TEST(LiveLoop, TheSignificanceFloorCountsTheCapturedFrames) {
  LiveBench& b = bench();
  SimSource source(b.sensor, parse_sim_script("sim"), unpaced());  // its first 15 frames untouched
  LiveOptions options;
  ASSERT_EQ(options.reference.capture_frames, 10);
  LiveLoop loop(source, b.pipeline, options);
  for (int k = 0; k < options.reference.capture_frames; ++k) EXPECT_EQ(loop.step(), nullptr) << "capture frame " << k;
  const auto floor_for = [&](double frames) {
    Reconstructor r = b.pipeline.reconstructor(options.frame);
    r.set_reference({Frame::Zero(16, 16), frames});
    return Vector(r.significance_floor());
  };
  const Vector live = loop.reconstructor().significance_floor();
  ASSERT_TRUE(live.allFinite());
  EXPECT_EQ(live, floor_for(10));
  EXPECT_NEAR(floor_for(1).maxCoeff() / live.maxCoeff(), std::sqrt(2 / 1.1), 1e-12);
  ASSERT_NE(loop.step(), nullptr);  // frame 10: untouched, reconstructed, followed
  ASSERT_TRUE(loop.last_frame().sequence < static_cast<std::uint64_t>(unpaced().untouched_frames));
  const double r = options.reference.drift_rate;
  EXPECT_NEAR(loop.reconstructor().significance_floor().maxCoeff() / floor_for(10).maxCoeff(),
              std::sqrt((1 + (1 - r) * (1 - r) / 10 + r * r) / 1.1), 1e-12);
}

// The scripted figure-eight, reconstructed live by contact fitting: every pressed frame gives one
// contact at the press, every untouched frame none; the JSON Lines carry the source's numbers.
TEST(LiveLoop, ContactsFollowTheScriptedFinger) {
  LiveBench& b = bench();
  SimSource source(b.sensor, parse_sim_script("sim"), unpaced());
  LiveOptions options;
  options.max_frames = 40;
  LiveLoop loop(source, b.pipeline, options);
  const std::string contacts_path = test::temp_folder("live_loop_contacts") + "/contacts.jsonl";
  OutputFile contacts({"--contacts", contacts_path});
  loop.write_contacts_to(&contacts);
  int pressed = 0;
  loop.on_frame([&](const SourceFrame& frame, const std::vector<Contact>& contacts) {
    const std::vector<Press> presses = source.presses_of(frame.sequence);
    ASSERT_EQ(contacts.size(), presses.size()) << "frame " << frame.sequence;
    if (presses.empty()) return;
    ++pressed;
    EXPECT_LT(std::hypot(contacts[0].x_mm - presses[0].x_mm, contacts[0].y_mm - presses[0].y_mm), live_fit_tolerance_mm)
        << "frame " << frame.sequence;
  });
  const std::atomic<bool> stop{false};
  const LiveStats stats = loop.run(stop);
  EXPECT_EQ(stats.frames, 40u);
  EXPECT_EQ(stats.capture_frames, static_cast<std::uint64_t>(ReferenceOptions{}.capture_frames));
  EXPECT_EQ(pressed, 40 - (unpaced().untouched_frames - ReferenceOptions{}.capture_frames));
  EXPECT_EQ(stats.latency.count(), 40u);
  contacts.commit();
  std::istringstream in(test::read_text(contacts_path));
  std::string line;
  long expected_frame = ReferenceOptions{}.capture_frames, frame = -1;
  for (; std::getline(in, line); ++expected_frame) {
    parse_contacts_line(line, &frame);
    EXPECT_EQ(frame, expected_frame);
  }
  EXPECT_EQ(expected_frame, ReferenceOptions{}.capture_frames + 40);
}

// Pulled a frame at a time (step(), as the Python iterator pulls), the loop gives what run()
// gives: no contacts during the baseline's capture, then each frame's contacts where the finger is.
TEST(LiveLoop, SteppingGivesEachReconstructedFramesContacts) {
  LiveBench& b = bench();
  SimSource source(b.sensor, parse_sim_script("sim"), unpaced());
  LiveLoop loop(source, b.pipeline);
  const int capture = ReferenceOptions{}.capture_frames;
  for (int f = 0; f < capture; ++f) {
    const std::vector<Contact>* contacts = nullptr;
    while (loop.stats().capture_frames == static_cast<std::uint64_t>(f)) contacts = loop.step();
    EXPECT_EQ(contacts, nullptr) << "capture frame " << f;
  }
  int pressed = 0;
  while (loop.stats().frames < 20) {
    const std::vector<Contact>* contacts = loop.step();
    if (!contacts) continue;
    const std::vector<Press> presses = source.presses_of(loop.last_frame().sequence);
    ASSERT_EQ(contacts->size(), presses.size()) << "frame " << loop.last_frame().sequence;
    if (presses.empty()) continue;
    ++pressed;
    EXPECT_LT(std::hypot((*contacts)[0].x_mm - presses[0].x_mm, (*contacts)[0].y_mm - presses[0].y_mm),
              live_fit_tolerance_mm);
  }
  EXPECT_EQ(pressed, 20 - (unpaced().untouched_frames - capture));
}

// The loop tracks its contacts at the frames' board times: the scripted finger is one touch (one id,
// down then move, moving at the script's pace); capturing the reference again ends it (its up comes
// with the next reconstructed frame) and the finger comes back as a new touch.
TEST(LiveLoop, TracksTheFingerAsOneTouchUntilTheReferenceIsCapturedAgain) {
  LiveBench& b = bench();
  SimSource source(b.sensor, parse_sim_script("sim"), unpaced());
  LiveLoop loop(source, b.pipeline);
  std::vector<Contact> touches;
  while (touches.size() < 15)
    if (const std::vector<Contact>* contacts = loop.step(); contacts && !contacts->empty()) {
      ASSERT_EQ(contacts->size(), 1u);
      touches.push_back((*contacts)[0]);
    }
  EXPECT_EQ(touches.front().phase, TouchPhase::down);
  for (std::size_t k = 1; k < touches.size(); ++k) {
    EXPECT_EQ(touches[k].id, touches.front().id) << "frame " << k;
    EXPECT_EQ(touches[k].phase, TouchPhase::move);
  }
  // The finger's speed along its figure-eight is tens of mm/s; the tracker's velocity says so.
  EXPECT_GT(std::hypot(touches.back().vx_mm_per_s, touches.back().vy_mm_per_s), 1.0);
  loop.command("recapture");
  const std::vector<Contact>* contacts = nullptr;
  while (!contacts) contacts = loop.step();
  ASSERT_EQ(loop.tracker().ended().size(), 1u);
  EXPECT_EQ(loop.tracker().ended()[0].id, touches.front().id);
  EXPECT_EQ(loop.tracker().ended()[0].phase, TouchPhase::up);
  for (const Contact& c : *contacts) {  // against a reference taken under the finger: whatever it finds is new
    EXPECT_GT(c.id, touches.front().id);
    EXPECT_EQ(c.phase, TouchPhase::down);
  }
}

/// Hands out one frame's volts under the sequence numbers it is given, then ends.
class NumberedSource : public FrameSource {
 public:
  NumberedSource(Frame volts, std::vector<std::uint64_t> sequences)
      : volts_(std::move(volts)), sequences_(std::move(sequences)) {}
  bool next(SourceFrame& frame, std::chrono::milliseconds) override {
    if (finished()) throw IoError("numbered: end");
    frame.volts = volts_;
    frame.sequence = sequences_[next_++];
    frame.received = std::chrono::steady_clock::now();
    return true;
  }
  bool finished() const override { return next_ == sequences_.size(); }
  std::string description() const override { return "numbered"; }

 private:
  Frame volts_;
  std::vector<std::uint64_t> sequences_;
  std::size_t next_ = 0;
};

// The loop counts the frames a source numbered but never handed out: 9 and 10 (inside the
// baseline's capture, which counts too), 12 and 13, and 5..7 after the source started again (a
// step back, 3 after 16, is no gap) — and a repeated number is none either.
TEST(LiveLoop, CountsGapsInTheSourcesNumbersAsMissedFrames) {
  LiveBench& b = bench();
  SimSource twin(b.sensor, parse_sim_script("sim"), unpaced());
  SourceFrame untouched;
  ASSERT_TRUE(twin.next(untouched, std::chrono::seconds(30)));
  std::vector<std::uint64_t> sequences = {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 14, 15, 16, 3, 4, 8, 8, 9};
  NumberedSource source(untouched.volts, sequences);
  LiveLoop loop(source, b.pipeline);
  const std::atomic<bool> stop{false};
  const LiveStats stats = loop.run(stop);
  EXPECT_EQ(stats.capture_frames + stats.frames, sequences.size());
  EXPECT_EQ(stats.frames_missed, 2u + 2u + 3u);
}

/// Hands out `untouched` `capture` times, then `pressed` `pressed_count` times, then ends.
class TwoFrameSource : public FrameSource {
 public:
  TwoFrameSource(Frame untouched, Frame pressed, int capture, int pressed_count)
      : untouched_(std::move(untouched)),
        pressed_(std::move(pressed)),
        capture_(capture),
        total_(capture + pressed_count) {}
  bool next(SourceFrame& frame, std::chrono::milliseconds) override {
    if (finished()) throw IoError("two frames: end");
    frame.volts = next_ < capture_ ? untouched_ : pressed_;
    frame.sequence = static_cast<std::uint64_t>(next_++);
    frame.received = std::chrono::steady_clock::now();
    return true;
  }
  bool finished() const override { return next_ == total_; }
  std::string description() const override { return "two frames"; }

 private:
  Frame untouched_, pressed_;
  int capture_, total_, next_ = 0;
};

/// What the viewer's server would be told, frame by frame.
struct HealthWatcher : FramePublisher {
  std::vector<std::vector<DeadElectrode>> dead;
  std::vector<double> misfit_mV;
  void publish(const LiveFrame& frame) override {
    dead.push_back(*frame.dead_electrodes);
    misfit_mV.push_back(frame.misfit_mV);
  }
};

// Electrode 5 disconnected (its column reads 0 V: electrode_health.hpp) under a held press: the
// frames published name it once a window of 25 pressed frames is full, and not before. The
// paper's method (contact fitting on such frames takes seconds each under the sanitizers), so no
// misfit is published: it has no fit.
TEST(LiveLoop, PublishesADeadElectrodeOnceAWindowOfPressedFramesShowsIt) {
  const Sensor sensor = default_sensor();
  Pipeline paper(sensor, {.method = Method::paper, .cache_dir = test::temp_folder("live_cache"), .excluded = {}});
  SimSource twin(sensor, parse_sim_script("sim:fixed:20,40"), unpaced());
  SourceFrame frame, untouched;
  ASSERT_TRUE(twin.next(untouched, std::chrono::seconds(30)));
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(twin.next(frame, std::chrono::seconds(30)));  // past the untouched frames
  Frame pressed = frame.volts;
  pressed.col(5).setZero();
  constexpr int capture = 40, pressed_count = 30;
  TwoFrameSource source(untouched.volts, pressed, capture, pressed_count);
  LiveLoop loop(source, paper);
  HealthWatcher watcher;
  loop.add_publisher(&watcher);
  const std::atomic<bool> stop{false};
  const LiveStats stats = loop.run(stop);
  ASSERT_EQ(watcher.dead.size(), static_cast<std::size_t>(capture + pressed_count));
  const auto first_reconstructed = static_cast<std::size_t>(stats.capture_frames);
  EXPECT_TRUE(watcher.dead[first_reconstructed + 23].empty());  // 24 pressed frames: the window is not full
  ASSERT_EQ(watcher.dead.back().size(), 1u);
  EXPECT_EQ(watcher.dead.back()[0].electrode, 5);
  EXPECT_NE(watcher.dead.back()[0].reason.find("reads 0 V as the sensed electrode"), std::string::npos);
  EXPECT_LT(watcher.misfit_mV.back(), 0);
}

// A WebSocket client as the page is one: the mesh first, then frames (binary: header + one float
// per triangle); its "recapture" reaches the loop, which captures the baseline again.
TEST(LiveServer, SendsMeshAndFramesAndTakesCommands) {
  namespace beast = boost::beast;
  namespace net = boost::asio;
  LiveBench& b = bench();
  SimSource source(b.sensor, parse_sim_script("sim:fixed:20,40"), unpaced());
  LiveLoop loop(source, b.pipeline);
  LiveServer server("127.0.0.1:0", b.pipeline.model().mesh, {b.sensor.name},
                    [&](const std::string& c) { loop.command(c); });
  loop.add_publisher(&server);
  std::atomic<bool> stop{false};
  std::thread runner([&] { loop.run(stop); });

  net::io_context io;
  net::ip::tcp::socket socket(io);
  socket.connect({net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(server.port())});
  beast::websocket::stream<net::ip::tcp::socket> ws(std::move(socket));
  ws.handshake("127.0.0.1", "/ws");
  beast::flat_buffer buffer;
  ws.read(buffer);
  ASSERT_TRUE(ws.got_text());
  const auto mesh = nlohmann::json::parse(beast::buffers_to_string(buffer.data()));
  buffer.consume(buffer.size());
  EXPECT_EQ(mesh["type"], "mesh");
  const auto triangles = static_cast<std::size_t>(b.pipeline.model().mesh.triangle_count());
  EXPECT_EQ(mesh["triangles"].size(), 3 * triangles);
  EXPECT_EQ(mesh["electrodes"].size(), 16u);

  auto read_frame = [&] {
    ws.read(buffer);
    EXPECT_TRUE(ws.got_binary());
    const std::string bytes = beast::buffers_to_string(buffer.data());
    buffer.consume(buffer.size());
    ws.text(true);
    ws.write(net::buffer(std::string("ack")));  // the next frame may come
    std::uint32_t header = 0;
    std::memcpy(&header, bytes.data(), 4);
    EXPECT_EQ(bytes.size(),
              4 + header + 4 * (triangles + std::size_t{16} * 16));  // pressure, then the 16 × 16 readings
    return nlohmann::json::parse(bytes.substr(4, header));
  };
  nlohmann::json frame;
  do frame = read_frame();
  while (frame["capturing_baseline"].get<bool>() || frame["contacts"].empty());
  EXPECT_NEAR(frame["contacts"][0]["x_mm"].get<double>(), 20, live_fit_tolerance_mm);
  EXPECT_NEAR(frame["contacts"][0]["y_mm"].get<double>(), 40, live_fit_tolerance_mm);
  EXPECT_EQ(frame["baseline_captures"], 1);
  // The fit's misfit: the twin's ADC noise (1 mV: sensor "adc") and the twin's other mesh, a few mV at most.
  EXPECT_GE(frame["misfit_mV"].get<double>(), 0);
  EXPECT_LT(frame["misfit_mV"].get<double>(), 5);
  EXPECT_EQ(frame["contacts"][0]["id"], 0);  // the tracker's first touch

  ws.write(net::buffer(std::string("recapture")));
  do frame = read_frame();
  while (frame["baseline_captures"].get<int>() != 2);
  EXPECT_EQ(frame["commands"], 1);
  EXPECT_EQ(server.commands_received(), 1u);

  // The client goes away; the loop keeps going and the server forgets it.
  ws.close(beast::websocket::close_code::normal);
  for (int wait = 0; wait < 200 && server.clients() > 0; ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(server.clients(), 0u);
  stop = true;
  runner.join();
}

TEST(LiveServer, PortInUseIsAClearError) {
  const Mesh& mesh = bench().pipeline.model().mesh;
  LiveServer first("127.0.0.1:0", mesh, {"a"}, {});
  try {
    LiveServer second("127.0.0.1:" + std::to_string(first.port()), mesh, {"b"}, {});
    FAIL() << "a second server on the same port";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("in use"), std::string::npos) << e.what();
  }
  EXPECT_THROW(LiveServer("127.0.0.1", mesh, {"c"}, {}), InvalidInput);
  EXPECT_THROW(LiveServer("127.0.0.1:99999", mesh, {"c"}, {}), InvalidInput);
}

}  // namespace
}  // namespace emit
