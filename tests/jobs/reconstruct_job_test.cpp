// `emit reconstruct`'s job (jobs/reconstruct_job.hpp) in-process on a coarse 30 mm sheet: a linear
// method's batch split across threads writes the very same contacts as one thread (its frames
// are independent), and as the frame-by-frame path that draws the pressure maps.
#include "emit/jobs/reconstruct_job.hpp"
#include "emit/render/pressure_map.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/render/image.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

TEST(ReconstructJob, ThreadsAndImagesChangeNoContact) {
  const std::string dir = test::temp_folder("reconstruct_job");
  std::ifstream in(test::source_path("examples/sensors/square30.json"));
  nlohmann::json sensor_json = nlohmann::json::parse(in);
  sensor_json["mesh"]["element_size_mm"] = 2.0;  // ~500 triangles: quick
  std::ofstream(dir + "/sensor.json") << sensor_json.dump();
  Twin twin(parse_sensor(sensor_json));
  write_frames_csv(dir + "/ref.csv", {twin.frame({}), twin.frame({})});
  write_frames_csv(dir + "/frames.csv", {twin.frame({{10, 10, 2.5, 5}}), twin.frame({}), twin.frame({{20, 15, 2.5, 8}}),
                                         twin.frame({{8, 22, 2.5, 3}, {22, 8, 2.5, 3}})});

  ReconstructJob job;
  job.sensor_path = dir + "/sensor.json";
  job.reference_path = dir + "/ref.csv";
  job.frames_path = dir + "/frames.csv";
  job.method = Method::paper;
  job.contacts_path = dir + "/one.jsonl";
  const ReconstructReport one = run_reconstruct_job(job);
  EXPECT_EQ(one.frames, 4u);
  EXPECT_EQ(one.measurements, 16 * 15);
  EXPECT_FALSE(one.calibrated);
  EXPECT_FALSE(one.operator_from_cache);  // no cache folder given
  EXPECT_GT(one.lambda2, 0.0);            // the rule's choice, reported
  EXPECT_TRUE(one.dead_electrodes.empty());

  job.threads = 2;
  job.contacts_path = dir + "/two.jsonl";
  run_reconstruct_job(job);
  job.threads = 1;
  job.images_dir = dir + "/maps";
  job.contacts_path = dir + "/imaged.jsonl";
  run_reconstruct_job(job);

  const std::string contacts = test::read_text(dir + "/one.jsonl");
  EXPECT_EQ(test::read_text(dir + "/two.jsonl"), contacts);
  EXPECT_EQ(test::read_text(dir + "/imaged.jsonl"), contacts);
  long frame = -1;
  EXPECT_FALSE(parse_contacts_line(contacts.substr(0, contacts.find('\n')), &frame).empty());  // the 5 N press
  EXPECT_EQ(frame, 0);
  for (int f = 0; f < 4; ++f)
    EXPECT_GT(read_png(dir + "/maps/" + frame_image_name(static_cast<std::size_t>(f))).width(), 100) << f;
}

}  // namespace
}  // namespace emit
