#include "emit/frame/contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>

#include "emit/core/errors.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

const char* touch_phase_name(TouchPhase phase) {
  switch (phase) {
    case TouchPhase::none: return "none";
    case TouchPhase::down: return "down";
    case TouchPhase::move: return "move";
    case TouchPhase::up: return "up";
  }
  return "none";
}

namespace {

/// One triangle's edge with its nodes sorted, so the triangles sharing an edge sort next to each other.
struct Edge {
  int low, high, triangle;
  bool same_nodes(const Edge& other) const { return low == other.low && high == other.high; }
  bool operator<(const Edge& other) const {
    return std::tie(low, high, triangle) < std::tie(other.low, other.high, other.triangle);
  }
};

std::vector<Edge> sorted_edges(const Mesh& mesh) {
  std::vector<Edge> edges;
  edges.reserve(3 * static_cast<std::size_t>(mesh.triangle_count()));
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(t, k), b = mesh.triangles(t, (k + 1) % 3);
      edges.push_back({std::min(a, b), std::max(a, b), static_cast<int>(t)});
    }
  std::sort(edges.begin(), edges.end());
  return edges;
}

/// Calls link(s, t) once for every pair of distinct triangles sharing an edge. A run of equal edges
/// holds 1 (border) or 2 (interior) triangles on a manifold mesh; on a non-manifold one every pair
/// in the run is linked, and a degenerate triangle is never linked to itself.
template <class Link>
void for_each_shared_edge(const std::vector<Edge>& edges, Link link) {
  for (std::size_t begin = 0, end = 0; begin < edges.size(); begin = end) {
    end = begin + 1;
    while (end < edges.size() && edges[end].same_nodes(edges[begin])) ++end;
    for (std::size_t i = begin; i < end; ++i)
      for (std::size_t j = i + 1; j < end; ++j)
        if (edges[i].triangle != edges[j].triangle) link(edges[i].triangle, edges[j].triangle);
  }
}

/// Edge adjacency as CSR: the neighbours of t are neighbours[offsets[t] .. offsets[t + 1]).
void build_adjacency(const Mesh& mesh, std::vector<int>& offsets, std::vector<int>& neighbours) {
  const std::vector<Edge> edges = sorted_edges(mesh);
  offsets.assign(static_cast<std::size_t>(mesh.triangle_count()) + 1, 0);
  for_each_shared_edge(edges, [&](int s, int t) {
    ++offsets[s + 1];
    ++offsets[t + 1];
  });
  for (std::size_t t = 1; t < offsets.size(); ++t) offsets[t] += offsets[t - 1];
  neighbours.resize(static_cast<std::size_t>(offsets.back()));
  std::vector<int> next(offsets.begin(), offsets.end() - 1);  // fill cursor per triangle
  for_each_shared_edge(edges, [&](int s, int t) {
    neighbours[next[s]++] = t;
    neighbours[next[t]++] = s;
  });
}

/// Running sums over one contact's elements.
class Accumulator {
 public:
  void add(double area, double pressure, double weight, double floor, const Vector3& centroid) {
    significant_ = significant_ || weight > floor;
    area_ += area;
    force_ += pressure * area;
    peak_ = std::max(peak_, pressure);
    weight_area_ += weight * area;
    weighted_centroid_sum_ += weight * area * centroid;
    area_centroid_sum_ += area * centroid;
    area_second_moment_ += area * centroid.head<2>() * centroid.head<2>().transpose();
    centroid_sum_ += centroid;
    ++count_;
  }

  bool significant() const { return significant_; }

  Contact contact() const {
    Contact c;
    const Vector3 centroid = this->centroid();
    c.x_mm = centroid.x(), c.y_mm = centroid.y(), c.z_mm = centroid.z();
    c.area_mm2 = area_;
    c.force_N = force_;
    c.pressure_N_per_mm2 = area_ > 0 ? force_ / area_ : 0.0;
    c.peak_pressure_N_per_mm2 = peak_;
    c.element_count = count_;
    if (area_ > 0) {  // the ellipse of the same second moments (seen from +z)
      const Vector2 mean = area_centroid_sum_.head<2>() / area_;
      const Eigen::Matrix2d covariance = area_second_moment_ / area_ - mean * mean.transpose();
      set_outline_ellipse(covariance, c);
    }
    return c;
  }

