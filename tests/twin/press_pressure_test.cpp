// Pressure profiles and the cover's blur (twin/press_pressure.hpp) and their contact conductance
// (twin/press_contact.hpp): the force each profile carries, with and without blur, radially and
// through the triangle quadrature; the contact's symmetry; blur → 0 gives the flat disc's frame.
#include "emit/twin/press_pressure.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/fem/forward_model.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_contact.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

Press press_of(PressProfile profile) { return Press{15, 15, 4, 10, profile}; }

/// 2π ∫ ρ P(ρ) dρ by the midpoint rule on 20,000 steps over the support.
double radial_force_N(const RadialPressure& p) {
  const int n = 20000;
  const double h = p.support_mm() / n;
  double sum = 0;
  for (int k = 0; k < n; ++k) sum += (k + 0.5) * h * p.at((k + 0.5) * h);
  return 2 * std::numbers::pi * h * sum;
}

// ∫ P dA = F for each profile, blurred or not. Errors: the midpoint rule across the flat rim's
// jump (one step of the rim's circumference, 5e-5 relative), the table's interpolation (~1e-4)
// and the Gaussian's tail beyond 4σ (< 1e-4 of the rim's share): 1e-3 with margin.
TEST(PressPressure, EachProfileCarriesItsForce) {
  for (PressProfile profile : {PressProfile::flat, PressProfile::spherical})
    for (double blur : {0.0, 0.3, 1.0, 2.0}) {
      const RadialPressure p(press_of(profile), blur);
      EXPECT_NEAR(radial_force_N(p), 10.0, 1e-3 * 10) << profile_name(profile) << ", blur " << blur;
      EXPECT_NEAR(p.support_mm(), 4 + 4 * blur, 1e-12);
    }
}

// Hertz's centre pressure is 3/2 of the mean, and blur lowers a peak (it spreads the force).
TEST(PressPressure, ProfilesHaveTheirShapes) {
  const Press flat = press_of(PressProfile::flat), sphere = press_of(PressProfile::spherical);
  EXPECT_DOUBLE_EQ(RadialPressure(sphere, 0).at(0), 1.5 * sphere.pressure_N_per_mm2());
  EXPECT_DOUBLE_EQ(RadialPressure(flat, 0).at(3.99), flat.pressure_N_per_mm2());
  EXPECT_EQ(RadialPressure(flat, 0).at(4.01), 0.0);
  EXPECT_EQ(RadialPressure(sphere, 0).at(4.0), 0.0);
  // Blurred by σ = 1 mm, a 4 mm flat disc's centre keeps 1 − exp(−r²/2σ²) of its pressure
  // (the Gaussian's mass within r of the centre): 0.99966; the table is good to 1e-4.
  EXPECT_NEAR(RadialPressure(flat, 1.0).at(0) / flat.pressure_N_per_mm2(), 1 - std::exp(-8.0), 1e-4);
  // At the rim it keeps about half (a straight edge would keep exactly 1/2; the curved rim, less).
  const double rim = RadialPressure(flat, 1.0).at(4) / flat.pressure_N_per_mm2();
  EXPECT_GT(rim, 0.40);
  EXPECT_LT(rim, 0.50);
  EXPECT_LT(RadialPressure(sphere, 1.0).at(0), RadialPressure(sphere, 0).at(0));
  EXPECT_THROW(RadialPressure(flat, -1), InvalidInput);
}

/// A contact law with g = P/α, so the total conductance is F/α: the quadrature's force.
ContactLaw linear_law() {
  ContactLaw law;
  law.gamma = -1, law.min_pressure_N_per_mm2 = 0, law.alpha_ohm_mm2 = 1;
  return law;
}

// Through the triangle quadrature: the pieces are a quarter of the blur (or an eighth of the
// radius) and the edge-midpoint rule errs by O(piece² P''), ~1e-3 of the force at most.
TEST(PressContact, QuadratureCarriesEachProfilesForce) {
  const Mesh mesh = test::strip_mesh(30, 30, 30, 30);
  for (PressProfile profile : {PressProfile::flat, PressProfile::spherical})
    for (double blur : {0.0, 0.5, 1.0}) {
      const double total = press_contact_load(mesh, {press_of(profile)}, linear_law(), 6, blur).total_conductance_S();
      EXPECT_NEAR(total, 10.0, 2e-3 * 10) << profile_name(profile) << ", blur " << blur;
    }
}

// The contact's centre of conductance, Σ C_ij x_i / Σ C_ij = ∫ g x dA / ∫ g dA (P1 interpolates x
// exactly), is the press's centre: a radial profile is symmetric. The quadrature's pieces do
// not follow the circle, so it holds to a few thousandths of a millimetre.
TEST(PressContact, SmoothContactIsCentredOnThePress) {
  const Mesh mesh = test::strip_mesh(30, 30, 23, 29);  // cells not aligned with the press
  const Sensor sensor = default_sensor();
  for (PressProfile profile : {PressProfile::flat, PressProfile::spherical}) {
    const Press press{13.37, 16.21, 4, 10, profile};
    const ContactLoad load = press_contact_load(mesh, {press}, sensor.contact, 6, 1.0);
    Vector2 moment(0, 0);
    for (std::size_t k = 0; k < load.triangles.size(); ++k)
      for (int i = 0; i < 3; ++i)
        moment += load.local_S[k].row(i).sum() *
                  mesh.nodes_mm.row(mesh.triangles(load.triangles[k], i)).head<2>().transpose();
    const Vector2 centre = moment / load.total_conductance_S();
    EXPECT_NEAR(centre.x(), press.x_mm, 5e-3) << profile_name(profile);
    EXPECT_NEAR(centre.y(), press.y_mm, 5e-3) << profile_name(profile);
  }
}

// Blur → 0: the blurred flat press's frame tends to the exact disc's (the unblurred path). The
// contact law is not linear in P (g ∝ P^1.2, and none below the minimum pressure), so blurring
// the rim changes ∫ g dA at first order, by σ times the rim's length: the difference halves with
// σ (measured 32, 16, 7.9 mV of 588 mV). We ask a ratio below 0.6 and 2 % of the frame at 0.2 mm.
TEST(PressContact, VanishingBlurGivesTheFlatDiscsFrame) {
  const Sensor sensor = load_sensor(test::source_path("examples/sensors/square30.json"));
  MeshOptions options;
  options.element_size_mm = 1.5;
  const Mesh mesh = generate_mesh(sensor, options);
  ForwardModel model(mesh, sensor.sheet_resistance_ohm_per_sq);
  const Press press{12, 17, 4, 8};
  const Frame exact = model.solve_frame(press_contact_load(mesh, {press}, sensor.contact), 3.3);
  std::vector<double> errors;
  for (double blur : {0.8, 0.4, 0.2}) {
    const Frame blurred = model.solve_frame(press_contact_load(mesh, {press}, sensor.contact, 6, blur), 3.3);
    errors.push_back((blurred - exact).cwiseAbs().maxCoeff());
    std::printf("blur %.1f mm: worst difference from the disc %.3e V (frame max %.3f V)\n", blur, errors.back(),
                exact.maxCoeff());
  }
  for (std::size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], 0.6 * errors[i - 1]);
  EXPECT_LT(errors.back(), 0.02 * exact.maxCoeff());
}

}  // namespace
}  // namespace emit
