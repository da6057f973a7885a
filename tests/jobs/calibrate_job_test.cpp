// `emit calibrate`'s job (jobs/calibrate_job.hpp) without the CLI: the contact law from a file of
// resistance–pressure pairs, and the checks made before any work, each a one-line message naming
// the file. (Calibration from presses runs end to end in tests/cli/cli_test.cpp.)
#include "emit/jobs/calibrate_job.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

// Pairs of R = 2e5 · P^−1.2 printed to 10 significant digits: the fit recovers α and γ to about
// that precision (1e-9 relative on exact pairs, contact_law_calibration_test; 1e-6 here).
TEST(CalibrateJob, ContactLawFromPairsWithAHeader) {
  const std::string path = test::temp_folder("calibrate_job_law") + "/pairs.csv";
  {
    std::ofstream out(path);
    out << "pressure_N_per_mm2,resistance_ohm\n";
    char line[64];
    for (int k = 0; k <= 10; ++k) {
      const double p = 0.01 * std::pow(1.5, k);
      std::snprintf(line, sizeof line, "%.10g,%.10g\n", p, 2e5 * std::pow(p, -1.2));
      out << line;
    }
  }
  CalibrateJob job;
  job.contact_law_path = path;
  const CalibrateReport report = run_calibrate_job(job);
  EXPECT_EQ(report.pairs, 11u);  // k = 0 … 10
  ASSERT_TRUE(report.contact_law.has_value());
  EXPECT_FALSE(report.presses.has_value());
  EXPECT_NEAR(report.contact_law->alpha / 2e5, 1.0, 1e-6);
  EXPECT_NEAR(report.contact_law->gamma, -1.2, 1e-6);
}

template <class Error>
std::string error_of(const CalibrateJob& job) {
  try {
    run_calibrate_job(job);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(CalibrateJob, ChecksItsInputsFirst) {
  const std::string dir = test::temp_folder("calibrate_job_bad");
  EXPECT_EQ(error_of<InvalidInput>(CalibrateJob{}),
            "nothing to calibrate: give --frames (with --reference, --truth, --out) or --contact-law");
  CalibrateJob presses;
  presses.frames_path = dir + "/f.csv";
  presses.reference_path = dir + "/r.csv";
  EXPECT_EQ(error_of<InvalidInput>(presses), "pressure calibration needs --reference, --frames, --truth and --out");
  CalibrateJob law;
  law.contact_law_path = dir + "/none.csv";
  EXPECT_EQ(error_of<IoError>(law),
            dir + "/none.csv: cannot open resistance-pressure pairs file (No such file or directory)");
  std::ofstream(dir + "/bad.csv") << "0.1,5e5\n0.2;3e5\n";
  law.contact_law_path = dir + "/bad.csv";
  EXPECT_EQ(error_of<InvalidInput>(law),
            dir + "/bad.csv:2: expected pressure_N_per_mm2,resistance_ohm, got \"0.2;3e5\"");
}

// Frames and truth of different lengths, or no single press among them: said before the models
// are built, naming the truth file.
TEST(CalibrateJob, TruthMustMatchTheFrames) {
  const std::string dir = test::temp_folder("calibrate_job_truth");
  std::string row;
  for (int i = 0; i < 256; ++i) row += (i ? ",0.1" : "0.1");
  std::ofstream(dir + "/r.csv") << row << "\n";
  std::ofstream(dir + "/f.csv") << row << "\n" << row << "\n";
  std::ofstream(dir + "/one.csv") << "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2\n0,30,30,5,10,0.127\n";
  std::ofstream(dir + "/two.csv") << "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2\n"
                                  << "0,20,30,5,10,0.127\n0,40,30,5,10,0.127\n1,20,30,5,10,0.127\n1,40,30,5,10,0.127\n";
  CalibrateJob job;
  job.reference_path = dir + "/r.csv";
  job.frames_path = dir + "/f.csv";
  job.out_path = dir + "/c.json";
  job.truth_path = dir + "/one.csv";
  EXPECT_EQ(error_of<InvalidInput>(job), dir + "/one.csv: 1 frames of presses for 2 frames in " + dir + "/f.csv");
  job.truth_path = dir + "/two.csv";
  EXPECT_EQ(error_of<InvalidInput>(job), dir + "/two.csv: no single presses to calibrate on");
}

}  // namespace
}  // namespace emit
