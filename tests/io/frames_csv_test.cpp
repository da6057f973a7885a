// Frames as CSV (io/frames_csv.hpp): written with 7 decimals and read back to them; blank lines
// skipped; a bad value or count an error naming the file, the line and the value.
#include "emit/io/frames_csv.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

// %.7f: each value within half a unit of the 7th decimal, 5e-8 V (plus the double's rounding).
TEST(FramesCsv, RoundTripToSevenDecimals) {
  const std::string path = test::temp_folder("frames_csv") + "/f.csv";
  Frame a(3, 3), b(3, 3);
  a << 0, 1.23456789, -2.5, 1e-9, 0, 3.3, 0.1, 0.2, 0;
  b = a * -0.37;
  write_frames_csv(path, {a, b});
  const auto frames = read_frames_csv(path, 3);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_LE((frames[0] - a).cwiseAbs().maxCoeff(), 5e-8 + 1e-15);
  EXPECT_LE((frames[1] - b).cwiseAbs().maxCoeff(), 5e-8 + 1e-15);
  // Round-off below the printed resolution is written as 0, never "-0.0000000".
  EXPECT_EQ(test::read_text(path).find("-0.0000000"), std::string::npos);
  EXPECT_EQ(test::read_text(path).substr(0, 30), "0.0000000,1.2345679,-2.5000000");
}

TEST(FramesCsv, SkipsBlankLinesAndToleratesSpaces) {
  const std::string path = test::temp_folder("frames_csv_blank") + "/f.csv";
  std::ofstream(path) << "\n1, 2 ,3,4\r\n  \n5,6,7,8\n";
  const auto frames = read_frames_csv(path, 2);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0](1, 0), 3.0);  // ground-major: value l·N + m is row l, column m
  EXPECT_EQ(frames[1](1, 1), 8.0);
}

std::string error_of(const std::string& path, int electrodes) {
  try {
    read_frames_csv(path, electrodes);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(FramesCsv, ErrorsNameTheLineAndTheValue) {
  const std::string dir = test::temp_folder("frames_csv_bad");
  std::ofstream(dir + "/long.csv") << "1,2,3,4\n1,2,3,4,5\n";
  EXPECT_EQ(error_of(dir + "/long.csv", 2), dir + "/long.csv:2: 5 values, expected 4 (2 electrodes)");
  std::ofstream(dir + "/inf.csv") << "1,inf,3,4\n";
  EXPECT_EQ(error_of(dir + "/inf.csv", 2), dir + "/inf.csv:1: value 2 is inf");
  std::ofstream(dir + "/empty_value.csv") << "1,,3,4\n";
  EXPECT_EQ(error_of(dir + "/empty_value.csv", 2), dir + "/empty_value.csv:1: value 2 \"\" is not a number");
  std::ofstream(dir + "/trailing.csv") << "1,2,3,4 V\n";
  EXPECT_EQ(error_of(dir + "/trailing.csv", 2), dir + "/trailing.csv:1: value 4 \"4 V\" is not a number");
  EXPECT_EQ(error_of(dir + "/none.csv", 2), dir + "/none.csv: cannot open frames file (No such file or directory)");
}

TEST(FramesCsv, WritingIntoAMissingFolderLeavesNothing) {
  const std::string dir = test::temp_folder("frames_csv_folder");
  try {
    write_frames_csv(dir + "/no/f.csv", {Frame::Zero(2, 2)});
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/no/f.csv: cannot write: folder " + dir + "/no does not exist");
  }
}

}  // namespace
}  // namespace emit

namespace emit {
namespace {

// An empty frames file used to exit 0 and replace a good contacts file with an empty one.
TEST(FramesCsv, AFileWithoutFramesIsAnError) {
  const std::string path = test::temp_folder("frames_csv_empty") + "/empty.csv";
  std::ofstream(path) << "\n  \n";
  try {
    read_frames_csv(path, 3);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), (path + ": no frames (an empty file?)").c_str());
  }
}

// Frames one at a time: the same frames as read whole, the line of each known.
TEST(FramesCsv, TheStreamingReaderGivesTheSameFramesAndTheirLines) {
  const std::string path = test::temp_folder("frames_csv_stream") + "/f.csv";
  std::ofstream(path) << "\xef\xbb\xbf"
                         "1,2,3,4\r\n\n5,6,7,8\n";
  FramesCsvReader reader(path, 2);
  Frame frame;
  ASSERT_TRUE(reader.next(frame));
  EXPECT_EQ(frame(1, 0), 3.0);  // ground-major: index l·N + m
  ASSERT_TRUE(reader.next(frame));
  EXPECT_EQ(frame(1, 1), 8.0);
  EXPECT_EQ(reader.where(), path + ":3");
  EXPECT_FALSE(reader.next(frame));
  EXPECT_EQ(reader.frames_read(), 2);
}

// A line of semicolons used to be echoed whole (4 KB) and binary bytes raw.
TEST(FramesCsv, MessagesQuoteAShortEscapedPieceOfTheLine) {
  const std::string path = test::temp_folder("frames_csv_quote") + "/f.csv";
  std::ofstream(path, std::ios::binary) << std::string(4096, ';') << "\n";
  try {
    read_frames_csv(path, 2);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), (path + ":1: value 1 \"" + std::string(40, ';') + "...\" is not a number").c_str());
  }
  std::ofstream(path, std::ios::binary) << std::string("1,\x01\x02,3,4\n");
  try {
    read_frames_csv(path, 2);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), (path + ":1: value 2 \"\\x01\\x02\" is not a number").c_str());
  }
}

}  // namespace
}  // namespace emit
