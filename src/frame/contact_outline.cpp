#include "emit/frame/contact_outline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <utility>

#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

double cross(const Vector2& a, const Vector2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Twice the signed area of triangle abc.
double twice_area(const Vector2& a, const Vector2& b, const Vector2& c) { return cross(b - a, c - a); }

/// The shoelace formula over a closed polygon [mm²], positive counter-clockwise.
double shoelace(const Vector2* points, std::size_t n) {
  double sum = 0;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) sum += cross(points[j], points[i]);
  return sum / 2;
}

/// v taken to within half a period of `near` (a sleeve's chart wraps in v); as is without a period.
double unwrap(double v, double near, double period) {
  if (period <= 0) return v;
  return v - period * std::round((v - near) / period);
}

}  // namespace

double Outline::area_mm2() const {
  double sum = 0;
  for (int i = 0, j = size - 1; i < size; j = i++) sum += cross(vertex_mm(j), vertex_mm(i));
  return size < 3 ? 0.0 : sum / 2;
}

void ellipse_outline(const Vector2& centre_mm, double semi_major_mm, double semi_minor_mm, double orientation_deg,
                     Outline& out, int vertex_count) {
  out.clear();
  if (!(semi_major_mm > 0 && semi_minor_mm > 0 && std::isfinite(semi_major_mm) && std::isfinite(semi_minor_mm) &&
        std::isfinite(orientation_deg) && centre_mm.allFinite()))
    return;
  const int n = std::clamp(vertex_count, 3, Outline::capacity);
  const double angle = orientation_deg * std::numbers::pi / 180;
  const Vector2 major(std::cos(angle), std::sin(angle)), minor(-major.y(), major.x());
  for (int k = 0; k < n; ++k) {
    const double phi = 2 * std::numbers::pi * k / n;
    out.push_back(centre_mm + semi_major_mm * std::cos(phi) * major + semi_minor_mm * std::sin(phi) * minor);
  }
}

