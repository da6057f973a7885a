// `emit eval --figures-of-merit` and `emit eval --resolvability` as a user runs them (--quick).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace emit {
namespace {

using test::run_emit;

/// A method's row of the figures' table: AR's CV (%), PE's mean (mm) and RES's mean.
bool read_method_row(const std::string& out, const std::string& method, double& ar_cv, double& pe_mm, double& res) {
  const std::size_t at = out.find("\n  " + method + " ");
  if (at == std::string::npos) return false;
  // NOLINTNEXTLINE(cert-err34-c): emit's own output, the field count checks its shape
  return std::sscanf(out.c_str() + at + 3 + method.size(), " %*g %*s %lf %% %lf +/- %*g %lf", &ar_cv, &pe_mm, &res) ==
         3;
}

// --quick: presses r 3 mm, 8 N at the centre and 9 and 18 mm from it. The bounds: contact fitting
// places its picture within the centroid target for every outline (0.5 mm) and keeps its
// amplitude response (its force over the true one) within the force target's 10 % across places
// (measured: PE 0.01 mm, AR CV 2.5 %); the paper's image δφ is a potential, not a conductivity:
// above a quarter of its maximum it covers most of the sheet, RES > 0.5 (measured 0.98; a point
// target's would be its radius ratio, 0.09 here), and its integral, the current the press lets in,
// varies little with place (CV under 5 %; measured 0.6 %).
TEST(Cli, EvalFiguresOfMeritScoresEachMethod) {
  const std::string d = test::temp_folder("cli_eval_merit");
  const auto r = run_emit("eval --figures-of-merit --quick --methods paper,fit --out " + d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  double cv = -1, pe = 1e9, res = -1;
  ASSERT_TRUE(read_method_row(r.out, "fit", cv, pe, res)) << r.out;
  EXPECT_LT(std::abs(pe), 0.5) << r.out;
  EXPECT_LT(cv, 10) << r.out;
  ASSERT_TRUE(read_method_row(r.out, "paper-dphi", cv, pe, res)) << r.out;
  EXPECT_GT(res, 0.5) << r.out;
  EXPECT_LT(cv, 5) << r.out;
  EXPECT_NE(r.out.find("\n  paper-P "), std::string::npos) << r.out;
  for (const char* figure : {"ar", "pe", "res", "sd", "rng"})
    EXPECT_TRUE(std::filesystem::exists(d + "/60_x_60_mm_sheet_merit_" + figure + ".png")) << figure;
}

TEST(Cli, EvalResolvabilityTellsWhatAFrameCan) {
  const auto r = run_emit("eval --resolvability --quick");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // A round press of r 3 mm: one frame does not tell its size (σ_r > r; tests/eval/resolvability_test).
  const std::size_t row = r.out.find("\n    r   3.0 mm");
  ASSERT_NE(row, std::string::npos) << r.out;
  double sigma_r = -1;
  // NOLINTNEXTLINE(cert-err34-c): emit's own output, the field count checks its shape
  ASSERT_EQ(std::sscanf(r.out.c_str() + row, "\n    r   3.0 mm %lf", &sigma_r), 1) << r.out;
  EXPECT_GT(sigma_r, 3) << r.out;
  EXPECT_NE(r.out.find("resolved (>= 16)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hole r  6.0 mm"), std::string::npos) << r.out;
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
  EXPECT_EQ(r.exit_code, 2);  // refused as the command line is parsed, in the library's words
  EXPECT_EQ(r.err, "emit: --radius-mm: must be positive, got 0 (see 'emit eval --help')\n") << r.err;
}

}  // namespace
}  // namespace emit
