// Locating a press with a learned response (frame/press_locator.hpp): on frames made exactly by a
// known response the search finds the true centre to its final step, with any press strength, and
// allocates nothing per frame.
#include "emit/frame/press_locator.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// A degree-3 response of 24 readings over the disc of 30 mm about its centre (a 64-gon), Λ = I.
PressResponse known_response() {
  PressResponse r;
  r.degree = 3;
  r.center_mm = {5, -3};
  r.scale_mm = 30;
  for (int k = 0; k < 64; ++k)
    r.region_mm.emplace_back(r.center_mm +
                             30 * Vector2(std::cos(k * 6.283185307 / 64), std::sin(k * 6.283185307 / 64)));
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  r.coefficients = Matrix(response_basis_size(3), 24);
  for (Index i = 0; i < r.coefficients.size(); ++i) r.coefficients(i) = normal(random);
  r.precision = Matrix::Identity(24, 24);
  return r;
}

TEST(PressLocator, FindsTheCentreThatMadeTheFrame) {
  const PressResponse response = known_response();
  PressLocator locator(response, 30);  // 2 mm steps
  std::mt19937 random(3);
  std::uniform_real_distribution<double> angle(0, 6.283), radius(0, 29);  // inside the 64-gon
  Vector basis(response_basis_size(3));
  const Vector reference = Vector::Constant(24, 1000);
  for (int k = 0; k < 20; ++k) {
    const double a = angle(random), r = radius(random);
    const Vector2 p = response.center_mm + r * Vector2(std::cos(a), std::sin(a));
    response.basis_at(p, basis);
    const Vector change = response.coefficients.transpose() * basis;
    // A press of any strength: the change's size does not move the centre.
    const double strength = 0.01 * (1 + k % 3);
    const Vector frame = (reference.array() * (strength * change / change.norm()).array().exp()).matrix();
    const LocatedPress located = locator.locate(frame, reference);
    ASSERT_TRUE(located.found);
    // The refinement's last step is 2 mm / 2⁵ = 0.0625 mm: the centre is within half a diagonal of it.
    EXPECT_LT((located.position_mm - p).norm(), 0.0625 * 0.71) << "press " << k;
    // An exact frame is all explained but for the last step's position error: 1 − O((δp ‖∂d/∂p‖)²).
    EXPECT_GT(located.explained, 1 - 1e-5);
    EXPECT_NEAR(located.relative_change_rms, strength / std::sqrt(24.0), 1e-12);
  }
}

TEST(PressLocator, AllocatesNothingPerFrameAndRefusesWhatItCannotRead) {
  PressLocator locator(known_response(), 30);
  const Vector reference = Vector::Constant(24, 1000);
  Vector frame = reference;
  frame(3) *= 1.02;
  frame(9) *= 0.99;
  locator.locate(frame, reference);  // warm
  {
    test::AllocationCounter counter;
    for (int k = 0; k < 10; ++k) locator.locate(frame, reference);
    EXPECT_EQ(counter.count(), 0);
  }
  EXPECT_FALSE(locator.locate(reference, reference).found);  // no change
  frame(0) = -1;
  EXPECT_FALSE(locator.locate(frame, reference).found);  // a value that is not positive
  EXPECT_EQ(test::error_of([&] { locator.locate(Vector::Ones(5), reference); }),
            "press locator: a frame of 5 values and a reference of 24 for a response of 24 readings");
  PressResponse none = known_response();
  none.region_mm.clear();
  EXPECT_EQ(test::error_of([&] { PressLocator{none}; }), "press locator: the press response has no region to search");
}

}  // namespace
}  // namespace emit
