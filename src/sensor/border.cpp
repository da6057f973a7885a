#include "emit/sensor/border.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <utility>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

BorderPiece line_piece(const Vector2& a, const Vector2& b) {
  BorderPiece piece;
  piece.kind = BorderPiece::Kind::line;
  piece.start_mm = a;
  piece.end_mm = b;
  piece.length_mm = (b - a).norm();
  return piece;
}

BorderPiece arc_piece(const Vector2& center, double radius, double start_rad, double sweep_rad) {
  BorderPiece piece;
  piece.kind = BorderPiece::Kind::arc;
  piece.arc_center_mm = center;
  piece.arc_radius_mm = radius;
  piece.arc_start_rad = start_rad;
  piece.start_mm = center + radius * Vector2(std::cos(start_rad), std::sin(start_rad));
  const double end_rad = start_rad + sweep_rad;
  piece.end_mm = center + radius * Vector2(std::cos(end_rad), std::sin(end_rad));
  piece.length_mm = radius * sweep_rad;
  return piece;
}

Vector2 point_on_piece(const BorderPiece& piece, double t_mm) {
  if (piece.kind == BorderPiece::Kind::line)
    return piece.start_mm + (piece.end_mm - piece.start_mm) * (t_mm / piece.length_mm);
  const double angle = piece.arc_start_rad + t_mm / piece.arc_radius_mm;
  return piece.arc_center_mm + piece.arc_radius_mm * Vector2(std::cos(angle), std::sin(angle));
}

/// Arc length along the piece of its point nearest to p.
double nearest_on_piece(const BorderPiece& piece, const Vector2& p) {
  if (piece.kind == BorderPiece::Kind::line) {
    const Vector2 d = piece.end_mm - piece.start_mm;
    const double t = (p - piece.start_mm).dot(d) / d.squaredNorm();
    return std::clamp(t, 0.0, 1.0) * piece.length_mm;
  }
  const Vector2 r = p - piece.arc_center_mm;
  if (r.norm() == 0) return 0;
  double angle = std::atan2(r.y(), r.x()) - piece.arc_start_rad;
  angle = std::fmod(angle, 2 * std::numbers::pi);
  if (angle < 0) angle += 2 * std::numbers::pi;
  const double sweep = piece.length_mm / piece.arc_radius_mm;
  if (angle <= sweep) return angle * piece.arc_radius_mm;
  // Outside the arc's sweep: the nearer end wins.
  const double to_start = (p - piece.start_mm).norm(), to_end = (p - piece.end_mm).norm();
  return to_start <= to_end ? 0.0 : piece.length_mm;
}

/// Whether segments ab and cd meet: cross, or touch (an end on the other, or overlapping on a line).
bool segments_meet(const Vector2& a, const Vector2& b, const Vector2& c, const Vector2& d) {
  const auto cross = [](const Vector2& u, const Vector2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  const bool proper = ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
  const auto on_segment = [](const Vector2& p, const Vector2& q, const Vector2& r) {  // r on pq, collinear
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) && std::min(p.y(), q.y()) <= r.y() &&
           r.y() <= std::max(p.y(), q.y());
  };
  const bool touching = (d1 == 0 && on_segment(a, b, c)) || (d2 == 0 && on_segment(a, b, d)) ||
                        (d3 == 0 && on_segment(c, d, a)) || (d4 == 0 && on_segment(c, d, b));
  return proper || touching;
}

/// The first pair (i, j), i < j, of edges (edge i from point i to i + 1) that are not neighbours and
/// meet, if any. Swept along x: an edge is tested only against the edges whose x-range reaches its
/// own start and whose y-range overlaps its own. An outline meets few edges at any x, so this is
/// about n log n (testing every pair took over a minute on 200,000 points); every pair is tested
/// only when all edges share an x-range and a y-range.
std::optional<std::pair<std::size_t, std::size_t>> first_meeting_edges(const std::vector<Vector2>& points) {
  const std::size_t n = points.size();
  const auto start = [&](std::size_t i) -> const Vector2& { return points[i]; };
  const auto end = [&](std::size_t i) -> const Vector2& { return points[(i + 1) % n]; };
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  const auto x_min = [&](std::size_t i) { return std::min(start(i).x(), end(i).x()); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x_min(a) < x_min(b); });
  std::optional<std::pair<std::size_t, std::size_t>> first;
  std::vector<std::size_t> active;
  for (const std::size_t i : order) {
    const double from_x = x_min(i);
    std::erase_if(active, [&](std::size_t j) { return std::max(start(j).x(), end(j).x()) < from_x; });
    const double y0 = std::min(start(i).y(), end(i).y()), y1 = std::max(start(i).y(), end(i).y());
    for (const std::size_t j : active) {
      if (std::max(start(j).y(), end(j).y()) < y0 || std::min(start(j).y(), end(j).y()) > y1) continue;
      const std::size_t lo = std::min(i, j), hi = std::max(i, j);
      if (hi == lo + 1 || (lo == 0 && hi == n - 1)) continue;  // neighbours share a point
      if (first && std::pair(lo, hi) >= *first) continue;
      if (segments_meet(start(lo), end(lo), start(hi), end(hi))) first = std::pair(lo, hi);
    }
    active.push_back(i);
  }
  return first;
}

}  // namespace

double wrap_arclength(double s_mm, double length_mm) {
  double s = std::fmod(s_mm, length_mm);
  if (s < 0) s += length_mm;
  return s;
}

