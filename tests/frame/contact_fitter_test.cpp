// Contact fitting on frames of the twin (a finer, different mesh; ADC and noise on): single
// presses to a tenth of a millimetre, two presses as two contacts, no false contact.
#include "emit/frame/contact_fitter.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/mesh/generate_mesh.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/model/green_function.hpp"
#include "emit/model/measurements.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

struct FitBench {
  Sensor sensor = default_sensor();
  Mesh mesh = generate_mesh(sensor, [this] {
    MeshOptions o = reconstruction_mesh_options(sensor);
    o.electrode_edge_size_factor = 0.25;
    return o;
  }());
  DenseGreenFunction green = dense_green_function(mesh, sensor.sheet_resistance_ohm_per_sq);
  MeasurementSet measurements = make_measurement_set(sensor.electrode_count());
  Twin twin{sensor, [] {
              TwinOptions o;
              o.mesh_seed = 4;
              return o;
            }()};
  Vector dV(const std::vector<Press>& presses) {
    return frame_difference(measurements, twin.frame(presses), twin.frame({}));
  }
};

FitBench& bench() {
  static FitBench s;
  return s;
}

TEST(ContactFitter, RecoversTheDiscThatMadeTheFrame) {
  FitBench& s = bench();
  FitOptions options;
  options.prior_radius_mm = 5;  // the truth's: with the radius held, the rest is identifiable
  ContactFitter fitter(s.sensor, s.mesh, s.green, s.measurements, options);
  const Disc truth{21.3, 34.7, 5, 3.2e-7};
  const Frame frame = fitter.predict({truth});
  const Vector dV = frame_difference(s.measurements, frame, Frame::Zero(frame.rows(), frame.cols()));
  const FitResult& r = fitter.fit(dV, {Disc{truth.x_mm + 3, truth.y_mm - 3, 0, 0}});
  ASSERT_EQ(r.contacts.size(), 1u);
  // Noise-free frames of the fitter's own model: only the optimiser's tolerance remains.
  EXPECT_NEAR(r.contacts[0].disc.x_mm, truth.x_mm, 1e-4);
  EXPECT_NEAR(r.contacts[0].disc.y_mm, truth.y_mm, 1e-4);
  EXPECT_NEAR(r.contacts[0].disc.conductance_S_per_mm2, truth.conductance_S_per_mm2,
              1e-5 * truth.conductance_S_per_mm2);
}

TEST(ContactFitter, FindsSinglePressesOnTheTwinToATenthOfAMillimetre) {
  FitBench& s = bench();
  ContactFitter fitter(s.sensor, s.mesh, s.green, s.measurements);
  double total_mm = 0;
  const std::vector<Press> presses{{21.3, 34.7, 5, 8}, {8, 9, 5, 4}, {45, 15, 3, 2}, {30, 30, 5, 20}, {52, 50, 5, 1.5}};
  for (const Press& press : presses) {
    const FitResult& r = fitter.fit(s.dV({press}), {Disc{press.x_mm + 2, press.y_mm - 2, 0, 0}});
    ASSERT_EQ(r.contacts.size(), 1u) << "a false contact at " << press.x_mm << ", " << press.y_mm;
    const double error = std::hypot(r.contacts[0].disc.x_mm - press.x_mm, r.contacts[0].disc.y_mm - press.y_mm);
    std::printf("press %.1f, %.1f: error %.3f mm (1 sigma %.3f mm), misfit %.2f mV\n", press.x_mm, press.y_mm, error,
                r.contacts[0].x_std_mm, 1e3 * r.rms_misfit_V);
    total_mm += error;
    // The fit explains the frame down to about the readings' noise (1 mV): the model is right.
    EXPECT_LT(r.rms_misfit_V, 2.5 * fitter.noise_V());
  }
  // The 60 mm sheet's target: a mean of 0.3 mm (the paper's method: ~3.3 mm).
  EXPECT_LT(total_mm / static_cast<double>(presses.size()), 0.3);
}

TEST(ContactFitter, FindsTwoPressesAsTwoContacts) {
  FitBench& s = bench();
  ContactFitter fitter(s.sensor, s.mesh, s.green, s.measurements);
  const std::vector<Press> presses{{20, 25, 5, 10}, {42, 38, 5, 6}};
  // Seeded with the stronger press only: the second must come from the residual.
  const auto residual_seed = [&](const Vector&, Disc& seed) {
    seed = {40, 40, 0, 0};  // where a linear image of the residual would peak, roughly
    return true;
  };
  const FitResult& r = fitter.fit(s.dV(presses), {Disc{21, 24, 0, 0}}, residual_seed);
  ASSERT_EQ(r.contacts.size(), 2u);
  for (const Press& p : presses) {
    double nearest = 1e9;
    for (const FittedContact& c : r.contacts)
      nearest = std::min(nearest, std::hypot(c.disc.x_mm - p.x_mm, c.disc.y_mm - p.y_mm));
    EXPECT_LT(nearest, 0.5) << "press at " << p.x_mm << ", " << p.y_mm;  // target: within 2 mm in 95 % of frames
  }
}

