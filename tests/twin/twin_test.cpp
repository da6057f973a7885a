// The digital twin: contact quadrature, symmetry, monotonicity, the zero frame, the ADC, and
// agreement with the independent implementation's conformance frames.
#include "emit/twin/twin.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include "emit/core/errors.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/sensor/adc.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/adc_noise.hpp"
#include "emit/twin/press_contact.hpp"
#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

TwinOptions exact_twin() {
  TwinOptions options;
  options.adc = false;
  return options;
}

// ∫ g dA over a disc wholly inside the sheet is g·π r². The quadrature misplaces at most a band
// of width h/2^levels along the circle, so the relative error is below 2h / (r·2^levels).
TEST(PressContact, TotalConductanceMatchesTheDisc) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = generate_mesh(sensor, twin_mesh_options(sensor));
  const Press press{31.3, 28.9, 5.0, 10.0};
  const int levels = 6;
  const double exact = sensor.contact.conductance_S_per_mm2(press.pressure_N_per_mm2()) * std::numbers::pi * 25.0;
  const double total = press_contact_load(mesh, {press}, sensor.contact, levels).total_conductance_S();
  const double h = twin_mesh_options(sensor).element_size_mm;
  EXPECT_LE(std::abs(total - exact) / exact, 2 * h / (press.radius_mm * std::pow(2.0, levels)));
}

// Overlapping presses add their pressures, so the overlap conducts g(P1 + P2), not g(P1) + g(P2).
TEST(PressContact, OverlappingPressesAddPressure) {
  const Mesh mesh = test::strip_mesh(20, 20, 40, 40);
  ContactLaw law;
  const Press a{10, 10, 3, 2}, b{10, 10, 3, 3};
  const double together = press_contact_load(mesh, {a, b}, law).total_conductance_S();
  const double single = press_contact_load(mesh, {{10, 10, 3, 5}}, law).total_conductance_S();
  EXPECT_NEAR(together, single, 1e-12 * single);
}

// Mirror the mesh across x = 30: a press mirrored on the mirrored mesh must give the same frame
// with electrodes relabelled, to round-off. This checks the implementation's indexing and
// quadrature, free of discretisation error.
TEST(Twin, MirrorSymmetryToRoundOff) {
  const Sensor sensor = default_sensor();
  MeshOptions options;
  options.element_size_mm = 2.0;
  const Mesh mesh = generate_mesh(sensor, options);
  std::vector<int> mirror(16);
  for (int e = 0; e < 16; ++e)
    for (int f = 0; f < 16; ++f)
      if ((sensor.electrodes[f].center_mm -
           Vector2(60 - sensor.electrodes[e].center_mm.x(), sensor.electrodes[e].center_mm.y()))
              .norm() < 1e-9)
        mirror[e] = f;
  Mesh mirrored = mesh;
  mirrored.nodes_mm.col(0) = Vector::Constant(mesh.node_count(), 60.0) - mesh.nodes_mm.col(0);
  mirrored.triangles.col(1).swap(mirrored.triangles.col(2));
  for (int e = 0; e < 16; ++e) mirrored.electrode_nodes[mirror[e]] = mesh.electrode_nodes[e];
  const Press press{21.0, 37.0, 5.0, 10.0}, mirrored_press{60 - 21.0, 37.0, 5.0, 10.0};
  const Frame a = ForwardModel(mesh, 5000).solve_frame(press_contact_load(mesh, {press}, sensor.contact), 3.3);
  const Frame b =
      ForwardModel(mirrored, 5000).solve_frame(press_contact_load(mirrored, {mirrored_press}, sensor.contact), 3.3);
  double worst = 0;
  for (int l = 0; l < 16; ++l)
    for (int m = 0; m < 16; ++m) worst = std::max(worst, std::abs(a(l, m) - b(mirror[l], mirror[m])));
  EXPECT_LE(worst, test::solve_roundoff * 3.3);
}

// On one (unsymmetric) twin mesh the mirrored press differs only by discretisation error, which
// the conformance criterion bounds by 1 % of the largest potential for each of the two frames.
TEST(Twin, MirrorSymmetryWithinDiscretisationError) {
  const Sensor sensor = default_sensor();
  Twin twin(sensor, exact_twin());
  const Frame a = twin.exact_frame({{21, 37, 5, 10}});
  const Frame b = twin.exact_frame({{39, 37, 5, 10}});
  const int mirror[16] = {3, 2, 1, 0, 15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4};
  double worst = 0;
  for (int l = 0; l < 16; ++l)
    for (int m = 0; m < 16; ++m) worst = std::max(worst, std::abs(a(l, m) - b(mirror[l], mirror[m])));
  EXPECT_LE(worst, 2 * test::conformance_fraction_of_max * a.maxCoeff());
}