Border Border::rectangle(double width_mm, double height_mm) {
  Border border;
  const Vector2 a(0, 0), b(width_mm, 0), c(width_mm, height_mm), d(0, height_mm);
  border.pieces_ = {line_piece(a, b), line_piece(b, c), line_piece(c, d), line_piece(d, a)};
  border.finish();
  return border;
}

Border Border::circle(const Vector2& center_mm, double radius_mm) {
  Border border;
  // Four quarter arcs: every piece spans less than π, as Gmsh's circle arcs require.
  for (int quarter = 0; quarter < 4; ++quarter)
    border.pieces_.push_back(arc_piece(center_mm, radius_mm, quarter * std::numbers::pi / 2, std::numbers::pi / 2));
  border.finish();
  return border;
}

Border Border::polygon(const std::vector<Vector2>& points_mm) {
  const std::size_t n = points_mm.size();
  if (n < 3) throw InvalidInput("a polygon needs at least 3 points, got " + std::to_string(n));
  double twice_area = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vector2& p = points_mm[i];
    const Vector2& q = points_mm[(i + 1) % n];
    if ((q - p).norm() == 0)
      throw InvalidInput("polygon points " + std::to_string(i) + " and " + std::to_string((i + 1) % n) + " coincide");
    twice_area += p.x() * q.y() - q.x() * p.y();
  }
  if (std::abs(twice_area) < 1e-12) throw InvalidInput("the polygon has zero area");
  // Edges i (points i, i+1) and j that are not neighbours must not meet: a self-intersecting
  // outline has no inside to mesh (and Gmsh fails on it where its error cannot be caught).
  if (const auto meeting = first_meeting_edges(points_mm))
    throw InvalidInput("the polygon's edges " + std::to_string(meeting->first) + "-" +
                       std::to_string((meeting->first + 1) % n) + " and " + std::to_string(meeting->second) + "-" +
                       std::to_string((meeting->second + 1) % n) + " meet: the outline must not cross or touch itself");
  std::vector<Vector2> ccw = points_mm;
  if (twice_area < 0) std::reverse(ccw.begin() + 1, ccw.end());  // keep points[0] first
  Border border;
  for (std::size_t i = 0; i < n; ++i) border.pieces_.push_back(line_piece(ccw[i], ccw[(i + 1) % n]));
  border.finish();
  return border;
}

void Border::finish() {
  double s = 0;
  Eigen::AlignedBox2d box;
  for (auto& piece : pieces_) {
    piece.start_s_mm = s;
    s += piece.length_mm;
    box.extend(piece.start_mm);
    if (piece.kind == BorderPiece::Kind::arc) {
      box.extend(piece.arc_center_mm + Vector2(piece.arc_radius_mm, piece.arc_radius_mm));
      box.extend(piece.arc_center_mm - Vector2(piece.arc_radius_mm, piece.arc_radius_mm));
    }
  }
  length_mm_ = s;
  size_mm_ = box.diagonal().norm();
}

Vector2 Border::point_at(double s_mm) const {
  const double s = wrap_arclength(s_mm, length_mm_);
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), s,
                             [](double value, const BorderPiece& p) { return value < p.start_s_mm; });
  const BorderPiece& piece = *std::prev(it);
  return point_on_piece(piece, s - piece.start_s_mm);
}

Border::Projection Border::project(const Vector2& p_mm) const {
  Projection best{0, std::numeric_limits<double>::infinity()};
  for (const auto& piece : pieces_) {
    const double t = nearest_on_piece(piece, p_mm);
    const double distance = (point_on_piece(piece, t) - p_mm).norm();
    if (distance < best.distance_mm) best = {wrap_arclength(piece.start_s_mm + t, length_mm_), distance};
  }
  return best;
}

bool Border::contains(const Vector2& p_mm) const {
  if (distance_to_border_mm(p_mm) <= 1e-9 * size_mm_) return true;
  // Even-odd rule on a polyline through the border; arcs are sampled finely enough that the
  // chord error (≤ r·(1-cos(π/256)) ≈ 7.5e-5 r) only matters within that distance of the border.
  // The polyline must close exactly: each piece's last point is the next piece's first, not its
  // own end recomputed. A circle's quarter arcs end at cos/sin of π/2·k, a few 1e-15 mm from where
  // the next one starts; a point on the line y = 0 between those two ends (the apex of a dome,
  // the centre (1e-15, -2e-15) of a circle) then crossed neither piece there and fell "off the sheet".
  int crossings = 0;
  const int samples_per_arc = 128;
  auto crosses = [&](const Vector2& a, const Vector2& b) {
    if ((a.y() > p_mm.y()) == (b.y() > p_mm.y())) return false;
    const double x = a.x() + (p_mm.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    return p_mm.x() < x;
  };
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const BorderPiece& piece = pieces_[i];
    const Vector2& closing = pieces_[(i + 1) % pieces_.size()].start_mm;
    const int steps = piece.kind == BorderPiece::Kind::line ? 1 : samples_per_arc;
    Vector2 previous = piece.start_mm;
    for (int k = 1; k <= steps; ++k) {
      const Vector2 next = k == steps ? closing : point_on_piece(piece, piece.length_mm * k / steps);
      if (crosses(previous, next)) ++crossings;
      previous = next;
    }
  }
  return crossings % 2 == 1;
}

}  // namespace emit
