#include "emit/sensor/press_outline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"

namespace emit {

namespace {

/// A polygon's integrals ∫1, ∫p, ∫p pᵀ by the shoelace sums (Green's theorem), signed by its
/// orientation (positive counter-clockwise).
struct PolygonIntegrals {
  double area = 0;
  Vector2 first = Vector2::Zero();
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
};

PolygonIntegrals integrals_of(const std::vector<Vector2>& polygon) {
  PolygonIntegrals s;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vector2& p = polygon[i];
    const Vector2& q = polygon[(i + 1) % n];
    const double c = p.x() * q.y() - q.x() * p.y();
    s.area += c / 2;
    s.first += c / 6 * (p + q);
    s.second(0, 0) += c / 12 * (p.x() * p.x() + p.x() * q.x() + q.x() * q.x());
    s.second(1, 1) += c / 12 * (p.y() * p.y() + p.y() * q.y() + q.y() * q.y());
    s.second(0, 1) += c / 24 * (p.x() * q.y() + 2 * p.x() * p.y() + 2 * q.x() * q.y() + q.x() * p.y());
  }
  s.second(1, 0) = s.second(0, 1);
  return s;
}

/// The outline's integrals, relative to the press's centre: the boundary's less its holes'.
PolygonIntegrals outline_integrals(const std::vector<std::vector<Vector2>>& outline) {
  PolygonIntegrals total;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const PolygonIntegrals s = integrals_of(outline[k]);
    const double sign = (s.area >= 0 ? 1.0 : -1.0) * (k == 0 ? 1.0 : -1.0);
    total.area += sign * s.area;
    total.first += sign * s.first;
    total.second += sign * s.second;
  }
  return total;
}

double reach_of(const std::vector<std::vector<Vector2>>& outline) {
  double reach = 0;
  for (const auto& polygon : outline)
    for (const Vector2& v : polygon) reach = std::max(reach, v.norm());
  return reach;
}

Press outline_press(const Vector2& centre_mm, std::vector<std::vector<Vector2>> outline, double force_N) {
  Press press{centre_mm.x(), centre_mm.y(), reach_of(outline), force_N};
  press.outline_mm = std::move(outline);
  return press;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void check_size(const char* what, double value_mm) {
  if (!(value_mm > 0) || !std::isfinite(value_mm))
    throw InvalidInput(std::string(what) + " must be a positive length, got " + number(value_mm));
}

Vector2 rotated(const Vector2& v, double angle_deg) {
  const double a = angle_deg * std::numbers::pi / 180;
  return {std::cos(a) * v.x() - std::sin(a) * v.y(), std::sin(a) * v.x() + std::cos(a) * v.y()};
}

std::vector<Vector2> ellipse_polygon(double a_mm, double b_mm, double angle_deg) {
  std::vector<Vector2> polygon;
  for (int k = 0; k < outline_curve_vertices; ++k) {
    const double t = 2 * std::numbers::pi * k / outline_curve_vertices;
    polygon.push_back(rotated({a_mm * std::cos(t), b_mm * std::sin(t)}, angle_deg));
  }
  return polygon;
}

std::vector<double> numbers_of(const std::string& text, const std::string& list, const std::string& expected) {
  std::vector<double> values;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || item.find_first_not_of(" \t", used) != std::string::npos)
      throw InvalidInput("press " + quote_input(text) + ": " + quote_input(item) + " is not a number (expected " +
                         expected + ")");
    values.push_back(value);
  }
  return values;
}

}  // namespace

Press bar_press(const Vector2& centre_mm, double length_mm, double width_mm, double angle_deg, double force_N) {
  check_size("bar length", length_mm);
  check_size("bar width", width_mm);
  std::vector<Vector2> polygon;
  for (const Vector2& corner : {Vector2(-1, -1), Vector2(1, -1), Vector2(1, 1), Vector2(-1, 1)})
    polygon.push_back(rotated({corner.x() * length_mm / 2, corner.y() * width_mm / 2}, angle_deg));
  return outline_press(centre_mm, {polygon}, force_N);
}

Press ellipse_press(const Vector2& centre_mm, double a_mm, double b_mm, double angle_deg, double force_N) {
  check_size("ellipse semi-axis a", a_mm);
  check_size("ellipse semi-axis b", b_mm);
  return outline_press(centre_mm, {ellipse_polygon(a_mm, b_mm, angle_deg)}, force_N);
}

Press ring_press(const Vector2& centre_mm, double inner_mm, double outer_mm, double force_N) {
  check_size("ring inner radius", inner_mm);
  check_size("ring outer radius", outer_mm);
  if (!(inner_mm < outer_mm))
    throw InvalidInput("ring: inner radius " + number(inner_mm) + " mm must be below the outer " + number(outer_mm) +
                       " mm");
  return outline_press(centre_mm, {ellipse_polygon(outer_mm, outer_mm, 0), ellipse_polygon(inner_mm, inner_mm, 0)},
                       force_N);
}

