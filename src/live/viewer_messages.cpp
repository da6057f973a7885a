#include "emit/live/viewer_messages.hpp"

#include <bit>
#include <cstring>

#include <nlohmann/json.hpp>

#include "emit/mesh/flatness.hpp"

namespace emit {

namespace {

using json = nlohmann::json;

void append_segment(json& out, const Mesh& mesh, const std::array<int, 2>& edge) {
  for (int node : edge) {
    out.push_back(mesh.nodes_mm(node, 0));
    out.push_back(mesh.nodes_mm(node, 1));
  }
}

void append_segment_z(json& out, const Mesh& mesh, const std::array<int, 2>& edge) {
  for (int node : edge) out.push_back(mesh.nodes_mm(node, 2));
}

}  // namespace

bool viewer_draws_in_3d(const Mesh& mesh) { return !is_flat(mesh); }

std::string mesh_message(const Mesh& mesh, const ViewerSheet& sheet) {
  const bool curved = viewer_draws_in_3d(mesh);
  json nodes = json::array(), triangles = json::array(), outline = json::array(), electrodes = json::array();
  json nodes_z = json::array(), outline_z = json::array();
  for (Index v = 0; v < mesh.node_count(); ++v) {
    nodes.push_back(mesh.nodes_mm(v, 0));
    nodes.push_back(mesh.nodes_mm(v, 1));
    if (curved) nodes_z.push_back(mesh.nodes_mm(v, 2));
  }
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) triangles.push_back(mesh.triangles(t, k));
  for (const auto& edge : mesh.border_edges()) {
    append_segment(outline, mesh, edge);
    if (curved) append_segment_z(outline_z, mesh, edge);
  }
  for (int e = 0; e < mesh.electrode_count(); ++e) {
    json segments = json::array(), segments_z = json::array();
    for (const auto& edge : mesh.electrode_edges(e)) {
      append_segment(segments, mesh, edge);
      if (curved) append_segment_z(segments_z, mesh, edge);
    }
    Vector3 center(0, 0, 0);
    for (int node : mesh.electrode_nodes[e]) center += mesh.nodes_mm.row(node).transpose();
    center /= std::max<double>(1.0, static_cast<double>(mesh.electrode_nodes[e].size()));
    json electrode = {{"segments_mm", segments}, {"x_mm", center.x()}, {"y_mm", center.y()}};
    if (curved) {
      electrode["segments_z_mm"] = segments_z;
      electrode["z_mm"] = center.z();
    }
    electrodes.push_back(std::move(electrode));
  }
  json message = {{"type", "mesh"},
                  {"name", sheet.name},
                  {"calibrated", sheet.calibrated},
                  {"pressure_range_N_per_mm2", sheet.pressure_range_N_per_mm2},
                  {"adc_reference_V", sheet.adc_reference_V},
                  {"nodes_mm", nodes},
                  {"triangles", triangles},
                  {"outline_mm", outline},
                  {"electrodes", electrodes}};
  if (curved) {
    message["nodes_z_mm"] = nodes_z;
    message["outline_z_mm"] = outline_z;
  }
  return message.dump();
}

std::string frame_message(const LiveFrame& frame, std::uint64_t commands, bool curved) {
  static_assert(std::endian::native == std::endian::little, "the frame message is little-endian");
  json contacts = json::array();
  for (const Contact& c : *frame.contacts) {
    json contact = {{"id", c.id},
                    {"x_mm", c.x_mm},
                    {"y_mm", c.y_mm},
                    {"area_mm2", c.area_mm2},
                    {"pressure_N_per_mm2", c.pressure_N_per_mm2},
                    {"force_N", c.force_N}};
    if (c.semi_major_mm > 0) {  // the outline's ellipse, as the JSON Lines name it
      contact["semi_major_mm"] = c.semi_major_mm;
      contact["semi_minor_mm"] = c.semi_minor_mm;
      contact["orientation_deg"] = c.orientation_deg;
    }
    if (!c.outline.empty()) {  // its polygon in the sheet's chart, as the JSON Lines name it
      json outline = json::array();
      for (int k = 0; k < c.outline.size; ++k) {
        const Vector2 p = c.outline.vertex_mm(k);
        outline.push_back({p.x(), p.y()});
      }
      contact["outline_mm"] = std::move(outline);
    }
    if (curved) {
      contact["z_mm"] = c.z_mm;
      contact["normal"] = {c.nx, c.ny, c.nz};
    }
    contacts.push_back(std::move(contact));
  }
  json dead = json::array();
  if (frame.dead_electrodes)
    for (const DeadElectrode& d : *frame.dead_electrodes)
      dead.push_back({{"electrode", d.electrode}, {"reason", d.reason}});
  json swapped = json::array();
  if (frame.swapped_electrodes)
    for (const SwappedElectrodes& w : *frame.swapped_electrodes)
      swapped.push_back({{"electrodes", {w.a, w.b}}, {"reason", w.reason}});
  const Vector& pressure = *frame.pressure_N_per_mm2;
  const Index readings = frame.volts ? frame.volts->size() : 0;
  std::string header = json{{"type", "frame"},
                            {"index", frame.index},
                            {"sequence", frame.sequence},
                            {"board_time_s", frame.board_time_s},
                            {"capturing_baseline", frame.capturing_reference},
                            {"baseline_captures", frame.reference_captures},
                            {"commands", commands},
                            {"frames_per_s", frame.frames_per_s},
                            {"latency_ms", 1e3 * frame.latency_s},
                            {"frames_missed", frame.frames_missed},
                            {"misfit_mV", frame.misfit_mV},
                            {"readings_masked", frame.readings_masked},
                            {"dead_electrodes", dead},
                            {"swapped_electrodes", swapped},
                            {"electrode_count", frame.volts ? frame.volts->rows() : 0},
                            {"max_pressure_N_per_mm2", pressure.size() ? pressure.maxCoeff() : 0.0},
                            {"contacts", contacts}}
                           .dump();
  header.append((4 - header.size() % 4) % 4, ' ');
  const auto header_bytes = static_cast<std::uint32_t>(header.size());
  std::string message(4 + header.size() + 4 * static_cast<std::size_t>(pressure.size() + readings), '\0');
  std::memcpy(message.data(), &header_bytes, 4);
  std::memcpy(message.data() + 4, header.data(), header.size());
  char* values = message.data() + 4 + header.size();
  const auto put = [&values](double v) {
    const auto value = static_cast<float>(v);
    std::memcpy(values, &value, 4);
    values += 4;
  };
  for (Index t = 0; t < pressure.size(); ++t) put(pressure[t]);
  for (Index k = 0; k < readings; ++k) put(frame.volts->data()[k]);  // row-major: ground l, sense m
  return message;
}

}  // namespace emit
