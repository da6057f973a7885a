// A real skin's folder of presses (io/real_dataset.hpp): read as laid out, with the per-frame
// references or the one reference, and every malformed file named with its line.
#include "emit/io/real_dataset.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace emit {
namespace {

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::string folder_with(const std::string& name, const std::string& frames, const std::string& references,
                        const std::string& truth) {
  std::string dir = test::temp_folder(name);
  write(dir + "/frames.csv", frames);
  if (!references.empty()) write(dir + "/references_per_frame.csv", references);
  write(dir + "/truth.csv", truth);
  return dir;
}

TEST(RealDataset, ReadsFramesReferencesAndTruth) {
  const std::string dir = folder_with("real_ok", "1,2,3\n4,5,6.5\n", "1,2,2\n4,4,6\n",
                                      "frame,contact,x_mm,y_mm,depth_mm\n1,0,-3.5,2,10\n0,0,1,1,15\n");
  const RealDataset d = read_real_dataset(dir);
  ASSERT_EQ(d.presses(), 2);
  ASSERT_EQ(d.readings(), 3);
  EXPECT_EQ(d.frames(1, 2), 6.5);
  EXPECT_TRUE(d.per_frame_references);
  EXPECT_EQ(d.references(1, 1), 4);
  ASSERT_EQ(d.contacts[1].size(), 1u);
  EXPECT_EQ(d.contacts[1][0], Vector2(-3.5, 2));
  // Without per-frame references, reference.csv serves every frame.
  const std::string one = folder_with("real_one", "1,2,3\n4,5,6\n", "", "frame,contact,x_mm,y_mm\n");
  write(one + "/reference.csv", "7,8,9\n");
  const RealDataset e = read_real_dataset(one);
  EXPECT_FALSE(e.per_frame_references);
  EXPECT_EQ(e.references.row(1), Eigen::RowVector3d(7, 8, 9));
  EXPECT_TRUE(e.contacts[0].empty());
}

TEST(RealDataset, MalformedFilesAreNamedWithTheirLine) {
  const std::string truth = "frame,contact,x_mm,y_mm\n0,0,1,1\n";
  auto dir = folder_with("real_nan", "1,2,3\n4,x,6\n", "1,2,3\n1,2,3\n", truth);
  EXPECT_EQ(test::error_of([&] { read_real_dataset(dir); }), dir + "/frames.csv:2: value 2 \"x\" is not a number");
  dir = folder_with("real_width", "1,2,3\n4,5\n", "1,2,3\n1,2,3\n", truth);
  EXPECT_EQ(test::error_of([&] { read_real_dataset(dir); }), dir + "/frames.csv:2: 2 values, the frames have 3");
  dir = folder_with("real_refs", "1,2,3\n4,5,6\n", "1,2,3\n", truth);
  EXPECT_EQ(test::error_of([&] { read_real_dataset(dir); }),
            dir + "/references_per_frame.csv: 1 references for 2 frames in frames.csv");
  dir = folder_with("real_truth", "1,2,3\n", "1,2,3\n", "frame,contact,x_mm,y_mm\n3,0,1,1\n");
  EXPECT_EQ(test::error_of([&] { read_real_dataset(dir); }),
            dir + "/truth.csv:2: frame \"3\" is not a frame of frames.csv (0 to 0)");
  dir = folder_with("real_header", "1,2,3\n", "1,2,3\n", "x,y\n");
  EXPECT_EQ(test::error_of([&] { read_real_dataset(dir); }),
            dir + "/truth.csv:1: expected the header \"frame,contact,x_mm,y_mm[,...]\", got \"x,y\"");
  dir = folder_with("real_noref", "1,2,3\n", "", truth);
  EXPECT_EQ(test::error_of([&] { read_real_dataset(dir); }),
            dir + ": neither references_per_frame.csv nor reference.csv (the unpressed frames)");
  EXPECT_EQ(test::error_of([&] { read_real_dataset(dir + "/none"); }), dir + "/none: not a folder of real presses");
  dir = folder_with("real_big", "1,2,3\n4,5,6\n", "1,2,3\n1,2,3\n", truth);
  EXPECT_EQ(test::error_of([&] { read_real_dataset(dir, 5); }),
            dir + "/frames.csv:2: more than 5 values in all; too large");
}

}  // namespace
}  // namespace emit