/// The distance from `press` to the nearest fitted contact.
double nearest_contact_mm(const FitResult& r, const Press& press) {
  double nearest = 1e9;
  for (const FittedContact& c : r.contacts)
    nearest = std::min(nearest, std::hypot(c.disc.x_mm - press.x_mm, c.disc.y_mm - press.y_mm));
  return nearest;
}

// Three and four presses ≥ 20 mm apart of 8–12 N, seeded with the first press alone: the others
// must come from the fitter's own search (its atoms). Issue 31's target is every press within
// 2 mm in ≥ 95 % (three) and ≥ 90 % (four) of frames ≥ 12 mm apart; the fit misses where the held
// disc's model error says more than the frame says of a press's place (docs/physics.md, "What
// limits four"): a press inside the others, a weak one among strong ones, and with some noise
// draws even a triangle 24 mm apart (3–5 mm off). These frames, a wide triangle of equal presses
// and a square, with their own noise draw, must be found to the target's 2 mm with no contact left
// over: a fit that breaks its search for several contacts fails here. A twin of its own, with its
// own noise: the frames do not depend on the tests before.
TEST(ContactFitter, FindsThreeAndFourPressesApart) {
  FitBench& s = bench();
  Twin twin{s.sensor, [] {
              TwinOptions o;
              o.mesh_seed = 4;
              o.noise_seed = 31;
              return o;
            }()};
  const Frame reference = twin.frame({});
  ContactFitter fitter(s.sensor, s.mesh, s.green, s.measurements);
  const std::vector<std::vector<Press>> frames{{{15, 15, 5, 10}, {45, 15, 5, 10}, {30, 45, 5, 10}},
                                               {{18, 18, 5, 8}, {40, 18, 5, 10}, {18, 40, 5, 12}, {40, 40, 5, 9}}};
  for (const std::vector<Press>& presses : frames) {
    const Press& first = presses.front();
    const FitResult& r = fitter.fit(frame_difference(s.measurements, twin.frame(presses), reference),
                                    {Disc{first.x_mm + 1, first.y_mm - 1, 0, 0}});
    EXPECT_EQ(r.contacts.size(), presses.size());
    for (const Press& p : presses)
      EXPECT_LT(nearest_contact_mm(r, p), 2.0) << presses.size() << " presses; press at " << p.x_mm << ", " << p.y_mm;
  }
}

double chi2_per_measurement(const FitResult& r, const ContactFitter& fitter) {
  return r.rms_misfit_V * r.rms_misfit_V / (fitter.noise_V() * fitter.noise_V());
}

// A strong press (0.45 N/mm², near the paper's full scale) departs from the fit's held small disc
// by its shape: one disc leaves χ²/M of 4–10, far above the noise's 1, yet a second contact would
// be false. What one disc leaves is a small fraction of the frame, so it is the model's error.
TEST(ContactFitter, GivesAStrongSinglePressOneContact) {
  FitBench& s = bench();
  ContactFitter fitter(s.sensor, s.mesh, s.green, s.measurements);
  const double force_N = 0.45 * std::numbers::pi * 5 * 5;
  for (const Press& press : {Press{52, 53, 5, force_N}, Press{10, 8, 5, force_N}, Press{30, 25, 5, force_N}}) {
    const FitResult& r = fitter.fit(s.dV({press}), {Disc{press.x_mm + 2, press.y_mm - 2, 0, 0}});
    ASSERT_EQ(r.contacts.size(), 1u) << "a false contact at " << press.x_mm << ", " << press.y_mm;
    const double error = std::hypot(r.contacts[0].disc.x_mm - press.x_mm, r.contacts[0].disc.y_mm - press.y_mm);
    std::printf("strong press %.0f, %.0f: chi2/M %.2f, error %.3f mm\n", press.x_mm, press.y_mm,
                chi2_per_measurement(r, fitter), error);
    // Above the noise bound: the model-error test, not the noise, keeps it to one contact.
    EXPECT_GT(chi2_per_measurement(r, fitter), ContactFitter::noise_chi2_per_measurement);
    EXPECT_LT(error, 0.3);  // the single-press target
  }
}

struct FitBench30 {
  Sensor sensor = load_sensor(test::source_path("examples/sensors/square30.json"));
  FitModel model = build_fit_model(sensor);
  MeasurementSet measurements = make_measurement_set(sensor.electrode_count());
  Twin twin{sensor, [] {
              TwinOptions o;
              o.mesh_seed = 4;
              return o;
            }()};
  Vector dV(const std::vector<Press>& presses) {
    return frame_difference(measurements, twin.frame(presses), twin.frame({}));
  }
};

