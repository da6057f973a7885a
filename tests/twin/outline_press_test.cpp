// Flat punches of any outline in the twin (twin/press_contact.hpp, sensor/press_outline.hpp): the
// load's total against the outline's area, the same outline given two ways, and a bar's frame
// that tells its orientation.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/outline_scripts.hpp"
#include "emit/twin/press_contact.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

double longest_edge_mm(const Mesh& mesh) {
  double longest = 0;
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest,
                         (mesh.nodes_mm.row(mesh.triangles(t, k)) - mesh.nodes_mm.row(mesh.triangles(t, (k + 1) % 3)))
                             .norm());
  return longest;
}

double perimeter_mm(const Press& press) {
  double length = 0;
  for (const auto& polygon : press.outline_mm)
    for (std::size_t i = 0; i < polygon.size(); ++i) length += (polygon[(i + 1) % polygon.size()] - polygon[i]).norm();
  return length;
}

// ∫ g dA = Σ of the contact matrices = g(F/A)·A. Pieces wholly inside or outside are exact; a cut
// piece of the last level (diameter ≤ d = h_max/2^levels) is counted whole or not at all, and
// every such piece lies within d of the outline: the error is at most the area of the outline's
// d-neighbourhood, 2dP + πd² per polygon (Steiner's formula bounds it for a closed polygon).
TEST(OutlinePress, TotalConductanceIsGTimesTheArea) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = generate_mesh(sensor, twin_mesh_options(sensor));
  const int levels = 6;
  const double d = longest_edge_mm(mesh) / std::pow(2.0, levels);
  for (const Press& press :
       {bar_press({29.3, 31.1}, 30, 3, 37, 9), ellipse_press({27, 33}, 12, 6, 101, 12), ring_press({31, 28}, 6, 9, 7),
        outline_presses(OutlineFamily::l_20x4, {30.4, 29.1}, 200, 10)[0]}) {
    const double area = press_area_mm2(press);
    const double g = sensor.contact.conductance_S_per_mm2(press.force_N / area);
    const double total = press_contact_load(mesh, {press}, sensor.contact, levels).total_conductance_S();
    const double bound =
        2 * d * perimeter_mm(press) + std::numbers::pi * d * d * static_cast<double>(press.outline_mm.size());
    EXPECT_LE(std::abs(total / g - area), bound) << "outline of area " << area;
    EXPECT_GT(bound, 0);
  }
}

// A square given as a polygon is the bar of the same size: the same load, to the last bit.
TEST(OutlinePress, PolygonSquareIsTheBar) {
  const Mesh mesh = test::strip_mesh(20, 20, 40, 40);
  ContactLaw law;
  const Press bar = bar_press({10.1, 9.7}, 8, 8, 0, 6);
  const Press square = polygon_press({10.1, 9.7}, {{{-4, -4}, {4, -4}, {4, 4}, {-4, 4}}}, 6);
  const ContactLoad a = press_contact_load(mesh, {bar}, law), b = press_contact_load(mesh, {square}, law);
  ASSERT_EQ(a.triangles, b.triangles);
  for (std::size_t k = 0; k < a.local_S.size(); ++k) EXPECT_EQ(a.local_S[k], b.local_S[k]);
}

// A disc beside a bar adds its pressure where they overlap, as two discs do.
TEST(OutlinePress, DiscBesideAnOutlineKeepsItsConductance) {
  const Mesh mesh = test::strip_mesh(20, 20, 40, 40);
  ContactLaw law;
  const Press disc{5, 5, 2, 3};
  const double alone = press_contact_load(mesh, {disc}, law).total_conductance_S();
  const double bar = press_contact_load(mesh, {bar_press({14, 14}, 8, 3, 45, 4)}, law).total_conductance_S();
  const double both = press_contact_load(mesh, {disc, bar_press({14, 14}, 8, 3, 45, 4)}, law).total_conductance_S();
  // Apart, they add; the disc's rim is resolved by the same pieces on both paths: to round-off.
  EXPECT_NEAR(both, alone + bar, 1e-12 * both);
}

// A bar 30 × 3 mm and the same bar turned 90° give different frames: the frame sees orientation.
// By how much, against the ADC's 1 mV noise: more than 10 mV in the largest reading's change
// (measured: 17 mV of a 689 mV signal, the bar at 20° and 110° in the centre).
TEST(OutlinePress, TurnedBarChangesTheFrame) {
  TwinOptions options;
  options.adc = false;
  Twin twin(default_sensor(), options);
  const Frame empty = twin.exact_frame({});
  const Frame along = twin.exact_frame({bar_press({30, 30}, 30, 3, 20, 10)});
  const Frame across = twin.exact_frame({bar_press({30, 30}, 30, 3, 110, 10)});
  const double signal = (along - empty).cwiseAbs().maxCoeff(), change = (along - across).cwiseAbs().maxCoeff();
  std::printf("bar's signal %.4f V, change on turning it 90 deg %.4f V\n", signal, change);
  EXPECT_GT(change, 0.010);
}

TEST(OutlinePress, RefusedWhereNotSimulated) {
  const Mesh mesh = test::strip_mesh(20, 20, 10, 10);
  ContactLaw law;
  const Press bar = bar_press({10, 10}, 8, 3, 0, 4);
  EXPECT_EQ(test::error_of([&] { press_contact_load(mesh, {bar}, law, 6, 1.0); }),
            "an outline press under a blurring cover is not simulated (cover blur 0 only)");
  Press spherical{5, 5, 2, 3};
  spherical.profile = PressProfile::spherical;
  EXPECT_EQ(test::error_of([&] {
              press_contact_load(mesh, {bar, spherical}, law);
            }),
            "outline presses go with flat presses only");
  Mesh curved = mesh;
  curved.nodes_mm(0, 2) = 1;
  EXPECT_EQ(test::error_of([&] { press_contact_load(curved, {bar}, law); }), "an outline press needs a flat sheet");
}

// The outline set: every family on the 60 mm sheet, each outline's vertices 3 mm or more inside.
TEST(OutlineScripts, EveryFamilyFitsOnTheSheet) {
  const Sensor sensor = default_sensor();
  for (const OutlineFamily family : outline_families()) {
    OutlineStyle style;
    style.seed = 5;
    const PressSequence frames = outline_script(sensor, family, 4, style);
    ASSERT_EQ(frames.size(), 4u);
    for (const auto& presses : frames) {
      double force = 0;
      for (const Press& p : presses) {
        force += p.force_N;
        EXPECT_EQ(test::error_of([&] { validate_press(sensor, p, "press"); }), "no error");
        for (const auto& polygon : placed_outline_mm(p))
          for (const Vector2& v : polygon) {
            EXPECT_GE(v.x(), 3 - 1e-9);
            EXPECT_LE(v.x(), 57 + 1e-9);
            EXPECT_GE(v.y(), 3 - 1e-9);
            EXPECT_LE(v.y(), 57 + 1e-9);
          }
      }
      EXPECT_GE(force, 4);
      EXPECT_LE(force, 16);
      EXPECT_EQ(presses.size(), family == OutlineFamily::parallel_bars ? 2u : 1u);
    }
  }
}

}  // namespace
}  // namespace emit
