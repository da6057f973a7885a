// The pipeline (pipeline/pipeline.hpp) on a coarse 30 mm sheet: each kind of method gets its kind
// of calibration, the other kind is refused naming the fix, options reach the models, and a
// linear pipeline's reconstructor finds a press of the twin.
#include "emit/pipeline/pipeline.hpp"

#include <cmath>
#include <functional>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

Sensor coarse_sensor() {
  Sensor sensor = load_sensor(test::source_path("examples/sensors/square30.json"));
  sensor.mesh.element_size_mm = 2.0;  // ~500 triangles: quick
  return sensor;
}

TEST(Pipeline, ACalibrationOfTheOtherKindIsRefusedNamingTheFix) {
  EXPECT_EQ(test::error_of([] { check_calibration_for_method(FitCalibration{}, Method::paper, "c.json"); }),
            "c.json: a calibration for contact fitting; run 'emit calibrate --method paper'");
  EXPECT_EQ(test::error_of([] { check_calibration_for_method(LinearCalibration{}, Method::fit, "c.json"); }),
            "c.json: a calibration for the linear methods; run 'emit calibrate --method fit'");
  EXPECT_EQ(test::error_of([] { check_calibration_for_method(LinearCalibration{}, Method::laplacian, "c.json"); }),
            "no error");
  // The pipeline refuses before building anything.
  EXPECT_EQ(test::error_of([] {
              Pipeline p(coarse_sensor(), {Method::noser, 0, "", {}}, FitCalibration{}, {}, "f.json");
            }),
            "f.json: a calibration for contact fitting; run 'emit calibrate --method noser'");
}

// A mesh-file sensor's electrodes are its file's: here the strip's two.
TEST(Pipeline, ElectrodeCountOfAMeshFileSensorIsTheFiles) {
  const std::string path = test::temp_folder("pipeline_msh") + "/strip.msh";
  write_msh(test::strip_mesh(10, 4, 5, 2), path);
  Sensor sensor;
  sensor.shape.kind = ShapeKind::mesh_file;
  sensor.shape.mesh_path = path;
  EXPECT_EQ(electrode_count_of(sensor), 2);
  EXPECT_EQ(electrode_count_of(coarse_sensor()), 16);
}

// The paper method, calibrated, with λ² and a dead electrode given: the options reach the model,
// the stages are told, and its reconstructor is the one built by hand from the same model and
// calibration: the same contacts, bit for bit, for a press of the twin. (The method's accuracy is
// tests/frame/reconstructor_test.cpp's.)
TEST(Pipeline, LinearMethodTakesItsOptionsAndCalibration) {
  const Sensor sensor = coarse_sensor();
  const LinearCalibration calibration{3.0, -0.5, -0.75};
  int stages = 0;
  Pipeline pipeline(sensor, {Method::paper, 2e4, "", {3}}, calibration, [&](const std::string&) { ++stages; });
  EXPECT_GT(stages, 0);
  EXPECT_EQ(pipeline.method(), Method::paper);
  EXPECT_TRUE(pipeline.calibrated());
  EXPECT_EQ(pipeline.linear_calibration().a2, -0.5);
  EXPECT_EQ(pipeline.operator_options().lambda2, 2e4);
  EXPECT_EQ(pipeline.model().measurements.size(), 15 * 14);  // electrode 3 left out, as ground and as sense
  EXPECT_EQ(pipeline.fit_mesh(), nullptr);

  OperatorOptions options = operator_options(Method::paper);
  options.lambda2 = 2e4;
  const ReconstructionModel model = build_reconstruction_model(sensor, options, "", {3});
  Reconstructor by_hand(model, calibration);
  Reconstructor piped = pipeline.reconstructor();
  Twin twin(sensor);
  const Frame reference = twin.frame({}), pressed = twin.frame({{12, 18, 2.5, 10}});
  by_hand.set_reference({reference, 1});
  piped.set_reference({reference, 1});
  const std::vector<Contact> expected = by_hand.process(pressed);
  const std::vector<Contact>& contacts = piped.process(pressed);
  ASSERT_FALSE(expected.empty());
  ASSERT_EQ(contacts.size(), expected.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    EXPECT_EQ(contacts[k].x_mm, expected[k].x_mm);
    EXPECT_EQ(contacts[k].force_N, expected[k].force_N);
  }
}

