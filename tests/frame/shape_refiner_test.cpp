// Contact shapes: the ellipse's contact load (its integral and derivatives), and the refit of the
// disc fit's contacts as ellipses, on frames of its own model (the optimiser) and of the twin (a
// finer, different mesh; ADC and noise on).
#include "emit/frame/shape_refiner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/mesh/generate_mesh.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/model/green_function.hpp"
#include "emit/model/measurements.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

struct ShapeBench {
  Sensor sensor = default_sensor();
  Mesh mesh = fit_mesh(sensor);
  DenseGreenFunction green = dense_green_function(mesh, sensor.sheet_resistance_ohm_per_sq);
  MeasurementSet measurements = make_measurement_set(sensor.electrode_count());
  FitPrecompute fit{sensor, mesh, green, measurements};
};

ShapeBench& bench() {
  static ShapeBench s;
  return s;
}

double load_total(const EllipseLoad& load) {
  double sum = 0;
  for (const Eigen::Matrix3d& m : load.local_S) sum += m.sum();  // Σ_ij ∫ g φ_i φ_j = ∫ g
  return sum;
}

TEST(EllipseContact, ItsLoadIntegratesToConductanceTimesArea) {
  ShapeBench& s = bench();
  const EllipseContactIntegrator integrator(s.fit.integrator());
  for (const Ellipse& e : {Ellipse{30, 30, std::log(5.0), 0, 0, 1e-6}, Ellipse{25, 33, std::log(6.0), 0.5, -0.4, 1e-6},
                           Ellipse{30, 28, std::log(4.0), -1.1, 0.2, 1e-6}}) {
    EllipseLoad load;
    integrator.integrate(e, load);
    // The smoothed rim is symmetric about the outline (a smoothstep): what it adds outside it
    // takes inside, to second order in edge/radius of curvature. The quadrature resolves the rim
    // to an eighth of an element. A 1 % bound is ~5× what those leave on these shapes.
    EXPECT_NEAR(load_total(load) / (e.conductance_S_per_mm2 * e.area_mm2()), 1.0, 0.01)
        << "semi-axes " << e.semi_major_mm() << ", " << e.semi_minor_mm();
  }
}

TEST(EllipseContact, ItsDerivativesAreTheLoadsSlopes) {
  ShapeBench& s = bench();
  const EllipseContactIntegrator integrator(s.fit.integrator());
  const Ellipse e{27.3, 31.1, std::log(5.0), 0.6, 0.3, 1e-6};
  EllipseLoad load;
  integrator.integrate(e, load, true);
  for (int j = 0; j < EllipseLoad::shape_parameters; ++j) {
    // Central differences of the load over the same triangles (a step small against the rim's
    // width: the smoothstep is C¹, so the difference's error is O(step) of its second derivative).
    const double step = 1e-5;
    Ellipse plus = e, minus = e;
    double* p = j == 0 ? &plus.x_mm : j == 1 ? &plus.y_mm : j == 2 ? &plus.log_radius : j == 3 ? &plus.p : &plus.q;
    double* m = j == 0 ? &minus.x_mm : j == 1 ? &minus.y_mm : j == 2 ? &minus.log_radius : j == 3 ? &minus.p : &minus.q;
    *p += step, *m -= step;
    EllipseLoad up, down;
    integrator.integrate(plus, up);
    integrator.integrate(minus, down);
    // The triangles touched may differ at the reach's margin, where the load is 0: compare per triangle.
    double largest = 0, error = 0;
    for (std::size_t t = 0; t < load.triangles.size(); ++t) {
      Eigen::Matrix3d difference = Eigen::Matrix3d::Zero();
      for (std::size_t u = 0; u < up.triangles.size(); ++u)
        if (up.triangles[u] == load.triangles[t]) difference += up.local_S[u];
      for (std::size_t u = 0; u < down.triangles.size(); ++u)
        if (down.triangles[u] == load.triangles[t]) difference -= down.local_S[u];
      difference /= 2 * step;
      largest = std::max(largest, load.d_local_S[t][static_cast<std::size_t>(j)].cwiseAbs().maxCoeff());
      error = std::max(error, (difference - load.d_local_S[t][static_cast<std::size_t>(j)]).cwiseAbs().maxCoeff());
    }
    EXPECT_GT(largest, 0) << "parameter " << j;
    EXPECT_LT(error, 1e-4 * largest) << "parameter " << j;
  }
}

