// `emit eval --figures-of-merit` and `emit eval --resolvability` as a user runs them (--quick).
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace emit {
namespace {

using test::run_emit;

/// A method's row of the figures' table: AR CV (%) and PE's mean (mm).
bool read_method_row(const std::string& out, const std::string& method, double& ar_cv, double& pe_mm) {
  const std::size_t at = out.find("\n  " + method + " ");
  if (at == std::string::npos) return false;
  // NOLINTNEXTLINE(cert-err34-c): emit's own output, the field count checks its shape
  return std::sscanf(out.c_str() + at + 3 + method.size(), " %*g %*s %lf %% %lf", &ar_cv, &pe_mm) == 2;
}

// BOUNDS: filled in from the measured run below.
TEST(Cli, EvalFiguresOfMeritScoresEachMethod) {
  const std::string d = test::temp_folder("cli_eval_merit");
  const auto r = run_emit("eval --figures-of-merit --quick --methods paper,fit --out " + d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::printf("%s", r.out.c_str());
  double paper_cv = -1, paper_pe = 1e9, fit_cv = -1, fit_pe = 1e9;
  ASSERT_TRUE(read_method_row(r.out, "paper", paper_cv, paper_pe)) << r.out;
  ASSERT_TRUE(read_method_row(r.out, "fit", fit_cv, fit_pe)) << r.out;
  for (const char* figure : {"ar", "pe", "res", "sd", "rng"})
    EXPECT_TRUE(std::filesystem::exists(d + "/60_x_60_mm_sheet_merit_" + figure + ".png")) << figure;
}

TEST(Cli, EvalResolvabilityTellsWhatAFrameCan) {
  const auto r = run_emit("eval --resolvability --quick");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::printf("%s", r.out.c_str());
  EXPECT_NE(r.out.find("resolved"), std::string::npos) << r.out;
}

// docs/bad-input.md: a curved sheet, a press of no size: one line naming what, exit 1, before any
// work (no fit model built, no folder made).
TEST(Cli, EvalMeritRefusesBadInput) {
  const std::string d = test::temp_folder("cli_eval_merit_bad");
  auto r = run_emit("eval --figures-of-merit --sheet dome --out " + d + "/plots");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--figures-of-merit on the dome, R 25 mm, a 20 mm: a flat sheet only"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(d + "/plots"));
  r = run_emit("eval --resolvability --sheet sleeve");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--resolvability on the sleeve, R 15 mm, L 60 mm: a flat sheet only"), std::string::npos)
      << r.err;
  r = run_emit("eval --figures-of-merit --radius-mm 0 --out " + d + "/plots");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("FiguresOfMeritOptions::radius_mm must be"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace emit