// Uncalibrated contact fitting: the seeds' operator is the paper method's at its λ², the sensor's
// own contact law, and a fit mesh of its own.
TEST(Pipeline, FittingBuildsItsOwnMesh) {
  const Sensor sensor = coarse_sensor();
  Pipeline pipeline(sensor, {Method::fit, 0, "", {}});
  EXPECT_FALSE(pipeline.calibrated());
  EXPECT_GT(pipeline.operator_options().lambda2, 0.0);  // the paper method's rule chose it
  EXPECT_EQ(pipeline.model().op.lambda2(), pipeline.operator_options().lambda2);
  ASSERT_NE(pipeline.fit_mesh(), nullptr);
  EXPECT_EQ(pipeline.fit_mesh()->electrode_count(), 16);
  EXPECT_NE(pipeline.fit_mesh()->node_count(), pipeline.model().mesh.node_count());  // graded into the electrodes' ends
  EXPECT_EQ(pipeline.linear_calibration().a1, pipeline.model().uncalibrated.a1);
}

/// Every number of every contact of every frame, for comparing bit for bit.
std::vector<double> numbers_of(const std::vector<std::vector<Contact>>& frames) {
  std::vector<double> numbers;
  for (const auto& contacts : frames)
    for (const Contact& c : contacts)
      numbers.insert(numbers.end(), {c.x_mm, c.y_mm, c.area_mm2, c.pressure_N_per_mm2, c.force_N, c.x_std_mm,
                                     c.y_std_mm, c.force_std_N});
  return numbers;
}

// Two reconstructors of one fitting pipeline, each its own fitter on the pipeline's one
// precompute, fit two streams at once on two threads, with no lock: each stream's contacts are
// bit for bit those of the same stream fitted alone on one thread. And the pipeline's batch fits
// independent frames the same on one thread or three.
TEST(Pipeline, ReconstructorsOfOneFittingPipelineFitOnThreadsAtOnce) {
  const Sensor sensor = load_sensor(test::source_path("examples/sensors/square30.json"));
  const Pipeline pipeline(sensor, {Method::fit, 0, "", {}});
  Twin twin(sensor);
  const Reference reference{twin.frame({}), 1};
  std::vector<std::vector<Frame>> streams(2);
  for (int k = 0; k < 3; ++k) {  // a press moving right, another moving up, with a lift-off
    streams[0].push_back(twin.frame({{10.0 + k, 15, 4, 8}}));
    streams[1].push_back(k == 1 ? twin.frame({}) : twin.frame({{18, 12.0 + k, 4, 8}}));
  }
  const auto run = [&](const std::vector<Frame>& frames, std::vector<std::vector<Contact>>& out) {
    Reconstructor reconstructor = pipeline.reconstructor();
    reconstructor.set_reference(reference);
    for (const Frame& frame : frames) out.push_back(reconstructor.process(frame));
  };
  std::vector<std::vector<std::vector<Contact>>> alone(2), together(2);
  run(streams[0], alone[0]);
  run(streams[1], alone[1]);
  std::thread other([&] { run(streams[1], together[1]); });
  run(streams[0], together[0]);
  other.join();
  for (int s = 0; s < 2; ++s) {
    ASSERT_EQ(together[s].size(), alone[s].size());
    EXPECT_FALSE(numbers_of(alone[s]).empty()) << "stream " << s << " found no contact";
    EXPECT_EQ(numbers_of(together[s]), numbers_of(alone[s])) << "stream " << s;
  }
  std::vector<Frame> frames = streams[0];
  frames.insert(frames.end(), streams[1].begin(), streams[1].end());
  EXPECT_EQ(numbers_of(pipeline.reconstruct_batch({}, reference, frames, 3)),
            numbers_of(pipeline.reconstruct_batch({}, reference, frames, 1)));
}

}  // namespace
}  // namespace emit
