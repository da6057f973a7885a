#pragma once
/// \file contacts_jsonl.hpp
/// Contacts out as JSON Lines (DESIGN §5), one object per frame:
/// {"frame": i, "contacts": [{"x_mm":…, "y_mm":…, "area_mm2":…, "pressure_N_per_mm2":…,
///   "peak_pressure_N_per_mm2":…, "force_N":…}]}
#include <ostream>
#include <string>
#include <vector>

#include "emit/reconstruct/contacts.hpp"

namespace emit {

/// Append one frame's line. Numbers are written with enough digits (e.g. %.6g), finite only.
void write_contacts_line(std::ostream& out, long frame, const std::vector<Contact>& contacts);

/// Parse one line back (for tests and tools). \throw InvalidInput naming what is wrong.
std::vector<Contact> parse_contacts_line(const std::string& line, long* frame = nullptr);

}  // namespace emit
