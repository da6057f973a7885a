// A polygon's outline must not cross or touch itself (sensor/border.hpp Border::polygon): the
// check sweeps along x instead of testing every pair of edges (over a minute on 200,000 points),
// and finds the same first pair as testing every pair does.
#include "emit/sensor/border.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// Every pair of edges that are not neighbours, in order: the first that meet (the check as it was).
std::optional<std::pair<std::size_t, std::size_t>> first_meeting_pair(const std::vector<Vector2>& p) {
  const std::size_t n = p.size();
  const auto cross = [](const Vector2& u, const Vector2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const auto on = [](const Vector2& a, const Vector2& b, const Vector2& r) {
    return std::min(a.x(), b.x()) <= r.x() && r.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= r.y() &&
           r.y() <= std::max(a.y(), b.y());
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;
      const Vector2 &a = p[i], &b = p[(i + 1) % n], &c = p[j], &d = p[(j + 1) % n];
      const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c),
                   d4 = cross(d - c, b - c);
      const bool proper = ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
      const bool touching =
          (d1 == 0 && on(a, b, c)) || (d2 == 0 && on(a, b, d)) || (d3 == 0 && on(c, d, a)) || (d4 == 0 && on(c, d, b));
      if (proper || touching) return std::pair(i, j);
    }
  return std::nullopt;
}

std::string expected_error(const std::optional<std::pair<std::size_t, std::size_t>>& pair, std::size_t n) {
  if (!pair) return "no error";
  return "the polygon's edges " + std::to_string(pair->first) + "-" + std::to_string((pair->first + 1) % n) + " and " +
         std::to_string(pair->second) + "-" + std::to_string((pair->second + 1) % n) +
         " meet: the outline must not cross or touch itself";
}

// Random polygons of 4 to 12 points on a small grid (so that points and edges touch, overlap and
// line up often): the sweep names the same first pair as testing every pair.
TEST(Border, TheSweptCrossingCheckAgreesWithEveryPair) {
  std::mt19937 random(7);
  int crossing = 0, simple = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = 4 + static_cast<int>(random() % 9);
    std::vector<Vector2> points;
    points.reserve(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      const auto x = static_cast<double>(random() % 6);
      points.emplace_back(x, static_cast<double>(random() % 6));
    }
    bool repeated = false;
    for (int k = 0; k < n; ++k) repeated = repeated || points[k] == points[(k + 1) % n];
    double twice_area = 0;
    for (int k = 0; k < n; ++k)
      twice_area += points[k].x() * points[(k + 1) % n].y() - points[(k + 1) % n].x() * points[k].y();
    if (repeated || std::abs(twice_area) < 1e-12) continue;  // refused before the check
    const auto pair = first_meeting_pair(points);
    (pair ? crossing : simple) += 1;
    EXPECT_EQ(test::error_of([&] { Border::polygon(points); }), expected_error(pair, points.size())) << trial;
  }
  EXPECT_GT(crossing, 500);
  EXPECT_GT(simple, 100);
}

// A 20,000-point circle is an outline; one point moved across the circle makes its edges cross
// the far side, and the sweep finds them without testing 2·10⁸ pairs.
TEST(Border, AFineOutlineIsCheckedAlongItsLength) {
  const std::size_t n = 20000;
  std::vector<Vector2> points;
  points.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double angle = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    points.emplace_back(30 + 25 * std::cos(angle), 30 + 25 * std::sin(angle));
  }
  EXPECT_NEAR(Border::polygon(points).length_mm(), 2 * std::numbers::pi * 25, 1e-3);
  points[12345] = {30 - 30 * std::cos(2 * std::numbers::pi * 12345 / n),
                   30 - 30 * std::sin(2 * std::numbers::pi * 12345 / n)};
  const std::string error = test::error_of([&] { Border::polygon(points); });
  EXPECT_NE(error.find("the outline must not cross or touch itself"), std::string::npos) << error;
}

}  // namespace
}  // namespace emit