// Two presses 7 mm apart on the 30 mm sheet (its smallest separations, as emit eval scales them):
// one disc between them leaves χ²/M of only 4–8, under a fixed 3σ gate (9), but a larger share of
// the frame than a single press's model error: the second contact is found.
TEST(ContactFitter, FindsTwoClosePressesOnTheSmallSheet) {
  static FitBench30 s;
  ContactFitter fitter(s.sensor, s.model.mesh, s.model.green, s.measurements);
  FitOptions one_contact;
  one_contact.max_contacts = 1;
  ContactFitter single(s.sensor, s.model.mesh, s.model.green, s.measurements, one_contact);
  const std::vector<std::vector<Press>> pairs{{{19.45, 21.54, 2.5, 1.63}, {13.29, 17.57, 2.5, 2.12}},
                                              {{14.45, 18.94, 2.5, 2.79}, {9.30, 14.45, 2.5, 4.07}},
                                              {{11.15, 4.64, 2.5, 3.14}, {10.15, 11.74, 2.5, 1.31}}};
  for (const auto& presses : pairs) {
    const Vector dV = s.dV(presses);
    // Seeded between the presses, as the linear image's one merged region would.
    const Disc between{(presses[0].x_mm + presses[1].x_mm) / 2, (presses[0].y_mm + presses[1].y_mm) / 2, 0, 0};
    const double one_contact_chi2 = chi2_per_measurement(single.fit(dV, {between}), single);
    std::printf("pair: one contact leaves chi2/M %.2f\n", one_contact_chi2);
    EXPECT_LT(one_contact_chi2, 9);  // the case a fixed 3σ gate passed as one contact
    const FitResult& r = fitter.fit(dV, {between});
    ASSERT_EQ(r.contacts.size(), 2u);
    for (const Press& p : presses) {
      double nearest = 1e9;
      for (const FittedContact& c : r.contacts)
        nearest = std::min(nearest, std::hypot(c.disc.x_mm - p.x_mm, c.disc.y_mm - p.y_mm));
      std::printf("  press %.2f, %.2f: nearest contact %.3f mm\n", p.x_mm, p.y_mm, nearest);
      EXPECT_LT(nearest, 2.0);  // the target: within 2 mm
    }
  }
}

// Tracking: a finger sliding 0.5 mm a frame is refitted from where it was, to the same accuracy
// as a cold fit; a lifted finger and a new touch are not tracked (the cold fit takes over).
TEST(ContactFitter, TracksAMovingPressAndLetsGoWhenTheFramesChange) {
  FitBench& s = bench();
  ContactFitter fitter(s.sensor, s.mesh, s.green, s.measurements);
  std::vector<Disc> previous{Disc{20, 20, 0, 0}};
  FitResult r = fitter.fit(s.dV({{20, 20, 5, 8}}), previous);
  for (int i = 1; i <= 4; ++i) {
    const Press press{20 + 0.5 * i, 20 + 0.3 * i, 5, 8};
    previous = {r.contacts.at(0).disc};
    r = fitter.track(s.dV({press}), previous);
    ASSERT_TRUE(r.tracked) << "frame " << i;
    ASSERT_EQ(r.contacts.size(), 1u);
    // The cold fit's accuracy on this sheet: a tenth of a millimetre (and well under the 0.3 mm target).
    EXPECT_LT(std::hypot(r.contacts[0].disc.x_mm - press.x_mm, r.contacts[0].disc.y_mm - press.y_mm), 0.2)
        << "frame " << i;
  }
  // A second finger lands: one disc cannot explain the frame (beyond noise and model error).
  const std::vector<Press> two{{22, 21.2, 5, 8}, {45, 40, 5, 8}};
  EXPECT_FALSE(fitter.track(s.dV(two), previous).tracked);
  // The first lifts off, from two contacts at the presses: its disc fades below what the readings see.
  const std::vector<Disc> both{Disc{22, 21.2, previous[0].radius_mm, previous[0].conductance_S_per_mm2},
                               Disc{45, 40, previous[0].radius_mm, previous[0].conductance_S_per_mm2}};
  EXPECT_FALSE(fitter.track(s.dV({two[1]}), both).tracked);
  // Both lift and two land elsewhere: tracked discs would travel across the sheet, where a pair
  // can settle in a local minimum; the cold fit decides.
  EXPECT_FALSE(fitter.track(s.dV({{12, 45, 5, 8}, {40, 12, 5, 8}}), both).tracked);
}

}  // namespace
}  // namespace emit