 private:
  /// Weighted as documented; falling back to the area-weighted centroid when the weights are all
  /// 0, and to the plain mean only for degenerate (zero-area) elements, so it is never 0/0.
  Vector3 centroid() const {
    if (weight_area_ > 0) return weighted_centroid_sum_ / weight_area_;
    if (area_ > 0) return area_centroid_sum_ / area_;
    return centroid_sum_ / count_;
  }

  double area_ = 0, force_ = 0, peak_ = -std::numeric_limits<double>::infinity(), weight_area_ = 0;
  Vector3 weighted_centroid_sum_ = Vector3::Zero(), area_centroid_sum_ = Vector3::Zero(),
          centroid_sum_ = Vector3::Zero();
  Eigen::Matrix2d area_second_moment_ = Eigen::Matrix2d::Zero();
  int count_ = 0;
  bool significant_ = false;
};

/// One frame's flood fill: views of ContactFinder's precomputed data and scratch, and of find()'s
/// inputs, so the fill is a free function and the header keeps its private members only.
struct FloodFill {
  const int* offsets;
  const int* neighbours;
  const double* areas_mm2;
  const Vector3* centroids_mm;
  const double* pressure;
  const double* weight;
  const double* floor;
  std::uint8_t* pending;  ///< selected and not yet in a contact
  int* stack;
  int* members;  ///< receives the contact's elements

  /// The contact grown from a pending seed. An element stops pending when pushed, so each is
  /// pushed once and the stack never holds more than #F. Raw pointers held by value: a store
  /// through a byte pointer may alias anything, so pointers behind references would be reloaded
  /// after every store (measured 10 % slower). \return false for a contact without an element
  /// above the floor (then `out` is left as it was).
  bool grow(int seed, Contact& out, int& member_count) const {
    Accumulator sum;
    member_count = 0;
    std::size_t top = 0;
    pending[seed] = 0;
    stack[top++] = seed;
    while (top > 0) {
      const int t = stack[--top];
      members[member_count++] = t;
      sum.add(areas_mm2[t], pressure[t], weight[t], floor[t], centroids_mm[t]);
      for (int k = offsets[t]; k < offsets[t + 1]; ++k) {
        const int n = neighbours[k];
        if (pending[n]) {
          pending[n] = 0;
          stack[top++] = n;
        }
      }
    }
    if (!sum.significant()) return false;
    out = sum.contact();
    return true;
  }
};

/// Throws on a size mismatch; builds its message only when throwing, so it never allocates otherwise.
void check_size(const char* what, Index size, Index element_count) {
  if (size != element_count)
    throw InvalidInput(std::string("contacts: ") + what + " has " + std::to_string(size) +
                       " entries, expected one per mesh element (" + std::to_string(element_count) + ")");
}

/// Sort key: NaN forces (from a NaN pressure) go last, so the comparison stays a strict weak
/// ordering, which std::sort needs to stay in bounds.
double force_key(const Contact& c) {
  return std::isnan(c.force_N) ? -std::numeric_limits<double>::infinity() : c.force_N;
}

}  // namespace

void set_outline_ellipse(const Eigen::Matrix2d& covariance_mm2, Contact& contact) {
  // A uniform ellipse of semi-axes a, b has variances a²/4 and b²/4 along its axes.
  const double mean = covariance_mm2.trace() / 2, half_difference = (covariance_mm2(0, 0) - covariance_mm2(1, 1)) / 2;
  const double spread = std::hypot(half_difference, covariance_mm2(0, 1));
  contact.semi_major_mm = 2 * std::sqrt(std::max(0.0, mean + spread));
  contact.semi_minor_mm = 2 * std::sqrt(std::max(0.0, mean - spread));
  contact.orientation_deg = std::atan2(covariance_mm2(0, 1), half_difference) / 2 * 180 / std::numbers::pi;
}

void place_on_surface(const Shape& surface, const Vector2& chart_mm, Contact& contact) {
  const Vector3 point = surface_point_mm(surface, chart_mm), normal = surface_normal(surface, chart_mm);
  contact.x_mm = point.x(), contact.y_mm = point.y(), contact.z_mm = point.z();
  contact.nx = normal.x(), contact.ny = normal.y(), contact.nz = normal.z();
}

