// Scoring contacts against presses (eval/contact_scoring.hpp) on hand-made frames, with the
// figures worked out by hand.
#include "emit/eval/contact_scoring.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

Contact contact_at(double x_mm, double y_mm, double force_N = 0, double force_std_N = 0,
                   double pressure_N_per_mm2 = 0) {
  Contact c;
  c.x_mm = x_mm, c.y_mm = y_mm, c.force_N = force_N, c.force_std_N = force_std_N;
  c.pressure_N_per_mm2 = pressure_N_per_mm2;
  return c;
}

Press press_at(double x_mm, double y_mm, double force_N = 10) { return Press{x_mm, y_mm, 5, force_N}; }

// Four frames: a contact 3-4-5 mm off reading 12 N for 10 (+20 %, σ 1.5: outside 1σ, inside 2σ);
// an exact contact reading 19 N for 20 (−5 %, σ 2: inside 1σ) with a false contact beside it; a
// press with no contact; two presses (not a single press: skipped).
TEST(ContactScoring, SinglePressesByHand) {
  const ContactSequence contacts{
      {contact_at(13, 14, 12, 1.5, 0.15)},
      {contact_at(30, 30, 19, 2, 0.25), contact_at(50, 50, 1, 1, 0.01)},
      {},
      {contact_at(0, 0, 99, 1, 1)},
  };
  const PressSequence presses{{press_at(10, 10, 10)},
                              {press_at(30, 30, 20)},
                              {press_at(40, 40)},
                              {press_at(0, 0), press_at(20, 20)}};
  const SinglePressScore s = score_single_presses(contacts, presses);
  EXPECT_EQ(s.frames, 3);
  EXPECT_EQ(s.position_mm.count, 2);
  EXPECT_EQ(s.position_mm.missed, 1);
  EXPECT_DOUBLE_EQ(s.position_mm.mean, 2.5);      // (5 + 0) / 2
  EXPECT_DOUBLE_EQ(s.force_error, 0.125);         // (0.20 + 0.05) / 2
  EXPECT_DOUBLE_EQ(s.force_bias, 0.075);          // (0.20 − 0.05) / 2
  const double area_mm2 = std::numbers::pi * 25;  // the 5 mm presses' F/(π r²)
  EXPECT_DOUBLE_EQ(s.pressure_error_N_per_mm2, (std::abs(0.15 - 10 / area_mm2) + std::abs(0.25 - 20 / area_mm2)) / 2);
  EXPECT_DOUBLE_EQ(s.within_1_sigma, 0.5);
  EXPECT_DOUBLE_EQ(s.within_2_sigma, 1.0);
  EXPECT_EQ(s.extra_contacts, 1);
}

TEST(ContactScoring, NoFramesScoreNothing) {
  const SinglePressScore s = score_single_presses({}, {});
  EXPECT_EQ(s.frames, 0);
  EXPECT_EQ(s.position_mm.count, 0);
  EXPECT_EQ(s.force_error, 0.0);
  EXPECT_EQ(s.within_1_sigma, 0.0);
}

// Each press needs a contact of its own: one contact between two presses finds only one of them,
// though it is within reach of both.
TEST(ContactScoring, EachContactMatchesOnePress) {
  const std::vector<Press> two{press_at(0, 0), press_at(10, 0)};
  EXPECT_TRUE(every_press_matched({contact_at(1, 0), contact_at(9, 0)}, two, 2));
  EXPECT_TRUE(every_press_matched({contact_at(9, 0), contact_at(1, 0)}, two, 2));  // in any order
  EXPECT_FALSE(every_press_matched({contact_at(5, 0)}, two, 6));
  EXPECT_FALSE(every_press_matched({contact_at(1, 0), contact_at(12.5, 0)}, two, 2));  // 2.5 mm off
  EXPECT_FALSE(every_press_matched({}, two, 2));
  EXPECT_TRUE(every_press_matched({contact_at(3, 4)}, {}, 2));  // no press: nothing to find
}

// Exactly match_mm away is a match (3-4-5: exactly 5 mm).
TEST(ContactScoring, TheDistanceItselfMatches) {
  EXPECT_TRUE(every_press_matched({contact_at(3, 4)}, {press_at(0, 0)}, 5));
  EXPECT_FALSE(every_press_matched({contact_at(3, 4)}, {press_at(0, 0)}, 4.999));
}

// Greedy, in the presses' order, as tests/tools/score_contacts.py: the first press takes its
// nearest contact (0.9 mm) and leaves the second press only one 3.4 mm away, though the other
// assignment (1.5 mm and 1.0 mm) would match both within 2 mm.
TEST(ContactScoring, MatchingIsGreedyInThePressesOrder) {
  const std::vector<Contact> contacts{contact_at(0.9, 0), contact_at(-1.5, 0)};
  EXPECT_FALSE(every_press_matched(contacts, {press_at(0, 0), press_at(1.9, 0)}, 2));
  EXPECT_TRUE(every_press_matched(contacts, {press_at(1.9, 0), press_at(0, 0)}, 2));
}

// Three frames of four matched: 0.75; no frames: 0; lengths that differ: refused.
TEST(ContactScoring, FractionOfFramesMatched) {
  const ContactSequence contacts{{contact_at(0, 0)}, {contact_at(10, 10)}, {}, {contact_at(20, 21)}};
  const PressSequence presses{{press_at(0, 0)}, {press_at(10, 10)}, {}, {press_at(20, 25)}};
  EXPECT_DOUBLE_EQ(fraction_every_press_matched(contacts, presses, 2), 0.75);  // the 4th is 4 mm off
  EXPECT_DOUBLE_EQ(fraction_every_press_matched({}, {}, 2), 0.0);
  EXPECT_THROW(fraction_every_press_matched(contacts, {{press_at(0, 0)}}, 2), InvalidInput);
  EXPECT_THROW(score_single_presses(contacts, {{press_at(0, 0)}}), InvalidInput);
}

// A false contact is a contact no press takes and far from all: the press's own contact 12 mm
// off is a position error, not one; a second contact 12 mm off is; one 8 mm off (within the 10 mm
// of two radii) is not; any contact in a frame without presses is.
TEST(ContactScoring, FalseContactsAreContactsNoPressTakes) {
  EXPECT_FALSE(has_false_contact({contact_at(22, 10)}, {press_at(10, 10)}, 10));
  EXPECT_TRUE(has_false_contact({contact_at(10, 10), contact_at(22, 10)}, {press_at(10, 10)}, 10));
  EXPECT_TRUE(has_false_contact({contact_at(22, 10), contact_at(10, 10)}, {press_at(10, 10)}, 10));
  EXPECT_FALSE(has_false_contact({contact_at(10, 10), contact_at(18, 10)}, {press_at(10, 10)}, 10));
  EXPECT_FALSE(has_false_contact({contact_at(10, 10), contact_at(40, 40)}, {press_at(10, 10), press_at(40, 41)}, 10));
  EXPECT_TRUE(has_false_contact({contact_at(0, 0)}, {}, 10));
  EXPECT_FALSE(has_false_contact({}, {press_at(10, 10)}, 10));
}

}  // namespace
}  // namespace emit
