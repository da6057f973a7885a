// Contact shapes on curved sheets (frame/ellipse_contact.hpp): the ellipse in the tangent plane at
// its centre, its load against the surface's area in closed form, its derivatives against finite
// differences, and the refit of the twin's presses on the dome (a finer, different mesh; ADC and
// noise on) against the disc fit's place.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "emit/frame/shape_refiner.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/model/green_function.hpp"
#include "emit/model/measurements.hpp"
#include "emit/sensor/press.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

struct DomeBench {
  Sensor sensor = load_sensor(test::source_path("examples/sensors/dome25.json"));
  Mesh mesh = fit_mesh(sensor);
  DenseGreenFunction green = fit_green_function(mesh, sensor, nullptr);
  MeasurementSet measurements = make_measurement_set(sensor.electrode_count());
  FitPrecompute fit{sensor, mesh, green, measurements};
};

DomeBench& dome() {
  static DomeBench d;
  return d;
}

double load_total(const EllipseLoad& load) {
  double sum = 0;
  for (const Eigen::Matrix3d& m : load.local_S) sum += m.sum();  // Σ_ij ∫ g φ_i φ_j = ∫ g
  return sum;
}

// At the dome's apex the tangent plane is z's, and a round ellipse of radius r covers the points
// seen from +z within r: a zone of the sphere of area 2πR(R − √(R² − r²)) (Archimedes), r²/4R²
// (1 %) more than πr². The load carries g times that area within the flat sheet's 1 % (the smoothed
// rim and its quadrature, shape_refiner_test's bound), and an ellipse's too (its area the zone's
// at its equal-area radius, to (r/R)² of that 1 %).
TEST(CurvedShapes, AnEllipsesLoadOnTheDomeCarriesItsSurfaceArea) {
  DomeBench& d = dome();
  const EllipseContactIntegrator integrator(d.fit.integrator());
  const double R = d.sensor.shape.sphere_radius_mm;
  for (const Ellipse& e : {Ellipse{0, 0, std::log(5.0), 0, 0, 1e-6}, Ellipse{0, 0, std::log(3.0), 0, 0, 1e-6},
                           Ellipse{0, 0, std::log(4.0), 0.4, -0.3, 1e-6}}) {
    EllipseLoad load;
    integrator.integrate(e, load);
    const double r = std::exp(e.log_radius);
    const double zone_mm2 = 2 * std::numbers::pi * R * (R - std::sqrt(R * R - r * r));
    std::printf("apex ellipse %.2f x %.2f mm: load / (g zone) %.4f, / (g pi a b) %.4f\n", e.semi_major_mm(),
                e.semi_minor_mm(), load_total(load) / (e.conductance_S_per_mm2 * zone_mm2),
                load_total(load) / (e.conductance_S_per_mm2 * e.area_mm2()));
    EXPECT_NEAR(load_total(load) / (e.conductance_S_per_mm2 * zone_mm2), 1.0, 0.01);
  }
}

// Around a sleeve the chart is an isometry: an ellipse across the chart's seam (v = 0 =
// 2πR) carries g·πab as on a flat sheet (the facets' area is the cylinder's to h²/24R² < 0.03 %).
TEST(CurvedShapes, AnEllipseAcrossTheSleevesSeamCarriesItsArea) {
  const Sensor sensor = load_sensor(test::source_path("examples/sensors/sleeve.json"));
  const Mesh mesh = fit_mesh(sensor);
  const DiscContactIntegrator discs(mesh, 0.6, 3, sensor.shape);
  const EllipseContactIntegrator integrator(discs);
  const double round_mm = 2 * std::numbers::pi * sensor.shape.radius_mm;
  for (const double v : {0.5, round_mm - 0.5, round_mm / 2})
    for (const Ellipse& e :
         {Ellipse{30, v, std::log(5.0), 0, 0, 1e-6}, Ellipse{25, v, std::log(5.0), 0.5, 0.4, 1e-6}}) {
      EllipseLoad load;
      integrator.integrate(e, load);
      EXPECT_NEAR(load_total(load) / (e.conductance_S_per_mm2 * e.area_mm2()), 1.0, 0.01)
          << "v " << v << ", semi-axes " << e.semi_major_mm() << ", " << e.semi_minor_mm();
      // The picture's test agrees: the centre and a point just inside along the major axis, both
      // sides of the seam.
      const Vector2 major(std::cos(e.orientation_rad()), std::sin(e.orientation_rad()));
      EXPECT_TRUE(
          integrator.contains(e, Vector2(e.x_mm, e.y_mm) + 0.99 * e.semi_major_mm() * major + Vector2(0, round_mm)));
      EXPECT_FALSE(integrator.contains(e, Vector2(e.x_mm, e.y_mm) + 1.01 * e.semi_major_mm() * major));
    }
}

