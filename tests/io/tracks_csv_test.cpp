// Touches as a flat CSV (io/tracks_csv.hpp): the documented header and rows byte for byte, one row
// per tracked contact and per ended touch, untracked contacts left out, nothing written for a
// non-finite number, and no allocation per frame.
#include "emit/io/tracks_csv.hpp"

#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "emit/core/errors.hpp"

namespace emit {
namespace {

Contact touch(std::int64_t id, TouchPhase phase) {
  Contact c;
  c.id = id, c.phase = phase;
  c.x_mm = 30.125, c.y_mm = 29.5, c.force_N = 4.5, c.area_mm2 = 78.5, c.pressure_N_per_mm2 = 0.0625;
  c.vx_mm_per_s = 12.5, c.vy_mm_per_s = -2;
  return c;
}

TEST(TracksCsv, WritesTheDocumentedRows) {
  std::ostringstream out;
  write_tracks_header(out);
  const std::vector<Contact> ended{touch(2, TouchPhase::up)};
  Contact untracked = touch(-1, TouchPhase::none);
  write_tracks_rows(out, 0.3, 15, {touch(3, TouchPhase::down), untracked, touch(1, TouchPhase::move)}, &ended);
  EXPECT_EQ(out.str(),
            "time_s,frame,id,phase,x_mm,y_mm,z_mm,force_N,area_mm2,pressure_N_per_mm2,vx_mm_per_s,vy_mm_per_s\n"
            "0.3,15,3,down,30.125,29.5,0,4.5,78.5,0.0625,12.5,-2\n"
            "0.3,15,1,move,30.125,29.5,0,4.5,78.5,0.0625,12.5,-2\n"
            "0.3,15,2,up,30.125,29.5,0,4.5,78.5,0.0625,12.5,-2\n");
}

TEST(TracksCsv, RefusesANonFiniteNumberWritingNothing) {
  std::ostringstream out;
  Contact bad = touch(0, TouchPhase::move);
  bad.vx_mm_per_s = std::numeric_limits<double>::quiet_NaN();
  try {
    write_tracks_rows(out, 1, 7, {touch(1, TouchPhase::move), bad});
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "tracks of frame 7: a contact's number is not finite");
  }
  EXPECT_TRUE(out.str().empty()) << "no half frame";
}

TEST(TracksCsv, WritingAFrameAllocatesNothingOnceWarm) {
  std::ostringstream out;
  const std::vector<Contact> contacts{touch(0, TouchPhase::move), touch(1, TouchPhase::move)};
  write_tracks_rows(out, 0, 0, contacts);
  out.str(std::string(1 << 16, ' '));  // room for what follows
  out.seekp(0);
  const test::AllocationCounter counter;
  for (int frame = 1; frame < 100; ++frame) write_tracks_rows(out, 0.02 * frame, frame, contacts);
  EXPECT_EQ(counter.count(), 0);
}

}  // namespace
}  // namespace emit