TEST(EllipseContact, ItsAxesAndAngleAreTheOutlines) {
  const double angle = 30 * std::numbers::pi / 180, a = 12, b = 3;
  const double e = std::log(std::sqrt(a / b));
  const Ellipse el{10, 20, std::log(std::sqrt(a * b)), e * std::cos(2 * angle), e * std::sin(2 * angle), 1};
  EXPECT_NEAR(el.semi_major_mm(), a, 1e-12);
  EXPECT_NEAR(el.semi_minor_mm(), b, 1e-12);
  EXPECT_NEAR(el.orientation_rad(), angle, 1e-12);
  EXPECT_NEAR(el.area_mm2(), std::numbers::pi * a * b, 1e-9);
  const double c = std::cos(angle), s = std::sin(angle);
  EXPECT_TRUE(el.contains(10 + 0.999 * a * c, 20 + 0.999 * a * s));
  EXPECT_FALSE(el.contains(10 + 1.001 * a * c, 20 + 1.001 * a * s));
  EXPECT_TRUE(el.contains(10 - 0.999 * b * s, 20 + 0.999 * b * c));
  EXPECT_FALSE(el.contains(10 - 1.001 * b * s, 20 + 1.001 * b * c));
}

// The optimiser on frames of its own model: an elongated contact, started from the disc the disc
// fit would give, comes back with its axes and angle.
TEST(ShapeRefiner, RecoversTheEllipseThatMadeTheFrame) {
  ShapeBench& s = bench();
  ShapeRefiner refiner(s.fit);
  const double angle = 35 * std::numbers::pi / 180, e = std::log(std::sqrt(10.0 / 3.0));
  const Ellipse truth{28,
                      33,
                      std::log(std::sqrt(30.0)),
                      e * std::cos(2 * angle),
                      e * std::sin(2 * angle),
                      s.sensor.contact.conductance_S_per_mm2(0.08)};
  const Frame frame = refiner.predict({truth});
  const Vector dV = frame_difference(s.measurements, frame, Frame::Zero(frame.rows(), frame.cols()));
  const Disc start{truth.x_mm + 1, truth.y_mm - 1, s.fit.options().prior_radius_mm,
                   truth.conductance_S_per_mm2 * truth.area_mm2() /
                       (std::numbers::pi * std::pow(s.fit.options().prior_radius_mm, 2))};
  // The area is held at the prior's (a frame does not tell it): here the truth's.
  const std::vector<RefinedContact>& r = refiner.refine(dV, {start}, {std::sqrt(30.0), ShapeOptions{}.log_radius_std});
  ASSERT_EQ(r.size(), 1u);
  const Ellipse& got = r[0].ellipse;
  std::printf("semi-axes %.3f x %.3f mm at %.2f deg (truth 10 x 3 at 35); sigma area %.3f, angle %.2f deg\n",
              got.semi_major_mm(), got.semi_minor_mm(), got.orientation_rad() * 180 / std::numbers::pi,
              r[0].log_area_std, r[0].orientation_std_rad * 180 / std::numbers::pi);
  // Noise-free frames: only the elongation prior's pull (its residual is a few units where the
  // data's are thousands of σ) and the solver's tolerance remain.
  EXPECT_NEAR(got.x_mm, truth.x_mm, 0.01);
  EXPECT_NEAR(got.y_mm, truth.y_mm, 0.01);
  EXPECT_NEAR(got.orientation_rad(), angle, 0.5 * std::numbers::pi / 180);
  EXPECT_NEAR(got.semi_major_mm() / 10, 1, 0.02);
  EXPECT_NEAR(got.semi_minor_mm() / 3, 1, 0.02);
}

