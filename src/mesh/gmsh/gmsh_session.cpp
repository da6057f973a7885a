#include "gmsh_session.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>

#include <gmsh.h>

#include "emit/core/errors.hpp"
#include "emit/mesh/sort_for_locality.hpp"

namespace emit::detail {

std::mutex& GmshSession::mutex() {
  static std::mutex m;
  return m;
}

GmshSession::GmshSession() : lock_(mutex()) {
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.Verbosity", 1);  // errors only
  gmsh::logger::start();
}

GmshSession::~GmshSession() {
  try {
    gmsh::logger::stop();
    gmsh::finalize();
  } catch (...) {
  }
}

std::string GmshSession::last_error() {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  // The last error first.
  const auto line =
      std::find_if(log.rbegin(), log.rend(), [](const std::string& l) { return l.rfind("Error", 0) == 0; });
  if (line == log.rend()) return {};
  std::string message = line->substr(line->find(':') == std::string::npos ? 0 : line->find(':') + 1);
  message.erase(0, message.find_first_not_of(' '));
  return message;
}

namespace {

/// The electrode number in a physical group's name "electrode <i>" (any case), if it is one.
std::optional<int> electrode_number(const std::string& name) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string prefix = "electrode";
  const auto start = lower.find_first_not_of(' ');
  if (start == std::string::npos || lower.compare(start, prefix.size(), prefix) != 0) return std::nullopt;
  const auto digits = lower.find_first_not_of(' ', start + prefix.size());
  const auto end = lower.find_last_not_of(' ');
  if (digits == std::string::npos || digits > end) return std::nullopt;
  const std::string number = lower.substr(digits, end - digits + 1);
  if (number.size() > 6 || number.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  return std::stoi(number);
}

}  // namespace

Mesh GmshSession::extract_mesh(const std::string& context, bool electrodes_required) {
  // Gmsh's calls below throw std::string (not std::exception) on failure: each becomes emit's error.
  try {
    return extract_mesh_unchecked(context, electrodes_required);
  } catch (const Error&) {
    throw;
  } catch (...) {
    throw InvalidInput(context + ": " + last_error());
  }
}

Mesh GmshSession::extract_mesh_unchecked(const std::string& context, bool electrodes_required) {
  std::vector<std::size_t> element_tags, triangle_node_tags;
  gmsh::model::mesh::getElementsByType(2, element_tags, triangle_node_tags);
  if (element_tags.empty()) throw InvalidInput(context + ": the mesh has no 3-node triangles");

  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, /*includeBoundary=*/true,
                              /*returnParametricCoord=*/false);
  // Gmsh numbers nodes about 1..count, so tables indexed by tag replace ordered maps (which
  // were a tenth of the meshing time at 23k triangles).
  constexpr Index none = -1;
  const std::size_t max_tag = node_tags.empty() ? 0 : *std::max_element(node_tags.begin(), node_tags.end());
  std::vector<Index> coord_row(max_tag + 1, none);
  for (std::size_t i = 0; i < node_tags.size(); ++i) coord_row[node_tags[i]] = static_cast<Index>(i);

  // Number the nodes the triangles use, in order of first use.
  std::vector<int> index_of(max_tag + 1, -1);
  std::vector<std::size_t> tag_of_index;
  Mesh mesh;
  mesh.triangles.resize(static_cast<Index>(element_tags.size()), 3);
  for (std::size_t t = 0; t < element_tags.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::size_t tag = triangle_node_tags[3 * t + k];
      if (tag > max_tag || coord_row[tag] == none)
        throw InvalidInput(context + ": triangle refers to missing node " + std::to_string(tag));
      if (index_of[tag] < 0) {
        index_of[tag] = static_cast<int>(tag_of_index.size());
        tag_of_index.push_back(tag);
      }
      mesh.triangles(static_cast<Index>(t), k) = index_of[tag];
    }
  mesh.nodes_mm.resize(static_cast<Index>(tag_of_index.size()), 3);
  for (std::size_t index = 0; index < tag_of_index.size(); ++index)
    for (int c = 0; c < 3; ++c)
      mesh.nodes_mm(static_cast<Index>(index), c) =
          coords[3 * static_cast<std::size_t>(coord_row[tag_of_index[index]]) + c];

  // A flat sheet's triangles all face +z.
  if (mesh.nodes_mm.col(2).cwiseAbs().maxCoeff() == 0.0)
    for (Index t = 0; t < mesh.triangle_count(); ++t) {
      const Vector3 a = mesh.nodes_mm.row(mesh.triangles(t, 0)), b = mesh.nodes_mm.row(mesh.triangles(t, 1)),
                    c = mesh.nodes_mm.row(mesh.triangles(t, 2));
      if ((b - a).cross(c - a).z() < 0) std::swap(mesh.triangles(t, 1), mesh.triangles(t, 2));
    }

  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 1);
  std::map<int, std::vector<int>> electrodes;
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    const auto number = electrode_number(name);
    if (!number) continue;
    std::vector<std::size_t> tags;
    std::vector<double> group_coords;
    gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, tags, group_coords);
    std::vector<int>& nodes = electrodes[*number];
    for (std::size_t t : tags)
      if (t < index_of.size() && index_of[t] >= 0) nodes.push_back(index_of[t]);
    std::sort(nodes.begin(), nodes.end());
  }
  if (electrodes.empty() && electrodes_required)
    throw InvalidInput(context + ": no physical curves named \"electrode 0\", \"electrode 1\", …");
  for (int e = 0; e < static_cast<int>(electrodes.size()); ++e) {
    if (!electrodes.count(e))
      throw InvalidInput(context + ": electrode groups must be numbered 0.." + std::to_string(electrodes.size() - 1) +
                         "; \"electrode " + std::to_string(e) + "\" is missing");
    if (electrodes[e].size() < 2)
      throw InvalidInput(context + ": \"electrode " + std::to_string(e) + "\" has fewer than 2 mesh nodes");
    mesh.electrode_nodes.push_back(electrodes[e]);
  }
  return sort_for_locality(mesh);
}

}  // namespace emit::detail