Press polygon_press(const Vector2& centre_mm, std::vector<std::vector<Vector2>> outline_mm, double force_N) {
  validate_outline(outline_mm, "polygon");
  return outline_press(centre_mm, std::move(outline_mm), force_N);
}

Press parse_outline_press(const std::string& text) {
  const std::size_t colon = text.find(':');
  const std::string kind = text.substr(0, colon), list = colon == std::string::npos ? "" : text.substr(colon + 1);
  const auto expect = [&](const std::string& fields, std::size_t count) {
    std::vector<double> v = numbers_of(text, list, fields);
    if (v.size() != count)
      throw InvalidInput("press " + quote_input(text) + ": expected " + std::to_string(count) + " values " + fields +
                         ", got " + std::to_string(v.size()));
    return v;
  };
  if (kind == "bar") {
    const auto v = expect("x_mm,y_mm,length_mm,width_mm,angle_deg,force_N", 6);
    return bar_press({v[0], v[1]}, v[2], v[3], v[4], v[5]);
  }
  if (kind == "ellipse") {
    const auto v = expect("x_mm,y_mm,a_mm,b_mm,angle_deg,force_N", 6);
    return ellipse_press({v[0], v[1]}, v[2], v[3], v[4], v[5]);
  }
  if (kind == "ring") {
    const auto v = expect("x_mm,y_mm,inner_radius_mm,outer_radius_mm,force_N", 5);
    return ring_press({v[0], v[1]}, v[2], v[3], v[4]);
  }
  if (kind == "polygon") {
    const std::string fields = "x_mm,y_mm,force_N,u1,v1,u2,v2,u3,v3[,...]";
    const std::vector<double> v = numbers_of(text, list, fields);
    if (v.size() < 9 || v.size() % 2 == 0)
      throw InvalidInput("press " + quote_input(text) + ": expected x_mm,y_mm,force_N and 3 or more vertices u,v (" +
                         fields + "), got " + std::to_string(v.size()) + " values");
    std::vector<Vector2> polygon;
    for (std::size_t k = 3; k + 1 < v.size(); k += 2) polygon.emplace_back(v[k], v[k + 1]);
    return polygon_press({v[0], v[1]}, {polygon}, v[2]);
  }
  throw InvalidInput("press " + quote_input(text) + ": " + quote_input(kind) +
                     " is not an outline (bar, ellipse, ring, polygon)");
}

void validate_outline(const std::vector<std::vector<Vector2>>& outline_mm, const std::string& where) {
  for (std::size_t k = 0; k < outline_mm.size(); ++k) {
    if (outline_mm[k].size() < 3)
      throw InvalidInput(where + ": outline polygon " + std::to_string(k) + " has " +
                         std::to_string(outline_mm[k].size()) + " vertices, 3 or more needed");
    for (const Vector2& v : outline_mm[k])
      if (!v.allFinite()) throw InvalidInput(where + ": outline vertices must be finite numbers");
  }
  if (outline_mm.empty() || !(outline_integrals(outline_mm).area > 0))
    throw InvalidInput(where + ": the outline encloses no area");
}

double press_area_mm2(const Press& press) {
  if (press.outline_mm.empty()) return std::numbers::pi * press.radius_mm * press.radius_mm;
  return outline_integrals(press.outline_mm).area;
}

Vector2 press_centroid_mm(const Press& press) {
  Vector2 centre(press.x_mm, press.y_mm);
  if (press.outline_mm.empty()) return centre;
  const PolygonIntegrals s = outline_integrals(press.outline_mm);
  return centre + s.first / s.area;
}

Eigen::Matrix2d press_second_moments_mm2(const Press& press) {
  if (press.outline_mm.empty()) return press.radius_mm * press.radius_mm / 4 * Eigen::Matrix2d::Identity();
  const PolygonIntegrals s = outline_integrals(press.outline_mm);
  const Vector2 c = s.first / s.area;
  return s.second / s.area - c * c.transpose();
}

bool inside_polygons(const std::vector<std::vector<Vector2>>& polygons, const Vector2& point_mm) {
  bool inside = false;
  for (const auto& polygon : polygons) {
    const std::size_t n = polygon.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {  // crossings of the ray towards +x
      const Vector2 &a = polygon[i], &b = polygon[j];
      if ((a.y() > point_mm.y()) != (b.y() > point_mm.y()) &&
          point_mm.x() < (b.x() - a.x()) * (point_mm.y() - a.y()) / (b.y() - a.y()) + a.x())
        inside = !inside;
    }
  }
  return inside;
}

std::vector<std::vector<Vector2>> placed_outline_mm(const Press& press) {
  std::vector<std::vector<Vector2>> placed = press.outline_mm;
  const Vector2 centre(press.x_mm, press.y_mm);
  for (auto& polygon : placed)
    for (Vector2& v : polygon) v += centre;
  return placed;
}

bool press_covers(const Press& press, const Vector2& point_mm) {
  const Vector2 offset = point_mm - Vector2(press.x_mm, press.y_mm);
  if (press.outline_mm.empty()) return offset.norm() <= press.radius_mm;
  return inside_polygons(press.outline_mm, offset);
}

}  // namespace emit