RegionOutliner::RegionOutliner(const Mesh& mesh, Shape surface) : surface_(std::move(surface)) {
  const auto F = static_cast<std::size_t>(mesh.triangle_count());
  const auto V = static_cast<std::size_t>(mesh.node_count());
  if (is_sleeve(surface_)) sleeve_period_mm_ = 2 * std::numbers::pi * surface_.radius_mm;
  std::vector<Vector2> node_charts(V);
  for (std::size_t n = 0; n < V; ++n)
    node_charts[n] = surface_chart_mm(surface_, mesh.nodes_mm.row(static_cast<Index>(n)).transpose());
  areas_mm2_.resize(F);
  corners_.resize(F);
  corner_charts_mm_.resize(F);
  for (std::size_t t = 0; t < F; ++t) {
    areas_mm2_[t] = mesh.triangle_area_mm2(static_cast<Index>(t));
    std::array<int, 3> c{mesh.triangles(static_cast<Index>(t), 0), mesh.triangles(static_cast<Index>(t), 1),
                         mesh.triangles(static_cast<Index>(t), 2)};
    std::array<Vector2, 3> p;
    for (int k = 0; k < 3; ++k) {
      p[k] = node_charts[static_cast<std::size_t>(c[k])];
      p[k].y() = unwrap(p[k].y(), p[0].y(), sleeve_period_mm_);
    }
    if (twice_area(p[0], p[1], p[2]) < 0) {  // counter-clockwise in the chart, whatever the mesh's order
      std::swap(c[1], c[2]);
      std::swap(p[1], p[2]);
    }
    corners_[t] = c;
    corner_charts_mm_[t] = p;
  }
  // Edges: the sides k → k+1 of every triangle, sorted by their nodes; a run of one is the border.
  std::vector<std::tuple<int, int, int, int>> sides;  // low node, high node, triangle, side
  sides.reserve(3 * F);
  for (std::size_t t = 0; t < F; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = corners_[t][k], b = corners_[t][(k + 1) % 3];
      sides.emplace_back(std::min(a, b), std::max(a, b), static_cast<int>(t), k);
    }
  std::sort(sides.begin(), sides.end());
  edges_.resize(F);
  on_border_.resize(F);
  std::vector<std::uint8_t> node_on_border(V, 0);
  for (std::size_t begin = 0, end = 0; begin < sides.size(); begin = end) {
    end = begin + 1;
    while (end < sides.size() && std::get<0>(sides[end]) == std::get<0>(sides[begin]) &&
           std::get<1>(sides[end]) == std::get<1>(sides[begin]))
      ++end;
    const bool border = end - begin == 1;
    for (std::size_t i = begin; i < end; ++i) {
      const auto [low, high, t, k] = sides[i];
      edges_[static_cast<std::size_t>(t)][k] = edge_count_;
      on_border_[static_cast<std::size_t>(t)][k] = border;
      if (border) node_on_border[static_cast<std::size_t>(low)] = node_on_border[static_cast<std::size_t>(high)] = 1;
    }
    ++edge_count_;
  }
  node_offsets_.assign(V + 1, 0);
  for (std::size_t t = 0; t < F; ++t)
    for (int n : corners_[t]) ++node_offsets_[static_cast<std::size_t>(n) + 1];
  for (std::size_t n = 1; n <= V; ++n) node_offsets_[n] += node_offsets_[n - 1];
  node_triangles_.resize(static_cast<std::size_t>(node_offsets_.back()));
  std::vector<int> fill(node_offsets_.begin(), node_offsets_.end() - 1);
  for (std::size_t t = 0; t < F; ++t)
    for (int n : corners_[t])
      node_triangles_[static_cast<std::size_t>(fill[static_cast<std::size_t>(n)]++)] = static_cast<int>(t);
  node_on_border_ = std::move(node_on_border);

  // Scratch for the worst case: every triangle in the band, a contour segment in each and one
  // along every border edge.
  std::size_t border_edges = 0;
  for (const auto& sides_on_border : on_border_)
    for (std::uint8_t b : sides_on_border) border_edges += b;
  in_region_.assign(F, 0);
  triangle_stamp_.assign(F, 0);
  node_value_stamp_.assign(V, 0);
  node_seen_stamp_.assign(V, 0);
  node_value_.assign(V, 0.0);
  band_.reserve(F);
  segments_.reserve(F + border_edges);
  used_.reserve(F + border_edges);
  starting_at_.assign(static_cast<std::size_t>(edge_count_) + V, -1);
  loop_.reserve(F + border_edges);
  best_.reserve(F + border_edges);
  const auto simplified = 2 * static_cast<std::size_t>(Outline::capacity);
  weights_.resize(simplified);
  previous_.resize(simplified);
  next_.resize(simplified);
}

int RegionOutliner::next_stamp() {
  if (++stamp_ == std::numeric_limits<int>::max()) {  // wrapped: start the stamps afresh
    std::fill(triangle_stamp_.begin(), triangle_stamp_.end(), 0);
    std::fill(node_value_stamp_.begin(), node_value_stamp_.end(), 0);
    std::fill(node_seen_stamp_.begin(), node_seen_stamp_.end(), 0);
    stamp_ = 1;
  }
  return stamp_;
}

double RegionOutliner::node_value(int node, const Vector& image, double level) {
  const auto n = static_cast<std::size_t>(node);
  if (node_value_stamp_[n] == stamp_) return node_value_[n];
  double sum = 0, area = 0;
  for (int i = node_offsets_[n]; i < node_offsets_[n + 1]; ++i) {
    const auto t = static_cast<std::size_t>(node_triangles_[static_cast<std::size_t>(i)]);
    double u;
    if (std::isnan(level)) {
      u = in_region_[t] ? 1.0 : -1.0;
    } else {
      const double above = image[static_cast<Index>(t)] - level;
      // The region's elements strictly positive (one at the level exactly still counts in it).
      u = in_region_[t] ? std::max(above, std::numeric_limits<double>::min()) : -std::abs(above);
    }
    sum += areas_mm2_[t] * u;
    area += areas_mm2_[t];
  }
  node_value_stamp_[n] = stamp_;
  return node_value_[n] = area > 0 ? sum / area : -1.0;
}

