// Which readings of a real board can be trusted (model/reading_screen.hpp): a rail is found only
// where the largest value recurs as a clipping ADC's top code does; a dropped sample, a value not
// finite and one at the rail are masked; a channel stuck at one value, or bad in most frames, is
// dropped for good; the worst channels are named in order.
#include "emit/model/reading_screen.hpp"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace emit {
namespace {

/// 200 frames of 12 readings, each a random value in (100, 900) at full resolution, and references alike.
void random_frames(Matrix& frames, Matrix& references) {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> value(100, 900);
  frames.resize(200, 12);
  references.resize(200, 12);
  for (Index i = 0; i < frames.size(); ++i) frames(i) = value(random), references(i) = value(random);
}

TEST(ReadingScreen, FindsARailOnlyWhereTheTopValueRecurs) {
  Matrix frames, references;
  random_frames(frames, references);
  // Free readings: no value repeats, so no rail; nothing is masked.
  ReadingSurvey clean = survey_readings(frames, references);
  EXPECT_FALSE(clean.rail_found);
  EXPECT_EQ(clean.screen.rail, std::numeric_limits<double>::infinity());
  EXPECT_EQ(clean.masked_readings, 0);
  EXPECT_TRUE(clean.worst(3).empty());
  // A board clipping at 1000 in 3 frames of 200 (1.5 %, above the 1 % a rail needs): masked there.
  for (const Index i : {10, 50, 90}) frames(i, 4) = 1000;
  ReadingSurvey clipped = survey_readings(frames, references);
  EXPECT_TRUE(clipped.rail_found);
  EXPECT_EQ(clipped.screen.rail, 1000);
  EXPECT_EQ(clipped.masked_readings, 3);
  EXPECT_EQ(clipped.bad_frames[4], 3);
  EXPECT_FALSE(clipped.screen.usable(1000, 500));
  EXPECT_TRUE(clipped.screen.usable(999.9, 500));
  // Clipped in 1 frame only (0.5 %): a large value, not a rail.
  frames(50, 4) = frames(90, 4) = 800;
  EXPECT_FALSE(survey_readings(frames, references).rail_found);
  // A stated rail is taken as stated.
  ReadingSurveyOptions stated;
  stated.rail = 850;
  const ReadingSurvey at_850 = survey_readings(frames, references, stated);
  EXPECT_FALSE(at_850.rail_found);
  EXPECT_EQ(at_850.screen.rail, 850);
  EXPECT_GT(at_850.masked_readings, 0);
}

TEST(ReadingScreen, MasksBadReadingsAndDropsChannelsBadInMostFrames) {
  Matrix frames, references;
  random_frames(frames, references);
  frames(3, 0) = 0;                                         // a dropped sample
  frames(4, 0) = std::numeric_limits<double>::quiet_NaN();  // a value not finite
  references(5, 1) = -2;                                    // a reference not positive
  frames(6, 1) = std::numeric_limits<double>::infinity();
  for (Index i = 0; i < 101; ++i) frames(i, 7) = 0;  // bad in 101 of 200 frames: dropped
  frames.col(9).setConstant(512);                    // stuck: one value everywhere
  references.col(9).setConstant(512);
  const ReadingSurvey s = survey_readings(frames, references);
  EXPECT_EQ(s.bad_frames[0], 2);
  EXPECT_EQ(s.bad_frames[1], 2);
  EXPECT_EQ(s.bad_frames[7], 101);
  EXPECT_EQ(s.stuck, std::vector<Index>{9});
  EXPECT_EQ(s.dropped(), (std::vector<Index>{7, 9}));
  // Dropped channels are not counted again as masked: 4 readings in frames 3–6.
  EXPECT_EQ(s.masked_readings, 4);
  EXPECT_EQ(s.frames_with_bad, 4);
  EXPECT_EQ(s.worst(2), (std::vector<Index>{7, 0}));  // most bad first; ties in channel order
  ReadingSurveyOptions bad;
  bad.drop_above = 1;
  EXPECT_EQ(test::error_of([&] { survey_readings(frames, references, bad); }),
            "drop above: must be in [0, 1), got 1.000000");
  EXPECT_EQ(test::error_of([&] { survey_readings(frames, references.topRows(3)); }),
            "reading survey: 200 × 12 frames against 3 × 12 references");
}

}  // namespace
}  // namespace emit
