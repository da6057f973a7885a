// A Cyclone DDS subscriber, as a ROS 2 node with the Cyclone RMW subscribes, for `emit live --dds`:
// it joins the domain, subscribes to every topic emit publishes (rt/PREFIX/contacts, /mesh, /frames,
// /pressure, /pressure_cloud) with ROS 2's type
// names, starts `emit live … --dds PREFIX --dds-domain D` and checks what arrives: every frame's
// contacts, in order, none lost (the source's frame numbers run on by one), with the right
// contents (a held press found where it is; nothing on the twin's untouched frames; every field of
// every contact as the JSON Lines emit writes in the same run, `--contacts`, say), and the mesh.
// With --elongated ANGLE_DEG (a held bar, `--source sim:fixed:bar:…`), every touched frame's
// strongest contact must also be an ellipse twice as long as wide along the bar, within 10°.
// It prints the publish-to-receive latency (receive time − the header's stamp, one clock).
//
//   emit_dds_check EMIT DOMAIN PREFIX FRAMES X_MM Y_MM [--elongated ANGLE_DEG] [emit live's other arguments…]
//
// Exit 0 when every check holds; 1, naming the first that failed.
#include <dds/dds.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "emit_ros2.h"

extern char** environ;

namespace {

std::uint64_t now_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
}

int fail(const std::string& what) {
  std::fprintf(stderr, "dds_check: FAIL: %s\n", what.c_str());
  return 1;
}

dds_entity_t reader(dds_entity_t participant, const std::string& topic, const dds_topic_descriptor_t* type) {
  const dds_entity_t t = dds_create_topic(participant, type, topic.c_str(), nullptr, nullptr);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  const dds_entity_t r = dds_create_reader(participant, t, qos, nullptr);
  dds_delete_qos(qos);
  return r;
}

/// A contact's numbers as the message carries them, in the order of json_keys below, then its
/// outline's points' x and y [m] (a polygon's Point32s; z 0 on these flat sheets).
constexpr int field_count = 21;
using Fields = std::vector<double>;

Fields fields_of(const emit_msgs_msg_dds__TactileContact_& c) {
  Fields fields = {c.position.x,
                   c.position.y,
                   c.position.z,
                   c.normal.x,
                   c.normal.y,
                   c.normal.z,
                   c.area,
                   c.pressure,
                   c.peak_pressure,
                   -c.wrench.force.z,
                   c.position_std_x,
                   c.position_std_y,
                   c.pressure_std,
                   c.force_std,
                   c.semi_major_m,
                   c.semi_minor_m,
                   c.orientation_rad,
                   c.area_std_m2,
                   c.orientation_std_rad,
                   c.velocity.x,
                   c.velocity.y};
  for (std::uint32_t k = 0; k < c.outline.points._length; ++k) {
    fields.push_back(c.outline.points._buffer[k].x);
    fields.push_back(c.outline.points._buffer[k].y);
  }
  return fields;
}

/// The same from the JSON Lines (src/io/contacts_jsonl.cpp; an absent key is 0, the normal's z 1),
/// in SI units. The wrench's z is −force·nz: on the flat sheets this is run on, nz = 1.
struct JsonKey {
  const char* key;
  double scale, absent;
};
constexpr JsonKey json_keys[field_count] = {
    {"x_mm", 1e-3, 0},
    {"y_mm", 1e-3, 0},
    {"z_mm", 1e-3, 0},
    {"nx", 1, 0},
    {"ny", 1, 0},
    {"nz", 1, 1},
    {"area_mm2", 1e-6, 0},
    {"pressure_N_per_mm2", 1e6, 0},
    {"peak_pressure_N_per_mm2", 1e6, 0},
    {"force_N", 1, 0},
    {"x_std_mm", 1e-3, 0},
    {"y_std_mm", 1e-3, 0},
    {"pressure_std_N_per_mm2", 1e6, 0},
    {"force_std_N", 1, 0},
    {"semi_major_mm", 1e-3, 0},
    {"semi_minor_mm", 1e-3, 0},
    {"orientation_deg", std::numbers::pi / 180, 0},
    {"area_std_mm2", 1e-6, 0},
    {"orientation_std_deg", std::numbers::pi / 180, 0},
    {"vx_mm_per_s", 1e-3, 0},
    {"vy_mm_per_s", 1e-3, 0},
};