/// The band: the triangles at a node on the region's boundary (a node of the region's with an
/// element not in it, or on the mesh's border). The level line runs in the band only: a node is
/// above the level only if an element of the region is at it, and one whose elements are all in
/// the region is above.
void RegionOutliner::mark_band(std::span<const int> region) {
  band_.clear();
  for (const int t : region)
    for (const int n : corners_[static_cast<std::size_t>(t)]) {
      const auto node = static_cast<std::size_t>(n);
      if (node_seen_stamp_[node] == stamp_) continue;
      node_seen_stamp_[node] = stamp_;
      bool boundary = node_on_border_[node] != 0;
      for (int i = node_offsets_[node]; i < node_offsets_[node + 1] && !boundary; ++i)
        boundary = !in_region_[static_cast<std::size_t>(node_triangles_[static_cast<std::size_t>(i)])];
      if (!boundary) continue;
      for (int i = node_offsets_[node]; i < node_offsets_[node + 1]; ++i) {
        const auto s = static_cast<std::size_t>(node_triangles_[static_cast<std::size_t>(i)]);
        if (triangle_stamp_[s] == stamp_) continue;
        triangle_stamp_[s] = stamp_;
        band_.push_back(static_cast<int>(s));
      }
    }
}

double RegionOutliner::band_area_mm2(std::span<const int> region) {
  next_stamp();
  for (const int t : region) in_region_[static_cast<std::size_t>(t)] = 1;
  mark_band(region);
  for (const int t : region) in_region_[static_cast<std::size_t>(t)] = 0;
  double area = 0;
  for (const int t : band_) area += areas_mm2_[static_cast<std::size_t>(t)];
  return area;
}

