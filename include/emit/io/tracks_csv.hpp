#pragma once
/// \file tracks_csv.hpp
/// A run's touches as a flat CSV that a spreadsheet or pandas reads without code (`--tracks`): one
/// row per tracked contact per frame, and one row when a touch ends (phase "up", its last state):
///
///     time_s,frame,id,phase,x_mm,y_mm,z_mm,force_N,area_mm2,pressure_N_per_mm2,vx_mm_per_s,vy_mm_per_s
///     0.3,15,0,down,30.1,29.8,0,4.93,78.1,0.0631,0,0
///
/// time_s: the frame's time on the board's clock [s]; id: the touch's (frame/contact_tracker.hpp),
/// the same on every row of one touch. Numbers to 6 significant digits ('.' decimal point).
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "emit/frame/contacts.hpp"

namespace emit {

/// The header line, "time_s,frame,…\n".
void write_tracks_header(std::ostream& out);

/// One frame's rows: its tracked contacts, then the touches that ended with it (null: none).
/// Untracked contacts (id < 0) are skipped. Allocates nothing. \throw InvalidInput for a
/// non-finite number, before anything is written.
void write_tracks_rows(std::ostream& out, double time_s, std::uint64_t frame, const std::vector<Contact>& contacts,
                       const std::vector<Contact>* ended = nullptr);

}  // namespace emit