TEST(Twin, ZeroFrameWhenNothingPresses) {
  Twin twin(default_sensor(), exact_twin());
  EXPECT_EQ(twin.exact_frame({}).cwiseAbs().maxCoeff(), 0.0);
  // below the separator's minimum pressure (0.002 N/mm² over 78.5 mm² is 0.157 N)
  EXPECT_EQ(twin.exact_frame({{30, 30, 5, 0.1}}).cwiseAbs().maxCoeff(), 0.0);
}

// More force, lower contact resistance, every electrode pulled closer to the drive: by the
// maximum principle ∂u/∂g ≥ 0, strictly where the sheet is connected to the contact.
TEST(Twin, ResponseGrowsWithForce) {
  Twin twin(default_sensor(), exact_twin());
  Frame previous = twin.exact_frame({{25, 33, 5, 1}});
  for (double force : {2.0, 4.0, 8.0, 16.0}) {
    const Frame frame = twin.exact_frame({{25, 33, 5, force}});
    for (int l = 0; l < 16; ++l)
      for (int m = 0; m < 16; ++m)
        if (l != m) {
          EXPECT_GT(frame(l, m), previous(l, m)) << "force " << force << " N, ground " << l << ", sense " << m;
        }
    previous = frame;
  }
}

TEST(Twin, PressOffTheSheetIsRejected) {
  Twin twin(default_sensor(), exact_twin());
  EXPECT_THROW(twin.exact_frame({{70, 30, 5, 10}}), InvalidInput);
  EXPECT_THROW(twin.exact_frame({{30, 30, -1, 10}}), InvalidInput);
  EXPECT_THROW(twin.exact_frame({{30, 30, 5, std::nan("")}}), InvalidInput);
}

struct ConformanceCase {
  const char* name;
};

class Conformance : public ::testing::TestWithParam<const char*> {};

// The independent implementation's exact frames (README: a correct twin on a reasonable mesh
// agrees to about 1 % of the largest potential).
TEST_P(Conformance, AgreesWithTheIndependentImplementation) {
  const std::string base = test::source_path(std::string("tests/data/conformance/") + GetParam());
  const Sensor sensor = load_sensor(base + "_sensor.json");
  const auto reference = read_frames_csv(base + "_frames.csv", 16);
  const PressSequence presses = read_presses_csv(base + "_presses.csv");
  ASSERT_EQ(reference.size(), presses.size());
  Twin twin(sensor, exact_twin());
  for (std::size_t f = 0; f < presses.size(); ++f) {
    const Frame frame = twin.exact_frame(presses[f]);
    const double largest = reference[f].cwiseAbs().maxCoeff();
    const double error = (frame - reference[f]).cwiseAbs().maxCoeff();
    std::printf("%s frame %zu: worst difference %.2e V = %.3f %% of the largest potential %.4f V\n", GetParam(), f,
                error, 100 * error / largest, largest);
    EXPECT_LE(error, test::conformance_fraction_of_max * largest)
        << GetParam() << " frame " << f << ": worst difference " << error << " V of " << largest << " V";
  }
}

INSTANTIATE_TEST_SUITE_P(Frames, Conformance, ::testing::Values("square60", "circle40", "dome25"));

// The dome's presses are given with the height of their centre: the surface's point above (x, y),
// which is where the twin centres a press on a curved sheet (sensor/surface.hpp).
TEST(CurvedTwin, ConformancePressesLieOnTheSurface) {
  const std::string base = test::source_path("tests/data/conformance/dome25");
  const Sensor sensor = load_sensor(base + "_sensor.json");
  for (const auto& frame : read_presses_csv(base + "_presses.csv"))
    for (const Press& p : frame)
      EXPECT_NEAR(p.z_mm, surface_point_mm(sensor.shape, Vector2(p.x_mm, p.y_mm)).z(), 1e-5);  // the file's 6 decimals
}

// A press at the apex of the dome looks the same from every electrode: the frame is invariant
// under shifting both electrode numbers by one, to the discretisation error (the conformance 1 %).
TEST(CurvedTwin, ApexPressIsSymmetricUnderTheRimsRotation) {
  const Sensor sensor = load_sensor(test::source_path("tests/data/conformance/dome25_sensor.json"));
  Twin twin(sensor, exact_twin());
  const Frame f = twin.exact_frame({{0, 0, 4, 10}});
  double worst = 0;
  for (int l = 0; l < 16; ++l)
    for (int m = 0; m < 16; ++m) worst = std::max(worst, std::abs(f((l + 1) % 16, (m + 1) % 16) - f(l, m)));
  EXPECT_LE(worst, test::conformance_fraction_of_max * f.maxCoeff());
  EXPECT_GT(f.maxCoeff(), 0.1);  // the press is felt
}