void RegionOutliner::outline(const Vector& image, double level, std::span<const int> region, Outline& out) {
  out.clear();
  if (region.empty()) return;
  next_stamp();
  for (const int t : region) in_region_[static_cast<std::size_t>(t)] = 1;
  mark_band(region);

  // Marching triangles: in each band triangle (corners counter-clockwise) the level line runs
  // from the crossing on the side leaving the region to the one entering it, so the region is on
  // its left; along a border side, the part above the level, in the side's direction.
  segments_.clear();
  const auto point_of_node = [this](int node) { return edge_count_ + node; };
  for (const int triangle : band_) {
    const auto t = static_cast<std::size_t>(triangle);
    const std::array<int, 3>& c = corners_[t];
    const std::array<Vector2, 3>& p = corner_charts_mm_[t];
    std::array<double, 3> v{};
    std::array<bool, 3> in{};
    for (int k = 0; k < 3; ++k) {
      v[k] = node_value(c[k], image, level);
      in[k] = v[k] > 0;
    }
    // The crossing on side k, computed from its lower-numbered node so both triangles agree.
    const auto crossing = [&](int k) -> Vector2 {
      const int a = k, b = (k + 1) % 3;
      if (c[a] < c[b]) return p[a] + v[a] / (v[a] - v[b]) * (p[b] - p[a]);
      return p[b] + v[b] / (v[b] - v[a]) * (p[a] - p[b]);
    };
    int leaving = -1, entering = -1;
    for (int k = 0; k < 3; ++k) {
      const bool from = in[k], to = in[(k + 1) % 3];
      if (from && !to) leaving = k;
      if (!from && to) entering = k;
      if (on_border_[t][k] && (from || to)) {
        const int edge = edges_[t][k];
        const int start = from ? point_of_node(c[k]) : edge;
        const int end = to ? point_of_node(c[(k + 1) % 3]) : edge;
        segments_.push_back({start, end, from ? p[k] : crossing(k)});
      }
    }
    if (leaving >= 0 && entering >= 0)
      segments_.push_back({edges_[t][leaving], edges_[t][entering], crossing(leaving)});
  }
  for (const int t : region) in_region_[static_cast<std::size_t>(t)] = 0;

  // Chain the segments into closed lines; keep the one enclosing the largest area.
  used_.assign(segments_.size(), 0);
  for (std::size_t i = 0; i < segments_.size(); ++i)
    starting_at_[static_cast<std::size_t>(segments_[i].from)] = static_cast<int>(i);
  double best_area = 0;
  best_.clear();
  for (std::size_t first = 0; first < segments_.size(); ++first) {
    if (used_[first]) continue;
    loop_.clear();
    int at = static_cast<int>(first);
    bool closed = false;
    while (at >= 0 && !used_[static_cast<std::size_t>(at)]) {
      const Segment& s = segments_[static_cast<std::size_t>(at)];
      used_[static_cast<std::size_t>(at)] = 1;
      Vector2 point = s.start_mm;
      if (!loop_.empty()) point.y() = unwrap(point.y(), loop_.back().y(), sleeve_period_mm_);
      loop_.push_back(point);
      at = starting_at_[static_cast<std::size_t>(s.to)];
      closed = at == static_cast<int>(first);
    }
    if (!closed || loop_.size() < 3) continue;
    const double area = shoelace(loop_.data(), loop_.size());
    if (area > best_area) {
      best_area = area;
      best_.assign(loop_.begin(), loop_.end());
    }
  }
  for (const Segment& s : segments_) starting_at_[static_cast<std::size_t>(s.from)] = -1;
  if (best_.size() < 3) return;

  // Simplify: first every k-th vertex down to twice the capacity (the line's vertices are a mesh
  // edge or less apart), then Visvalingam–Whyatt down to the capacity and past it through
  // vertices in line with their neighbours.
  const std::size_t most = 2 * static_cast<std::size_t>(Outline::capacity);
  if (best_.size() > most) {
    const std::size_t n = best_.size();
    for (std::size_t i = 0; i < most; ++i) best_[i] = best_[i * n / most];
    best_.resize(most);
  }
  const int n = static_cast<int>(best_.size());
  const auto weight = [&](int i) {
    return std::abs(twice_area(best_[static_cast<std::size_t>(previous_[static_cast<std::size_t>(i)])],
                               best_[static_cast<std::size_t>(i)],
                               best_[static_cast<std::size_t>(next_[static_cast<std::size_t>(i)])]));
  };
  for (int i = 0; i < n; ++i) {
    previous_[static_cast<std::size_t>(i)] = (i + n - 1) % n;
    next_[static_cast<std::size_t>(i)] = (i + 1) % n;
  }
  for (int i = 0; i < n; ++i) weights_[static_cast<std::size_t>(i)] = weight(i);
  int head = 0;
  // Down to the capacity, and on while a vertex is in line with its neighbours (a straight
  // stretch of the sheet's border: its triangle below 1e-9 of the outline's area).
  const double in_line = 1e-9 * 2 * best_area;
  int remaining = n;
  for (; remaining > 3; --remaining) {
    int smallest = head;
    for (int i = next_[static_cast<std::size_t>(head)], k = 1; k < remaining;
         i = next_[static_cast<std::size_t>(i)], ++k)
      if (weights_[static_cast<std::size_t>(i)] < weights_[static_cast<std::size_t>(smallest)]) smallest = i;
    if (remaining <= Outline::capacity && weights_[static_cast<std::size_t>(smallest)] > in_line) break;
    const int before = previous_[static_cast<std::size_t>(smallest)], after = next_[static_cast<std::size_t>(smallest)];
    next_[static_cast<std::size_t>(before)] = after;
    previous_[static_cast<std::size_t>(after)] = before;
    if (smallest == head) head = after;
    weights_[static_cast<std::size_t>(before)] = weight(before);
    weights_[static_cast<std::size_t>(after)] = weight(after);
  }
  for (int i = head, k = 0; k < remaining; i = next_[static_cast<std::size_t>(i)], ++k)
    out.push_back(best_[static_cast<std::size_t>(i)]);
}

}  // namespace emit
