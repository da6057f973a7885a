// What a frame can tell (eval/resolvability.hpp) on the default 60 mm sheet: properties the
// physics fixes, measured on the exact forward model of contact fitting.
#include "emit/eval/resolvability.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/frame/contact_fitter.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {
namespace {

struct Bench {
  Sensor sensor = default_sensor();
  FitModel fit = build_fit_model(sensor);
  MeasurementSet measurements = make_measurement_set(sensor.electrode_count());
  Resolvability r{sensor, fit, measurements};
};

Bench& bench() {
  static Bench b;
  return b;
}

// The outline integrator (a signed distance, its rim smoothed over ±0.5 mm) and the fitter's disc
// (its rim over ±a quarter of the mesh size) draw the same disc: a symmetric smoothing of the rim
// keeps its area to O((h/r)²), 1 % at r = 5 mm, so the frames agree to a few per cent.
TEST(Resolvability, OutlineFrameIsTheFittersDisc) {
  Bench& b = bench();
  const double g = b.sensor.contact.conductance_S_per_mm2(0.1);
  const Vector2 c(24, 35);
  const Vector outline = b.r.region_dV([&](const Vector2& p) { return (p - c).norm() - 5; }, g);
  ContactFitter fitter(b.sensor, b.fit.mesh, b.fit.green, b.measurements);
  const Frame frame = fitter.predict({Disc{c.x(), c.y(), 5, g}});
  Vector disc(b.measurements.size());
  for (int i = 0; i < b.measurements.size(); ++i) disc[i] = frame.data()[b.measurements.frame_index[i]];
  const double relative = (outline - disc).norm() / disc.norm();
  std::printf("outline vs the fitter's disc: %.4f relative\n", relative);
  EXPECT_LT(relative, 0.03);
}

// The Fisher information's derivative (the predictor's, differentiated through the Woodbury
// solve) against central differences of the fitter's own frame of the same disc: the disc's rim is
// a C¹ step, so the differences' error is first order in the step, 1e-4 mm or 1e-4 in log g: well
// under 1e-3 of each column.
TEST(Resolvability, JacobianMatchesFiniteDifferences) {
  Bench& b = bench();
  const Vector2 c(22, 37);
  const double r = 4, force = 8;
  const Eigen::Matrix<double, Eigen::Dynamic, 4> J = b.r.round_contact_jacobian(c, r, force);
  ContactFitter fitter(b.sensor, b.fit.mesh, b.fit.green, b.measurements);
  const double g = b.sensor.contact.conductance_S_per_mm2(force / (std::numbers::pi * r * r));
  const auto dV = [&](Disc d) {
    const Frame frame = fitter.predict({d});
    Vector v(b.measurements.size());
    for (int i = 0; i < b.measurements.size(); ++i) v[i] = frame.data()[b.measurements.frame_index[i]];
    return v;
  };
  const double h = 1e-4;
  const Disc d{c.x(), c.y(), r, g};
  const Vector columns[4] = {(dV({d.x_mm + h, d.y_mm, r, g}) - dV({d.x_mm - h, d.y_mm, r, g})) / (2 * h),
                             (dV({d.x_mm, d.y_mm + h, r, g}) - dV({d.x_mm, d.y_mm - h, r, g})) / (2 * h),
                             (dV({d.x_mm, d.y_mm, r + h, g}) - dV({d.x_mm, d.y_mm, r - h, g})) / (2 * h),
                             (dV({d.x_mm, d.y_mm, r, g * std::exp(h)}) - dV({d.x_mm, d.y_mm, r, g * std::exp(-h)})) /
                                 (2 * h)};
  for (int k = 0; k < 4; ++k) {
    const Vector analytic = J.col(k) * b.r.noise_V();
    EXPECT_LT((analytic - columns[k]).norm(), 1e-3 * columns[k].norm()) << "column " << k;
  }
}

// A radially symmetric contact looks like a point from outside it (the mean-value property): the
// frame pins its centre and its total conductance g·πr², its radius only weakly (through the
// contact's own loading of the sheet and the border's images, both growing with r and nearer the
// border). So one frame does not tell a round press's size (σ_r > r), the radius's bound is far
// above the centre's and the total's far below g's, a smaller disc is told worse, and one nearer
// the border better. At the centre of the square sheet, whose electrodes are symmetric under x ↔ y,
// the frame's sensitivities to x and to y agree but for the fit mesh's asymmetry (5 %); the full
// σ_x and σ_y less so (measured 11 % apart), as their small mesh-made couplings to the nearly
// degenerate pair (r, log g) weigh in the inverse.
TEST(Resolvability, FramePinsTheCentreAndTotalNotTheRadius) {
  Bench& b = bench();
  const Vector2 centre(30, 30);
  const RoundContactBound small = b.r.round_contact_bound(centre, 3, 8);
  std::printf("r 3 mm, 8 N at the centre: sigma x %.4f y %.4f r %.4f mm, log g %.4f, log total %.4f, log F %.4f\n",
              small.x_std_mm, small.y_std_mm, small.radius_std_mm, small.log_conductance_std, small.log_total_std,
              small.log_force_std);
  EXPECT_GT(small.radius_std_mm, 3.0);
  EXPECT_GT(small.radius_std_mm, 100 * small.x_std_mm);
  EXPECT_LT(small.log_total_std, small.log_conductance_std / 10);
  const Eigen::Matrix<double, Eigen::Dynamic, 4> J = b.r.round_contact_jacobian(centre, 3, 8);
  EXPECT_NEAR(J.col(0).norm(), J.col(1).norm(), 0.05 * J.col(0).norm());
  const double tiny = b.r.round_contact_bound(centre, 2, 8).radius_std_mm;
  const double large = b.r.round_contact_bound(centre, 6, 8).radius_std_mm;
  const double near_border = b.r.round_contact_bound({46, 30}, 3, 8).radius_std_mm;
  std::printf("sigma r: r 2 mm %.2f, r 6 mm %.2f at the centre; r 3 mm 16 mm from it %.2f\n", tiny, large, near_border);
  EXPECT_GT(tiny, large);
  EXPECT_LT(near_border, small.radius_std_mm);
}

// Two bars with no gap are one bar (the fit starts there: Δχ² = 0); the wider the gap, the more
// their frame departs from any single bar's.
TEST(Resolvability, BarsPartWithTheirGap) {
  Bench& b = bench();
  const Vector2 c(30, 30);
  const double none = b.r.two_bars_against_one(c, 3, 20, 0, 0.1).delta_chi2;
  const double close = b.r.two_bars_against_one(c, 3, 20, 2, 0.1).delta_chi2;
  const AlternativeFit wide_fit = b.r.two_bars_against_one(c, 3, 20, 6, 0.1);
  const double wide = wide_fit.delta_chi2;
  std::printf(
      "two bars 3 x 20 mm, 0.1 N/mm2: delta chi2 %.3g (no gap), %.3g (2 mm), %.3g (6 mm; the frame's own %.3g; "
      "one bar %.2f x %.2f mm)\n",
      none, close, wide, wide_fit.signal_chi2, wide_fit.parameters[0], wide_fit.parameters[1]);
  EXPECT_LT(none, 1e-6);
  EXPECT_GT(wide, close);
  // A single bar held at the bars' own pressure is a narrower alternative: it can only explain
  // them worse (a minimum over fewer bars), measured 1.4 against 0.16.
  const double held = b.r.two_bars_against_one(c, 3, 20, 6, 0.1, true).delta_chi2;
  std::printf("... the single bar at their pressure: %.3g\n", held);
  EXPECT_GT(held, wide);
}

// A ring whose hole closes is a disc; the larger the hole, the more its frame departs from any disc's.
TEST(Resolvability, RingHoleShowsWithItsSize) {
  Bench& b = bench();
  const Vector2 c(30, 30);
  const double none = b.r.ring_against_disc(c, 0, 9, 0.1).delta_chi2;
  const double small = b.r.ring_against_disc(c, 3, 9, 0.1).delta_chi2;
  const double large = b.r.ring_against_disc(c, 6, 9, 0.1).delta_chi2;
  std::printf("ring of outer r 9 mm, 0.1 N/mm2: delta chi2 %.3g (no hole), %.3g (hole 3 mm), %.3g (hole 6 mm)\n", none,
              small, large);
  EXPECT_LT(none, 1e-6);
  EXPECT_GT(large, small);
}

}  // namespace
}  // namespace emit
