#pragma once
/// \file contacts_jsonl.hpp
/// Contacts out as JSON Lines (README, "Files"), one object per frame:
/// {"frame": i, "contacts": [{"x_mm":…, "y_mm":…[, "z_mm":…, "nx":…, "ny":…, "nz":…], "area_mm2":…,
/// "pressure_N_per_mm2":…,
///   "peak_pressure_N_per_mm2":…, "force_N":…[, "x_std_mm":…, "y_std_mm":…,
///   "pressure_std_N_per_mm2":…]}][, "fit_misfit_mV":…]}
/// The uncertainties (1σ) and the frame's fit misfit (RMS of predicted − measured, to compare with
/// the ADC's noise) come with contact fitting; a confident contact has a small σ in a frame whose
/// misfit is near the noise. z and the unit normal come for contacts off the plane z = 0 (a
/// curved sheet); a flat sheet's lines are as before (z = 0, normal +z). Then the outline's
/// ellipse (semi_major_mm, …) and its polygon "outline_mm": [[x, y], …] (3 to 64 vertices in the
/// sheet's chart, counter-clockwise, frame/contact_outline.hpp), each when the contact has one.
///
/// Touch over time (frame/contact_tracker.hpp): a tracked contact carries "id", "phase" ("down",
/// "move") and "vx_mm_per_s", "vy_mm_per_s"; the line's "ended" lists the touches that ended with
/// this frame, each its last state with phase "up" (absent: none ended). A live frame's line has
/// "board_time_s" (when the board took it, on the board's clock) and "host_time_s" (when it
/// reached the host, seconds since the Unix epoch, the host's system clock), after "frame".
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "emit/frame/contacts.hpp"

namespace emit {

/// A frame's times; NaN: not known (not written).
struct FrameTimes {
  double board_s = std::numeric_limits<double>::quiet_NaN();      ///< the board's clock [s]
  double host_unix_s = std::numeric_limits<double>::quiet_NaN();  ///< receipt, since the Unix epoch [s]
};

/// Append one frame's line. Numbers are written with enough digits (e.g. %.6g), finite only.
/// `fit_misfit_mV` < 0: not written. `ended`: null or empty, no "ended".
void write_contacts_line(std::ostream& out, long frame, const std::vector<Contact>& contacts, double fit_misfit_mV = -1,
                         const FrameTimes& times = {}, const std::vector<Contact>* ended = nullptr);

/// One line read back: everything write_contacts_line writes.
struct ContactsLine {
  long frame = 0;
  std::vector<Contact> contacts, ended;
  FrameTimes times;
  double fit_misfit_mV = -1;  ///< −1: absent
};

/// Parse one line back (for tests and tools). \throw InvalidInput naming what is wrong.
ContactsLine parse_contacts_record(const std::string& line);
/// Its contacts only.
std::vector<Contact> parse_contacts_line(const std::string& line, long* frame = nullptr);

}  // namespace emit
