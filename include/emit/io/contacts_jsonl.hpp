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
#include <ostream>
#include <string>
#include <vector>

#include "emit/frame/contacts.hpp"

namespace emit {

/// Append one frame's line. Numbers are written with enough digits (e.g. %.6g), finite only.
/// `fit_misfit_mV` < 0: not written.
void write_contacts_line(std::ostream& out, long frame, const std::vector<Contact>& contacts,
                         double fit_misfit_mV = -1);

/// Parse one line back (for tests and tools). \throw InvalidInput naming what is wrong.
std::vector<Contact> parse_contacts_line(const std::string& line, long* frame = nullptr);

}  // namespace emit