// Nothing lost: single round presses of the twin (ADC and noise on) keep the disc fit's place,
// and their area (held at the prior's: the frame does not pin a round contact's size) lies within
// its reported 2σ of the truth, radii 3–7 mm against the prior's 5.
TEST(ShapeRefiner, KeepsRoundPressesInPlaceWithAnHonestArea) {
  ShapeBench& s = bench();
  Twin twin{s.sensor, [] {
              TwinOptions o;
              o.mesh_seed = 4;
              return o;
            }()};
  ContactFitter fitter(s.fit);
  ShapeRefiner refiner(s.fit);
  double total_mm = 0;
  const std::vector<Press> presses{{21.3, 34.7, 5, 8}, {8, 9, 5, 4}, {45, 15, 3, 2}, {30, 30, 7, 20}};
  for (const Press& press : presses) {
    const Vector dV = frame_difference(s.measurements, twin.frame({press}), twin.frame({}));
    const FitResult& fit = fitter.fit(dV, {Disc{press.x_mm + 2, press.y_mm - 2, 0, 0}});
    ASSERT_EQ(fit.contacts.size(), 1u);
    const std::vector<RefinedContact>& r =
        refiner.refine(dV, {fit.contacts[0].disc}, {5.0, ShapeOptions{}.log_radius_std});
    ASSERT_EQ(r.size(), 1u);
    const double error = std::hypot(r[0].ellipse.x_mm - press.x_mm, r[0].ellipse.y_mm - press.y_mm);
    const double true_area = std::numbers::pi * press.radius_mm * press.radius_mm;
    const double log_area_error = std::log(r[0].ellipse.area_mm2() / true_area);
    std::printf("press %.1f, %.1f r %.0f: error %.3f mm, area %.1f mm2 (true %.1f, log sigma %.2f), a/b %.2f\n",
                press.x_mm, press.y_mm, press.radius_mm, error, r[0].ellipse.area_mm2(), true_area, r[0].log_area_std,
                r[0].ellipse.semi_major_mm() / r[0].ellipse.semi_minor_mm());
    total_mm += error;
    EXPECT_LT(std::abs(log_area_error), 2 * r[0].log_area_std);
    // Round: the ellipse stays within the elongation the twin's mesh and noise allow.
    EXPECT_LT(r[0].ellipse.semi_major_mm() / r[0].ellipse.semi_minor_mm(), 1.5);
  }
  EXPECT_LT(total_mm / static_cast<double>(presses.size()), 0.3);  // the 60 mm sheet's target
}

// A ruler's edge: a 30 × 3 mm bar at 30°, pressed by the twin as a row of small flat presses
// (overlapping: its pressure is uneven along it). The disc fit covers it with two discs; the refit
// makes it one region whose axis and length are the bar's: the ellipse of its second moments has
// a semi-major axis of 30/√3 = 17.3 mm.
TEST(ShapeRefiner, MakesABarOneRegionAlongIt) {
  ShapeBench& s = bench();
  Twin twin{s.sensor, [] {
              TwinOptions o;
              o.mesh_seed = 4;
              return o;
            }()};
  const double angle = std::numbers::pi / 6, c = std::cos(angle), sn = std::sin(angle);
  std::vector<Press> bar;
  for (int i = 0; i < 12; ++i) {
    const double t = -15 + 1.5 + i * 27.0 / 11;
    bar.push_back(Press{30 + t * c, 30 + t * sn, 1.5, 8.0 / 12});
  }
  const Vector dV = frame_difference(s.measurements, twin.frame(bar), twin.frame({}));
  ContactFitter fitter(s.fit);
  const FitResult& fit = fitter.fit(dV, {Disc{32, 31, 0, 0}});
  std::vector<Disc> discs;
  for (const FittedContact& f : fit.contacts) discs.push_back(f.disc);
  ShapeRefiner refiner(s.fit);
  const std::vector<RefinedContact>& r = refiner.refine(dV, discs, {5.0, ShapeOptions{}.log_radius_std});
  ASSERT_EQ(r.size(), 1u) << "the disc fit gave " << discs.size();
  const Ellipse& e = r[0].ellipse;
  std::printf("bar: %zu discs -> 1 region %.2f x %.2f mm at %.1f deg (1 sigma %.1f), centre %.2f, %.2f\n", discs.size(),
              e.semi_major_mm(), e.semi_minor_mm(), e.orientation_rad() * 180 / std::numbers::pi,
              r[0].orientation_std_rad * 180 / std::numbers::pi, e.x_mm, e.y_mm);
  EXPECT_NEAR(e.orientation_rad() * 180 / std::numbers::pi, 30, 3);  // the target: 10°
  EXPECT_NEAR(e.semi_major_mm() / (30 / std::sqrt(3.0)), 1, 0.1);
  EXPECT_LT(std::hypot(e.x_mm - 30, e.y_mm - 30), 0.3);
  EXPECT_LT(std::abs(e.orientation_rad() * 180 / std::numbers::pi - 30),
            3 * r[0].orientation_std_rad * 180 / std::numbers::pi + 1);
}