/// JSON Lines carry 6 significant digits (%.6g): within 5e-6 relative of the double sent (and
/// the outline's float32 points 6e-8 of theirs).
bool agree(double a, double b) { return std::abs(a - b) <= 1e-5 * std::max(std::abs(a), std::abs(b)) + 1e-15; }

/// Every frame's contacts in the JSON Lines file, by frame number; its board time into `board_times`.
std::map<std::uint64_t, std::vector<Fields>> read_json_lines(const std::string& path,
                                                             std::map<std::uint64_t, double>& board_times) {
  std::map<std::uint64_t, std::vector<Fields>> frames;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    const nlohmann::json j = nlohmann::json::parse(line);
    board_times[j.at("frame").get<std::uint64_t>()] = j.at("board_time_s").get<double>();
    std::vector<Fields>& contacts = frames[j.at("frame").get<std::uint64_t>()];
    for (const nlohmann::json& c : j.at("contacts")) {
      Fields f(field_count);
      for (int k = 0; k < field_count; ++k)
        f[static_cast<std::size_t>(k)] = json_keys[k].scale * c.value(json_keys[k].key, json_keys[k].absent);
      if (c.contains("outline_mm"))
        for (const nlohmann::json& vertex : c.at("outline_mm")) {
          f.push_back(1e-3 * vertex.at(0).get<double>());
          f.push_back(1e-3 * vertex.at(1).get<double>());
        }
      contacts.push_back(f);
    }
  }
  return frames;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 7) {
    std::fprintf(stderr,
                 "usage: emit_dds_check EMIT DOMAIN PREFIX FRAMES X_MM Y_MM [--elongated ANGLE_DEG] "
                 "[emit live's arguments…]\n");
    return 2;
  }
  const std::string emit = argv[1], prefix = argv[3];
  double given[4];  // domain, frames, x, y
  for (int i = 0; i < 4; ++i) {
    const char* text = argv[i == 0 ? 2 : i + 3];
    char* end = nullptr;
    given[i] = std::strtod(text, &end);
    if (end == text || *end != '\0') return fail(std::string("not a number: \"") + text + "\"");
  }
  const auto domain = static_cast<int>(given[0]);
  const auto frames = static_cast<long>(given[1]);
  const double x_m = 1e-3 * given[2], y_m = 1e-3 * given[3];
  int rest = 7;
  double bar_deg = std::numeric_limits<double>::quiet_NaN();
  if (argc > rest + 1 && std::string(argv[rest]) == "--elongated") {
    char* end = nullptr;
    bar_deg = std::strtod(argv[rest + 1], &end);
    if (end == argv[rest + 1] || *end != '\0') return fail(std::string("not an angle: \"") + argv[rest + 1] + "\"");
    rest += 2;
  }
  // The header's frame: emit live's --frame-id among its arguments, else its default.
  std::string frame_id = "emit_sheet";
  for (int i = rest; i + 1 < argc; ++i)
    if (std::string(argv[i]) == "--frame-id") frame_id = argv[i + 1];
  // The JSON Lines emit writes beside DDS, to compare every field with.
  char json_path[] = "/tmp/emit_dds_check_XXXXXX";
  const int json_file = mkstemp(json_path);
  if (json_file < 0) return fail("creating a temporary file");
  close(json_file);

  const dds_entity_t participant = dds_create_participant(static_cast<dds_domainid_t>(domain), nullptr, nullptr);
  if (participant < 0) return fail(std::string("joining the domain: ") + dds_strretcode(participant));
  const dds_entity_t contacts =
      reader(participant, "rt/" + prefix + "/contacts", &emit_msgs_msg_dds__TactileContacts__desc);
  const dds_entity_t mesh = reader(participant, "rt/" + prefix + "/mesh", &shape_msgs_msg_dds__Mesh__desc);
  const dds_entity_t states = reader(participant, "rt/" + prefix + "/frames", &emit_msgs_msg_dds__TactileState__desc);
  const dds_entity_t images =
      reader(participant, "rt/" + prefix + "/pressure", &emit_msgs_msg_dds__PressureImage__desc);
  const dds_entity_t clouds =
      reader(participant, "rt/" + prefix + "/pressure_cloud", &sensor_msgs_msg_dds__PointCloud2__desc);
  if (contacts < 0 || mesh < 0 || states < 0 || images < 0 || clouds < 0) return fail("creating the readers");

  std::vector<std::string> args = {emit,           "live",
                                   "--dds",        prefix,
                                   "--dds-domain", std::to_string(domain),
                                   "--frames",     std::to_string(frames),
                                   "--contacts",   json_path};
  for (int i = rest; i < argc; ++i) args.emplace_back(argv[i]);
  std::vector<char*> child_argv;
  child_argv.reserve(args.size() + 1);
  for (std::string& a : args) child_argv.push_back(a.data());
  child_argv.push_back(nullptr);
  pid_t child = 0;
  if (posix_spawn(&child, emit.c_str(), nullptr, nullptr, child_argv.data(), environ) != 0)
    return fail("starting emit");

  // Take the contacts as they come, until all frames are in or the publisher has ended and
  // nothing more arrives.
  std::vector<std::uint64_t> numbers;
  std::map<std::uint64_t, std::vector<Fields>> received_contacts;
  std::map<std::uint64_t, double> received_board_times, written_board_times;
  long elongated = 0;
  std::vector<double> latency_ms;
  std::string problem;
  long touched = 0, outlined = 0;
  int status = -1;
  bool exited = false;
  auto quiet_since = std::chrono::steady_clock::now();
  const dds_entity_t waitset = dds_create_waitset(participant);
  const dds_entity_t condition = dds_create_readcondition(contacts, DDS_ANY_STATE);
  dds_waitset_attach(waitset, condition, 0);
  while (static_cast<long>(numbers.size()) < frames) {
    dds_waitset_wait(waitset, nullptr, 0, DDS_MSECS(100));
    void* samples[64] = {};
    dds_sample_info_t infos[64];
    const int n = dds_take(contacts, samples, infos, 64, 64);
    const std::uint64_t received = now_ns();
    for (int i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const auto* m = static_cast<const emit_msgs_msg_dds__TactileContacts_*>(samples[i]);
      const std::uint64_t stamp =
          static_cast<std::uint64_t>(m->header.stamp.sec) * 1'000'000'000u + m->header.stamp.nanosec;
      latency_ms.push_back(1e-6 * static_cast<double>(received - stamp));
      numbers.push_back(m->frame);
      received_board_times[m->frame] = m->board_time;
      std::vector<Fields>& kept = received_contacts[m->frame];
      for (std::uint32_t c = 0; c < m->contacts._length; ++c) kept.push_back(fields_of(m->contacts._buffer[c]));
      if (problem.empty() && std::string(m->header.frame_id) != frame_id) problem = "header.frame_id";
      // The twin's first 15 frames are untouched; the press is found within the paper method's
      // p95 on this sheet, 8.05 mm (README).
      if (m->frame < 15 && m->contacts._length != 0 && problem.empty())
        problem = "a contact on untouched frame " + std::to_string(m->frame);
      if (m->frame >= 15) {
        ++touched;
        const bool found = m->contacts._length >= 1 && std::hypot(m->contacts._buffer[0].position.x - x_m,
                                                                  m->contacts._buffer[0].position.y - y_m) < 8.05e-3;
        if (!found && problem.empty()) problem = "the press not found on frame " + std::to_string(m->frame);
        // Its outline: a counter-clockwise polygon (positive area) about the press.
        if (found) {
          const auto& points = m->contacts._buffer[0].outline.points;
          double twice_area = 0;
          for (std::uint32_t k = 0, j = points._length - 1; k < points._length; j = k++)
            twice_area +=
                double{points._buffer[j].x} * points._buffer[k].y - double{points._buffer[k].x} * points._buffer[j].y;
          if (points._length >= 3 && twice_area > 0) ++outlined;
          else if (problem.empty())
            problem = "frame " + std::to_string(m->frame) + "'s contact has no counter-clockwise outline (" +
                      std::to_string(points._length) + " points)";
        }
        if (found && std::isfinite(bar_deg)) {
          // A bar's outline is far longer than wide (24 × 4 mm: its second moments' ellipse is 6
          // times); twice, along the bar within the 10°, is what the frame must show.
          const auto& c = m->contacts._buffer[0];
          const double off_deg =
              std::remainder(c.orientation_rad * 180 / std::numbers::pi - bar_deg, 180.0);  // an axis: mod 180°
          if (c.semi_major_m >= 2 * c.semi_minor_m && c.semi_minor_m > 0 && std::abs(off_deg) <= 10) ++elongated;
          else if (problem.empty())
            problem = "frame " + std::to_string(m->frame) + "'s contact is not the bar's ellipse: semi-axes " +
                      std::to_string(1e3 * c.semi_major_m) + " and " + std::to_string(1e3 * c.semi_minor_m) + " mm, " +
                      std::to_string(off_deg) + " deg off its angle";
        }
      }
    }
    if (n > 0) {
      dds_return_loan(contacts, samples, n);
      quiet_since = std::chrono::steady_clock::now();
    }
    if (!exited && waitpid(child, &status, WNOHANG) == child) exited = true;
    if (exited && std::chrono::steady_clock::now() - quiet_since > std::chrono::seconds(5)) break;
  }
  if (!exited) waitpid(child, &status, 0);

  // The other types published every frame, decoded: the raw frame (N × N volts), the pressure
  // image (a float per triangle) and its cloud (a point per triangle, the image's pressure), each
  // frame's three matched by their header's stamp.
  std::map<std::uint64_t, std::vector<float>> image_of, cloud_of;  // by stamp [ns]
  long state_count = 0;
  const auto stamp_of = [](const std_msgs_msg_dds__Header_& h) {
    return static_cast<std::uint64_t>(h.stamp.sec) * 1'000'000'000u + h.stamp.nanosec;
  };
  for (auto waited = std::chrono::steady_clock::now();
       (state_count < frames || static_cast<long>(image_of.size()) < frames ||
        static_cast<long>(cloud_of.size()) < frames) &&
       std::chrono::steady_clock::now() - waited < std::chrono::seconds(5);) {
    void* samples[16] = {};
    dds_sample_info_t infos[16];
    int n = dds_take(states, samples, infos, 16, 16);
    for (int i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const auto* m = static_cast<const emit_msgs_msg_dds__TactileState_*>(samples[i]);
      ++state_count;
      if (problem.empty() && (m->sensors._length != 1 || m->sensors._buffer[0].values._length != 16 * 16))
        problem = "a raw frame without one sensor's 16 x 16 readings";
    }
    if (n > 0) dds_return_loan(states, samples, n);
    n = dds_take(images, samples, infos, 16, 16);
    for (int i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const auto* m = static_cast<const emit_msgs_msg_dds__PressureImage_*>(samples[i]);
      image_of[stamp_of(m->header)].assign(m->pressure._buffer, m->pressure._buffer + m->pressure._length);
    }
    if (n > 0) dds_return_loan(images, samples, n);
    n = dds_take(clouds, samples, infos, 16, 16);
    for (int i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const auto* m = static_cast<const sensor_msgs_msg_dds__PointCloud2_*>(samples[i]);
      const bool laid_out = m->height == 1 && m->point_step == 16 && m->row_step == 16 * m->width &&
                            m->data._length == 16 * m->width && !m->is_bigendian && m->fields._length == 4 &&
                            std::string(m->fields._buffer[3].name) == "pressure" && m->fields._buffer[3].offset == 12 &&
                            m->fields._buffer[3].datatype == 7;
      if (!laid_out && problem.empty()) problem = "a pressure cloud not laid out as x, y, z, pressure float32";
      std::vector<float>& pressure = cloud_of[stamp_of(m->header)];
      pressure.resize(m->width);
      for (std::uint32_t k = 0; laid_out && k < m->width; ++k)
        std::memcpy(&pressure[k], m->data._buffer + std::size_t{16} * k + 12, 4);
    }
    if (n > 0) dds_return_loan(clouds, samples, n);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  long clouds_matched = 0;
  for (const auto& [stamp, pressure] : cloud_of) {
    const auto image = image_of.find(stamp);
    if (image != image_of.end() && image->second == pressure && !pressure.empty()) ++clouds_matched;
    else if (problem.empty()) problem = "a pressure cloud whose pressures are not its frame's image's";
  }

  // The mesh, kept for late subscribers (transient-local): the 60 × 60 mm sheet, 3.6e-3 m².
  double area_m2 = 0;
  std::uint32_t mesh_triangles = 0;
  {
    void* samples[1] = {};
    dds_sample_info_t infos[1];
    if (dds_take(mesh, samples, infos, 1, 1) == 1 && infos[0].valid_data) {
      const auto* m = static_cast<const shape_msgs_msg_dds__Mesh_*>(samples[0]);
      mesh_triangles = m->triangles._length;
      for (std::uint32_t t = 0; t < m->triangles._length; ++t) {
        const std::uint32_t* v = m->triangles._buffer[t].vertex_indices;
        const auto& a = m->vertices._buffer[v[0]];
        const auto& b = m->vertices._buffer[v[1]];
        const auto& c = m->vertices._buffer[v[2]];
        area_m2 += std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2;
      }
      dds_return_loan(mesh, samples, 1);
    }
  }
  dds_delete(participant);

  // Every field of every contact received, as the JSON Lines say.
  std::map<std::uint64_t, std::vector<Fields>> written;
  try {
    written = read_json_lines(json_path, written_board_times);
  } catch (const std::exception& e) {
    std::remove(json_path);
    return fail(std::string("reading the JSON Lines: ") + e.what());
  }
  std::remove(json_path);
  long compared = 0;
  for (const auto& [frame, board_time] : received_board_times) {  // %.9g in the JSON Lines
    const auto line = written_board_times.find(frame);
    if ((line == written_board_times.end() || std::abs(line->second - board_time) > 1e-8 * (1 + board_time)) &&
        problem.empty())
      problem = "frame " + std::to_string(frame) + "'s board time is not the JSON Lines'";
  }
  for (const auto& [frame, contacts_received] : received_contacts) {
    const auto line = written.find(frame);
    if (line == written.end() || line->second.size() != contacts_received.size()) {
      if (problem.empty()) problem = "frame " + std::to_string(frame) + "'s contacts are not the JSON Lines'";
      continue;
    }
    for (std::size_t c = 0; c < contacts_received.size(); ++c) {
      if (contacts_received[c].size() != line->second[c].size()) {
        if (problem.empty())
          problem = "frame " + std::to_string(frame) + " contact " + std::to_string(c) + "'s outline has " +
                    std::to_string((contacts_received[c].size() - field_count) / 2) + " points, the JSON Lines' " +
                    std::to_string((line->second[c].size() - field_count) / 2);
        continue;
      }
      for (std::size_t k = 0; k < contacts_received[c].size(); ++k) {
        const double a = contacts_received[c][static_cast<std::size_t>(k)],
                     b = line->second[c][static_cast<std::size_t>(k)];
        if (!agree(a, b) && problem.empty())
          problem =
              "frame " + std::to_string(frame) + " contact " + std::to_string(c) + "'s " +
              (k < std::size_t{field_count} ? std::string(json_keys[k].key)
                                            : "outline_mm value " + std::to_string(k - std::size_t{field_count})) +
              ": " + std::to_string(a) + " (SI) against the JSON Lines' " + std::to_string(b);
        ++compared;
      }
    }
  }

  std::vector<double> sorted = latency_ms;
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&](double q) {
    return sorted.empty() ? 0.0 : sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))];
  };
  long out_of_order = 0;
  for (std::size_t i = 1; i < numbers.size(); ++i) out_of_order += numbers[i] != numbers[i - 1] + 1;
  std::printf(
      "dds_check: %zu of %ld frames' contacts received, %ld out of order or missing between, first %llu; "
      "latency p50 %.3f ms, p95 %.3f ms, max %.3f ms; mesh %.6g m^2; %ld contact fields (outlines' points "
      "included) as in the JSON Lines; %ld touched frames' contact outlined%s; %ld raw frames, %zu pressure images, "
      "%ld pressure clouds as their images\n",
      numbers.size(), frames, out_of_order, numbers.empty() ? 0ULL : static_cast<unsigned long long>(numbers[0]),
      at(0.5), at(0.95), sorted.empty() ? 0.0 : sorted.back(), area_m2, compared, outlined,
      std::isfinite(bar_deg) ? (", " + std::to_string(elongated) + " touched frames' contact the bar's ellipse").c_str()
                             : "",
      state_count, image_of.size(), clouds_matched);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return fail("emit live exited with " + std::to_string(status));
  if (static_cast<long>(numbers.size()) != frames) return fail("frames lost");
  if (out_of_order != 0) return fail("frames out of order");
  if (numbers[0] != 10) return fail("the first frame is not the one after the baseline's 10");
  if (!problem.empty()) return fail(problem);
  if (touched == 0) return fail("no touched frame");
  if (compared == 0) return fail("no contact to compare with the JSON Lines");
  if (outlined != touched) return fail("not every touched frame's contact outlined");
  if (std::isfinite(bar_deg) && elongated != touched) return fail("not every touched frame's contact the bar's");
  if (std::abs(area_m2 - 3.6e-3) > 1e-9) return fail("the mesh's area");
  if (state_count != frames || static_cast<long>(image_of.size()) != frames || clouds_matched != frames)
    return fail("not every frame's raw frame, pressure image and pressure cloud received");
  for (const auto& [stamp, pressure] : image_of)
    if (pressure.size() != mesh_triangles) return fail("a pressure image without a value per triangle of the mesh");
  return 0;
}
