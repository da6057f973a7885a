// Bounded line reading (io/line_reader.hpp): lines as written, "\r\n" and a byte-order mark
// accepted, a line beyond the bound an error naming file and line, read in bounded memory.
#include "emit/io/line_reader.hpp"

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

std::vector<std::string> all_lines(const std::string& path, std::size_t bound = LineReader::default_max_line_bytes) {
  LineReader reader(path, "test file", bound);
  std::vector<std::string> lines;
  for (std::string line; reader.next(line);) lines.push_back(line);
  return lines;
}

TEST(LineReader, LinesCrLfByteOrderMarkAndALastLineWithoutNewline) {
  const std::string path = test::temp_folder("line_reader") + "/a.csv";
  std::ofstream(path, std::ios::binary) << "\xef\xbb\xbf"
                                           "one\r\ntwo\n\nthree";
  EXPECT_EQ(all_lines(path), (std::vector<std::string>{"one", "two", "", "three"}));
}

TEST(LineReader, LinesAcrossTheReadBufferAreWhole) {
  const std::string path = test::temp_folder("line_reader") + "/long.csv";
  const std::string line(200'000, 'x');  // three times the 64 KiB buffer
  std::ofstream(path) << line << "\n" << line << "\n";
  const auto lines = all_lines(path);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1], line);
}

TEST(LineReader, ALineBeyondTheBoundIsAnErrorNamingTheLine) {
  const std::string path = test::temp_folder("line_reader") + "/b.csv";
  std::ofstream(path) << "short\n" << std::string(5000, '7') << "\n";
  try {
    all_lines(path, 4096);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), (path + ":2: line longer than 4 KiB (is this a test file?)").c_str());
  }
}

// `emit reconstruct --frames /dev/zero` used to grow to 5 GB in 13 s. Now one line's bound.
TEST(LineReader, DevZeroStopsAtTheBound) { EXPECT_THROW(all_lines("/dev/zero"), InvalidInput); }

TEST(LineReader, AMissingFileIsAnIoError) { EXPECT_THROW(LineReader("/nonexistent/x.csv", "frames file"), IoError); }

}  // namespace
}  // namespace emit
