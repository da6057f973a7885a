#include "emit/io/tracks_csv.hpp"

#include <cmath>
#include <cstdio>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

void check_finite(double time_s, std::uint64_t frame, const std::vector<Contact>& contacts) {
  const auto bad = [&](const char* what) {
    throw InvalidInput("tracks of frame " + std::to_string(frame) + ": " + what + " is not finite");
  };
  if (!std::isfinite(time_s)) bad("the time");
  for (const Contact& c : contacts)
    for (const double v :
         {c.x_mm, c.y_mm, c.z_mm, c.force_N, c.area_mm2, c.pressure_N_per_mm2, c.vx_mm_per_s, c.vy_mm_per_s})
      if (!std::isfinite(v)) bad("a contact's number");
}

void write_rows(std::ostream& out, double time_s, std::uint64_t frame, const std::vector<Contact>& contacts) {
  char row[320];  // 12 fields of at most 24 characters
  for (const Contact& c : contacts) {
    if (c.id < 0) continue;
    const int n = std::snprintf(row, sizeof row, "%.9g,%llu,%lld,%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", time_s,
                                static_cast<unsigned long long>(frame), static_cast<long long>(c.id),
                                touch_phase_name(c.phase), c.x_mm, c.y_mm, c.z_mm, c.force_N, c.area_mm2,
                                c.pressure_N_per_mm2, c.vx_mm_per_s, c.vy_mm_per_s);
    out.write(row, n);
  }
}

}  // namespace

void write_tracks_header(std::ostream& out) {
  out << "time_s,frame,id,phase,x_mm,y_mm,z_mm,force_N,area_mm2,pressure_N_per_mm2,vx_mm_per_s,vy_mm_per_s\n";
}

void write_tracks_rows(std::ostream& out, double time_s, std::uint64_t frame, const std::vector<Contact>& contacts,
                       const std::vector<Contact>* ended) {
  check_finite(time_s, frame, contacts);
  if (ended) check_finite(time_s, frame, *ended);
  write_rows(out, time_s, frame, contacts);
  if (ended) write_rows(out, time_s, frame, *ended);
}

}  // namespace emit