// A cap of a huge sphere (R = 20 m, the rim 20 mm: 10 µm high) is the flat disc: its frames are
// the circle sensor's within the discretisation error (the conformance 1 %; the two twin meshes
// differ, as the cap's disc is meshed at h / 1.0000001). Measured: 0.08 %.
TEST(CurvedTwin, ACapOfAHugeSphereIsTheFlatDisc) {
  const nlohmann::json electrodes = {{"count", 16}, {"width_mm", 3}};
  const Sensor flat = parse_sensor(
      {{"shape", {{"type", "circle"}, {"radius_mm", 20}, {"center_mm", {0, 0}}}}, {"electrodes", electrodes}});
  const Sensor cap =
      parse_sensor({{"shape", {{"type", "spherical_cap"}, {"sphere_radius_mm", 2e4}, {"base_radius_mm", 20}}},
                    {"electrodes", electrodes}});
  Twin flat_twin(flat, exact_twin()), cap_twin(cap, exact_twin());
  for (const std::vector<Press>& presses :
       std::vector<std::vector<Press>>{{{3, 4, 4, 10}}, {{-8, 5, 3, 6}, {7, -6, 4, 12}}}) {
    const Frame a = flat_twin.exact_frame(presses), b = cap_twin.exact_frame(presses);
    EXPECT_LE((a - b).cwiseAbs().maxCoeff(), test::conformance_fraction_of_max * a.maxCoeff());
  }
}

TEST(Adc, QuantisesClipsAndAddsNoise) {
  AdcSpec adc{12, 3.3, 0.0};
  const double step = adc_step_V(adc);
  EXPECT_NEAR(step, 3.3 / 4095, 1e-15);
  Frame frame(2, 2);
  frame << 0.1234, -0.2, 4.0, 1.0;
  std::mt19937_64 rng(1);
  apply_adc(adc, frame, rng);
  EXPECT_NEAR(frame(0, 0), std::round(0.1234 / step) * step, 1e-15);
  EXPECT_EQ(frame(0, 1), 0.0);           // clipped at ground
  EXPECT_NEAR(frame(1, 0), 3.3, 1e-12);  // clipped at the reference
  // Noise: the sample standard deviation of many readings of a constant is noise_V, within
  // 5 standard errors (σ/√(2n)) plus the quantisation's step/√12.
  adc.noise_V = 0.001;
  Frame many = Frame::Constant(100, 100, 1.0);
  apply_adc(adc, many, rng);
  const double mean = many.mean();
  const double sd = std::sqrt((many.array() - mean).square().sum() / static_cast<double>(many.size() - 1));
  const double expected = std::sqrt(0.001 * 0.001 + step * step / 12);
  EXPECT_NEAR(sd, expected, 5 * expected / std::sqrt(2.0 * many.size()));
}

}  // namespace
}  // namespace emit

namespace emit {
namespace {

// Refining the twin's mesh moves it towards the independent, finer reference: halving the
// element size must shrink the worst difference (O(h²) would quarter it; the reference's own
// discretisation error limits how far).
TEST(Conformance, TwinConvergesTowardsTheReferenceUnderRefinement) {
  const std::string base = test::source_path("tests/data/conformance/square60");
  const Sensor sensor = load_sensor(base + "_sensor.json");
  const auto reference = read_frames_csv(base + "_frames.csv", 16);
  const PressSequence presses = read_presses_csv(base + "_presses.csv");
  std::vector<double> errors;
  for (double h : {2.4, 1.2, 0.6}) {
    TwinOptions options = exact_twin();
    options.mesh = twin_mesh_options(sensor);
    options.mesh->element_size_mm = h;
    Twin twin(sensor, options);
    double worst = 0;
    for (std::size_t f = 0; f < presses.size(); ++f)
      worst = std::max(worst, (twin.exact_frame(presses[f]) - reference[f]).cwiseAbs().maxCoeff() /
                                  reference[f].cwiseAbs().maxCoeff());
    std::printf("twin element size %.1f mm: worst difference %.3f %% of the largest potential\n", h, 100 * worst);
    errors.push_back(worst);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], 0.7 * errors[i - 1]);
}

}  // namespace
}  // namespace emit

namespace emit {
namespace {

// A sheet read from a mesh file has no analytic border; the mesh itself says what is off it.
TEST(Twin, PressOffAMeshFileSheetIsRejected) {
  const std::string dir = test::temp_folder("twin_mesh_file");
  MeshOptions options;
  options.element_size_mm = 3;
  write_msh(generate_mesh(default_sensor(), options), dir + "/sheet.msh");
  const Sensor sensor =
      parse_sensor(nlohmann::json::parse(R"({"shape": {"type": "mesh", "file": "sheet.msh"}})"), "sensor", dir);
  TwinOptions twin_options = exact_twin();
  twin_options.mesh = options;
  Twin twin(sensor, twin_options);
  EXPECT_EQ(twin.mesh().electrode_count(), 16);
  EXPECT_GT(twin.exact_frame({{30, 30, 5, 10}}).maxCoeff(), 0.1);
  EXPECT_THROW(twin.exact_frame({{61, 30, 5, 10}}), InvalidInput);
}

}  // namespace
}  // namespace emit