// Issue 31's "no splits of one bar into two": a flat 24 × 4 mm bar at (20, 40) mm, 30°, that
// `emit reconstruct --method shapes` reported as two ellipses at −17° and −45° while the same bar
// at (30, 30) came out as one within 1°. The disc fit covers it with two discs; their merge, tried
// from a round ellipse, had not become the long one in a trial's iterations (χ² 6272 where the
// converged merge is 135, the two contacts' 124, BIC's price 33). Started from the pair's combined
// second moment, it is one region along the bar.
TEST(ShapeRefiner, MakesABarOneRegionWhereItWasSplit) {
  ShapeBench& s = bench();
  // The frames `emit simulate` makes (a twin of its default mesh and noise seeds for each run):
  // the bar's, and a reference of three frames without a press, averaged as `emit reconstruct` does.
  Twin twin{s.sensor}, reference_twin{s.sensor};
  const Frame pressed = twin.frame({bar_press({20, 40}, 24, 4, 30, 10)});
  Frame reference = reference_twin.frame({});
  for (int i = 0; i < 2; ++i) reference += reference_twin.frame({});
  const Vector dV = frame_difference(s.measurements, pressed, reference / 3);
  ContactFitter fitter(s.fit);
  const FitResult& fit = fitter.fit(dV, {Disc{20, 40, 0, 0}});
  std::vector<Disc> discs;
  for (const FittedContact& f : fit.contacts) discs.push_back(f.disc);
  ShapeRefiner refiner(s.fit);
  const std::vector<RefinedContact>& r = refiner.refine(dV, discs, {5.0, ShapeOptions{}.log_radius_std});
  for (const RefinedContact& c : r)
    std::printf("bar at (20, 40), 30 deg: %zu discs -> region %.2f x %.2f mm at %.1f deg, centre %.2f, %.2f\n",
                discs.size(), c.ellipse.semi_major_mm(), c.ellipse.semi_minor_mm(),
                c.ellipse.orientation_rad() * 180 / std::numbers::pi, c.ellipse.x_mm, c.ellipse.y_mm);
  ASSERT_EQ(discs.size(), 2u) << "the case is the disc fit's two discs on one bar";
  ASSERT_EQ(r.size(), 1u);                                                       // the bar is one region
  EXPECT_NEAR(r[0].ellipse.orientation_rad() * 180 / std::numbers::pi, 30, 10);  // the target
}

// Four round fingers (r 5 mm, 20 mm apart, the benchmark's frame) stay four round contacts where
// the disc fit put them. With every contact's elongation free, the elongations took up the model's
// error: they came back as a pinwheel of sticks 12–16 mm long (a/b 6–10), each centre moved 2–4 mm
// along its stick. a/b < 1.5 as for single round presses above; 0.5 mm beyond the disc's own
// error: the refit does not move a round press (single presses: ~0.1 mm).
TEST(ShapeRefiner, KeepsFourRoundFingersRoundAndInPlace) {
  ShapeBench& s = bench();
  Twin twin{s.sensor, [] {
              TwinOptions o;
              o.mesh_seed = 3;
              return o;
            }()};
  const std::vector<Press> presses{{18, 18, 5, 8}, {38, 18, 5, 10}, {18, 38, 5, 12}, {38, 38, 5, 9}};
  const Vector dV = frame_difference(s.measurements, twin.frame(presses), twin.frame({}));
  ContactFitter fitter(s.fit);
  std::vector<Disc> seeds;
  seeds.reserve(presses.size());
  for (const Press& p : presses) seeds.push_back({p.x_mm + 1, p.y_mm - 1, 0, 0});
  const FitResult& fit = fitter.fit(dV, seeds);
  std::vector<Disc> discs;
  for (const FittedContact& f : fit.contacts) discs.push_back(f.disc);
  ASSERT_EQ(discs.size(), 4u) << "the case is the disc fit's four contacts";
  const auto nearest_press_mm = [&](double x, double y) {
    double d = 1e9;
    for (const Press& p : presses) d = std::min(d, std::hypot(x - p.x_mm, y - p.y_mm));
    return d;
  };
  double worst_disc_mm = 0;
  for (const Disc& d : discs) worst_disc_mm = std::max(worst_disc_mm, nearest_press_mm(d.x_mm, d.y_mm));
  ShapeRefiner refiner(s.fit);
  const std::vector<RefinedContact>& r = refiner.refine(dV, discs, {5.0, ShapeOptions{}.log_radius_std});
  ASSERT_EQ(r.size(), 4u);
  for (const RefinedContact& c : r) {
    const double error = nearest_press_mm(c.ellipse.x_mm, c.ellipse.y_mm);
    std::printf("finger: %.2f x %.2f mm at (%.2f, %.2f), %.2f mm from its press (discs' worst %.2f)\n",
                c.ellipse.semi_major_mm(), c.ellipse.semi_minor_mm(), c.ellipse.x_mm, c.ellipse.y_mm, error,
                worst_disc_mm);
    EXPECT_LT(error, worst_disc_mm + 0.5);
    EXPECT_LT(c.ellipse.semi_major_mm() / c.ellipse.semi_minor_mm(), 1.5);
  }
}

}  // namespace
}  // namespace emit
