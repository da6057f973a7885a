// Current-injection protocols (sensor/excitation.hpp). The hydrogel skin's board (Hardman et al.
// 2023; OpenEIT's lookup table of 192 channels) drives opposite pairs and reads the 12 adjacent
// pairs clear of the drive: the named patterns give its table in its order (rows checked below
// are the table's own: channel, source, sink, V+, V−).
#include "emit/sensor/excitation.hpp"

#include <array>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace emit {
namespace {

TEST(Excitation, OppositeDriveAndAdjacentPairsAreTheHydrogelBoardsTable) {
  const std::vector<EitDrive> drives = drive_pattern("opposite", 16);
  ASSERT_EQ(drives.size(), 16u);
  const std::vector<EitReading> readings = adjacent_readings(drives, 16, /*skip_driving=*/true);
  ASSERT_EQ(readings.size(), 192u);
  for (const std::array<int, 5>& row :
       {std::array{0, 0, 8, 2, 1}, std::array{6, 0, 8, 10, 9}, std::array{60, 5, 13, 1, 0},
        std::array{67, 5, 13, 10, 9}, std::array{191, 15, 7, 14, 13}}) {
    const EitReading& r = readings[static_cast<std::size_t>(row[0])];
    EXPECT_EQ(drives[static_cast<std::size_t>(r.drive)].source, row[1]) << "channel " << row[0];
    EXPECT_EQ(drives[static_cast<std::size_t>(r.drive)].sink, row[2]) << "channel " << row[0];
    EXPECT_EQ(r.plus, row[3]) << "channel " << row[0];
    EXPECT_EQ(r.minus, row[4]) << "channel " << row[0];
  }
  // Without skipping, every drive reads all 16 pairs (pyEIT's default).
  EXPECT_EQ(adjacent_readings(drives, 16, false).size(), 256u);
  Excitation excitation{2e-3, 25e3, drives, readings, {}};
  const Matrix I = excitation.drive_currents_A(16);
  EXPECT_EQ(I(0, 0), 2e-3);
  EXPECT_EQ(I(8, 0), -2e-3);
  EXPECT_EQ(I.cwiseAbs().sum(), 16 * 4e-3);
}

TEST(Excitation, NamedDrivePatterns) {
  const auto adjacent = drive_pattern("adjacent", 8);
  EXPECT_EQ(adjacent[7].source, 7);
  EXPECT_EQ(adjacent[7].sink, 0);
  const auto skip = drive_pattern("skip-2", 8);
  EXPECT_EQ(skip[6].source, 6);
  EXPECT_EQ(skip[6].sink, 1);
  EXPECT_EQ(drive_pattern("opposite", 8)[1].sink, 5);
  EXPECT_EQ(test::error_of([] { drive_pattern("opposite", 7); }),
            "drive pattern \"opposite\": 7 electrodes have no opposite");
  EXPECT_EQ(test::error_of([] { drive_pattern("skip-7", 8); }),
            "drive pattern \"skip-7\": skip at most 6 of 8 electrodes");
  EXPECT_EQ(test::error_of([] { drive_pattern("diagonal", 8); }),
            "drive pattern \"diagonal\": must be adjacent, opposite or skip-<s> (e.g. skip-4)");
  EXPECT_EQ(test::error_of([] { drive_pattern("skip-", 8); }),
            "drive pattern \"skip-\": must be adjacent, opposite or skip-<s> (e.g. skip-4)");
}

}  // namespace
}  // namespace emit