// Off the apex the tangent plane turns with the centre, and the centre's derivatives carry its
// turn (ellipse_contact.cpp): central differences agree as on the flat sheet (shape_refiner_test).
TEST(CurvedShapes, ItsDerivativesOnTheDomeAreTheLoadsSlopes) {
  DomeBench& d = dome();
  const EllipseContactIntegrator integrator(d.fit.integrator());
  const Ellipse e{7.3, -5.1, std::log(4.0), 0.6, 0.3, 1e-6};
  EllipseLoad load;
  integrator.integrate(e, load, true);
  for (int j = 0; j < EllipseLoad::shape_parameters; ++j) {
    const double step = 1e-5;
    Ellipse plus = e, minus = e;
    double* p = j == 0 ? &plus.x_mm : j == 1 ? &plus.y_mm : j == 2 ? &plus.log_radius : j == 3 ? &plus.p : &plus.q;
    double* m = j == 0 ? &minus.x_mm : j == 1 ? &minus.y_mm : j == 2 ? &minus.log_radius : j == 3 ? &minus.p : &minus.q;
    *p += step, *m -= step;
    EllipseLoad up, down;
    integrator.integrate(plus, up);
    integrator.integrate(minus, down);
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

// Nothing lost on the dome: the twin's round presses (r 3–6 mm, ADC and noise on), refined by
// shapes from the disc fit's contact, keep its place, and their area (held at the prior's: a frame
// does not pin a round contact's size) lies within its reported 2σ of the truth. The bounds on the
// place: the 0.3 mm for single presses; and no farther from the truth than the fit's own
// error plus 0.1 mm. The fit's place on the dome is good to 0.06 mm (p95, `emit eval --sheet
// dome`), and on 36 random presses (docs/physics.md, "On a curved sheet") shapes' error exceeded
// the fit's by at most 0.061 mm; the chart's frozen metric, tried first, lost 0.27 mm on average.
TEST(CurvedShapes, KeepsDomePressesInPlaceWithAnHonestArea) {
  DomeBench& d = dome();
  Twin twin{d.sensor, [] {
              TwinOptions o;
              o.mesh_seed = 4;
              return o;
            }()};
  ContactFitter fitter(d.fit);
  ShapeRefiner refiner(d.fit);
  const Frame empty = twin.frame({});
  for (const auto& [chart, radius_mm, force_N] :
       {std::tuple{Vector2(0, 0), 5.0, 10.0}, std::tuple{Vector2(7, -5), 4.0, 8.0},
        std::tuple{Vector2(-9, 6), 3.0, 4.0}, std::tuple{Vector2(3, 11), 6.0, 15.0}}) {
    const Press press = press_at_chart(d.sensor.shape, chart, radius_mm, force_N);
    const Vector dV = frame_difference(d.measurements, twin.frame({press}), empty);
    const FitResult& fit = fitter.fit(dV, {Disc{chart.x() + 1.5, chart.y() - 1.5, 0, 0}});
    ASSERT_EQ(fit.contacts.size(), 1u);
    const Disc disc = fit.contacts[0].disc;
    const std::vector<RefinedContact>& r = refiner.refine(dV, {disc}, {5.0, ShapeOptions{}.log_radius_std});
    ASSERT_EQ(r.size(), 1u);
    const Vector3 truth(press.x_mm, press.y_mm, press.z_mm);
    const double fit_error = (surface_point_mm(d.sensor.shape, {disc.x_mm, disc.y_mm}) - truth).norm();
    const double error = (surface_point_mm(d.sensor.shape, {r[0].ellipse.x_mm, r[0].ellipse.y_mm}) - truth).norm();
    const double true_area = std::numbers::pi * radius_mm * radius_mm;  // a chord radius: Archimedes
    const double log_area_error = std::log(r[0].ellipse.area_mm2() / true_area);
    std::printf(
        "dome press (%.0f, %.0f) r %.0f: fit %.3f mm, shapes %.3f mm; area %.1f mm2 (true %.1f, log %.2f, "
        "sigma %.2f), a/b %.2f\n",
        chart.x(), chart.y(), radius_mm, fit_error, error, r[0].ellipse.area_mm2(), true_area, log_area_error,
        r[0].log_area_std, r[0].ellipse.semi_major_mm() / r[0].ellipse.semi_minor_mm());
    EXPECT_LT(error, 0.3);
    EXPECT_LT(error, fit_error + 0.1);
    EXPECT_LT(std::abs(log_area_error), 2 * r[0].log_area_std);
    EXPECT_LT(r[0].ellipse.semi_major_mm() / r[0].ellipse.semi_minor_mm(), 1.5);  // round stays round
  }
}

// A bar off the dome's apex, as the twin can press one on a curved sheet (its `bar:` outlines are
// flat sheets only): a row of 8 small flat presses along a line of the tangent plane at (6, −4) at
// −45° from the chart's x direction there, each lifted onto the surface. The refit makes it one
// region along the row: its angle within the flat sheet's 3° (shape_refiner_test; the issue's
// target is 10°), its centre within 0.3 mm of the row's.
TEST(CurvedShapes, MakesABarOffTheDomesApexOneRegionAlongIt) {
  DomeBench& d = dome();
  Twin twin{d.sensor, [] {
              TwinOptions o;
              o.mesh_seed = 4;
              return o;
            }()};
  const Vector2 centre(6, -4);
  const Vector3 P0 = surface_point_mm(d.sensor.shape, centre);
  const Eigen::Matrix<double, 3, 2> T = surface_tangents(d.sensor.shape, centre);
  const Vector3 e1 = T.col(0).normalized(), e2 = (T.col(1) - e1.dot(T.col(1)) * e1).normalized();
  const double angle = -std::numbers::pi / 4;
  std::vector<Press> bar;
  for (int i = 0; i < 8; ++i) {
    const double t = -8 + 1.5 + i * 13.0 / 7;
    const Vector3 q = P0 + t * (std::cos(angle) * e1 + std::sin(angle) * e2);
    bar.push_back(press_at_chart(d.sensor.shape, q.head<2>(), 1.5, 8.0 / 8));
  }
  const Vector dV = frame_difference(d.measurements, twin.frame(bar), twin.frame({}));
  ContactFitter fitter(d.fit);
  const FitResult& fit = fitter.fit(dV, {Disc{centre.x(), centre.y(), 0, 0}});
  std::vector<Disc> discs;
  for (const FittedContact& f : fit.contacts) discs.push_back(f.disc);
  ShapeRefiner refiner(d.fit);
  const std::vector<RefinedContact>& r = refiner.refine(dV, discs, {5.0, ShapeOptions{}.log_radius_std});
  ASSERT_EQ(r.size(), 1u) << "the disc fit gave " << discs.size();
  const Ellipse& e = r[0].ellipse;
  std::printf("dome bar: %zu discs -> 1 region %.2f x %.2f mm at %.1f deg (1 sigma %.1f), centre %.2f, %.2f\n",
              discs.size(), e.semi_major_mm(), e.semi_minor_mm(), e.orientation_rad() * 180 / std::numbers::pi,
              r[0].orientation_std_rad * 180 / std::numbers::pi, e.x_mm, e.y_mm);
  EXPECT_NEAR(e.orientation_rad() * 180 / std::numbers::pi, -45, 3);
  EXPECT_LT((surface_point_mm(d.sensor.shape, {e.x_mm, e.y_mm}) - P0).norm(), 0.3);
}

}  // namespace
}  // namespace emit