Vector2 chart_of(const Shape& surface, const Contact& contact) {
  return surface_chart_mm(surface, Vector3(contact.x_mm, contact.y_mm, contact.z_mm));
}

ContactFinder::ContactFinder(const Mesh& mesh, Shape surface)
    : surface_(std::move(surface)), outliner_(mesh, surface_) {
  build_adjacency(mesh, neighbour_offsets_, neighbours_);
  const auto count = static_cast<std::size_t>(mesh.triangle_count());
  areas_mm2_.resize(count);
  centroids_mm_.resize(count);
  charts_mm_.resize(count);
  for (std::size_t t = 0; t < count; ++t) {
    areas_mm2_[t] = mesh.triangle_area_mm2(static_cast<Index>(t));
    centroids_mm_[t] = mesh.triangle_centroid_mm(static_cast<Index>(t));
    charts_mm_[t] = surface_chart_mm(surface_, centroids_mm_[t]);
  }
  // Worst cases, so find() never grows a vector: every element on the stack, every element its own contact.
  pending_.resize(count);
  stack_.resize(count);
  members_.resize(count);
  no_floor_ = Vector::Constant(static_cast<Index>(count), -std::numeric_limits<double>::infinity());
  contacts_.reserve(count);
}

const std::vector<Contact>& ContactFinder::find(const std::vector<std::uint8_t>& selected, const Vector& pressure,
                                                const Vector& weight, double min_area_mm2, const Vector* floor,
                                                double level) {
  check_size("the selection", static_cast<Index>(selected.size()), element_count());
  check_size("the pressure", pressure.size(), element_count());
  check_size("the weight", weight.size(), element_count());
  if (floor) check_size("the floor", floor->size(), element_count());
  const FloodFill fill{neighbour_offsets_.data(),
                       neighbours_.data(),
                       areas_mm2_.data(),
                       centroids_mm_.data(),
                       pressure.data(),
                       weight.data(),
                       floor ? floor->data() : no_floor_.data(),
                       pending_.data(),
                       stack_.data(),
                       members_.data()};
  std::copy(selected.begin(), selected.end(), pending_.begin());
  contacts_.clear();
  for (int seed = 0; seed < static_cast<int>(pending_.size()); ++seed) {
    if (!pending_[seed]) continue;
    Contact contact;
    int member_count = 0;
    if (fill.grow(seed, contact, member_count) && contact.area_mm2 >= min_area_mm2) {
      const Vector2 chart = chart_of(surface_, contact);
      place_on_surface(surface_, chart, contact);
      outliner_.outline(weight, level, {members_.data(), static_cast<std::size_t>(member_count)}, contact.outline);
      if (contact.outline.empty())
        ellipse_outline(chart, contact.semi_major_mm, contact.semi_minor_mm, contact.orientation_deg, contact.outline);
      contacts_.push_back(contact);  // within the reserved capacity
    }
  }
  // std::sort works in place (unlike std::stable_sort, which may take a buffer).
  std::sort(contacts_.begin(), contacts_.end(),
            [](const Contact& a, const Contact& b) { return force_key(a) > force_key(b); });
  return contacts_;
}

const std::vector<Vector2>& ContactFinder::peaks(const Vector& image, double min_value, double min_separation_mm) {
  peak_elements_.clear();
  for (int t = 0; t < static_cast<int>(centroids_mm_.size()); ++t) {
    if (!(image[t] >= min_value)) continue;
    bool highest = true;
    for (int k = neighbour_offsets_[t]; k < neighbour_offsets_[t + 1] && highest; ++k)
      highest = image[neighbours_[k]] <= image[t];
    if (highest) peak_elements_.push_back(t);
  }
  std::sort(peak_elements_.begin(), peak_elements_.end(), [&](int a, int b) { return image[a] > image[b]; });
  peaks_.clear();
  for (int t : peak_elements_) {
    bool apart = true;
    for (const Vector2& p : peaks_) apart = apart && (p - charts_mm_[t]).norm() >= min_separation_mm;
    if (apart) peaks_.push_back(charts_mm_[t]);
  }
  return peaks_;
}

}  // namespace emit
