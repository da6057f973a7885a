// Emit's force law for the linear methods (model/force_law.hpp): F = (b1/I + b2)^b3 at chosen
// points, the base held positive, the σs from the indenter's unknown size, and its checks.
#include "emit/model/force_law.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

// b1 = 2, b2 = −1, b3 = −2: I = 1 gives (2 − 1)^−2 = 1; I = 0.5 gives 3^−2 = 1/9.
TEST(ForceLaw, AtChosenPoints) {
  ImageForceLaw law;
  law.b1_V_mm2 = 2, law.b2 = -1, law.b3 = -2;
  EXPECT_DOUBLE_EQ(law.force_N(1.0), 1.0);
  EXPECT_DOUBLE_EQ(law.force_N(0.5), 1.0 / 9);
  EXPECT_EQ(law.force_N(0.0), 0.0);  // no image, no force
  EXPECT_EQ(law.force_N(-1.0), 0.0);
  // An integral beyond the law's range (b1/I + b2 ≤ 0, here I ≥ 2) reads as the largest force it
  // can express, (1e-12)^−2, not NaN.
  EXPECT_DOUBLE_EQ(law.force_N(4.0), 1e24);
}

// The area a contact is reported with is the calibration indenter's, π r².
TEST(ForceLaw, IndenterArea) {
  ImageForceLaw law;
  law.indenter_radius_mm = 5;
  EXPECT_DOUBLE_EQ(law.indenter_area_mm2(), 25 * std::numbers::pi);
}

// At γ = −1.2 (b3 = 1/γ) the force moves by (1 + γ)/γ = 1/6 of ln A, the pressure by 1/γ = −5/6;
// over ln A's σ of 0.93 (radii 2–10 mm) that is 15.5 % and 77.5 %, combined with the calibration's
// own scatter as independent errors.
TEST(ForceLaw, RelativeStdsFromTheIndentersUnknownSize) {
  ImageForceLaw law;
  law.b3 = -1 / 1.2;
  law.log_std = 0;
  EXPECT_NEAR(law.force_relative_std(), 0.93 / 6, 1e-12);
  EXPECT_NEAR(law.pressure_relative_std(), 0.93 * 5 / 6, 1e-12);
  law.log_std = 0.05;
  EXPECT_NEAR(law.force_relative_std(), std::hypot(0.05, 0.93 / 6), 1e-12);
}

TEST(ForceLaw, ValidateNamesTheField) {
  ImageForceLaw law;
  EXPECT_NO_THROW(law.validate());
  law.b3 = 0.5;
  EXPECT_EQ(test::error_of([&] { law.validate(); }),
            "ImageForceLaw::b3 must be negative (the force grows with the image), got 0.500000");
  law = {};
  law.indenter_radius_mm = 0;
  EXPECT_NE(test::error_of([&] { law.validate(); }).find("ImageForceLaw::indenter_radius_mm"), std::string::npos);
  law = {};
  law.b1_V_mm2 = -1;
  EXPECT_NE(test::error_of([&] { law.validate(); }).find("ImageForceLaw::b1_V_mm2"), std::string::npos);
  law = {};
  law.b2 = std::nan("");
  EXPECT_NE(test::error_of([&] { law.validate(); }).find("ImageForceLaw::b2"), std::string::npos);
}

}  // namespace
}  // namespace emit
