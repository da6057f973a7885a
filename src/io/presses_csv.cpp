#include "emit/io/presses_csv.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "emit/core/errors.hpp"
#include "emit/core/output_file.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/io/line_reader.hpp"
#include "emit/sensor/press_outline.hpp"

namespace emit {

namespace {
const char* const header = "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2";
/// On a curved sheet the centre's height too (the surface's point above x, y).
const char* const header_with_z = "frame,x_mm,y_mm,z_mm,radius_mm,force_N,pressure_N_per_mm2";

/// An outline as one CSV field: "u v;u v;…", polygons separated by '|' (empty for a disc).
std::string outline_text(const std::vector<std::vector<Vector2>>& outline) {
  std::string text;
  char vertex[64];
  for (std::size_t k = 0; k < outline.size(); ++k) {
    if (k > 0) text += '|';
    for (std::size_t i = 0; i < outline[k].size(); ++i) {
      std::snprintf(vertex, sizeof vertex, "%s%.9g %.9g", i > 0 ? ";" : "", outline[k][i].x(), outline[k][i].y());
      text += vertex;
    }
  }
  return text;
}

/// outline_text's inverse. \throw InvalidInput naming `where` for a vertex that is not two numbers.
std::vector<std::vector<Vector2>> parse_outline_text(const std::string& text, const std::string& where) {
  std::vector<std::vector<Vector2>> outline;
  if (text.find_first_not_of(" \t") == std::string::npos) return outline;
  outline.emplace_back();
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t end = text.find_first_of(";|", at);
    const std::string vertex = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    double u = 0, v = 0;
    int used = 0;
    // NOLINTNEXTLINE(cert-err34-c): the field count and the end of the field check it
    if (std::sscanf(vertex.c_str(), " %lf %lf %n", &u, &v, &used) != 2 ||
        static_cast<std::size_t>(used) != vertex.size())
      throw InvalidInput(where + ": outline vertex " + quote_input(vertex) + " is not two numbers \"u v\"");
    outline.back().emplace_back(u, v);
    if (end == std::string::npos) break;
    if (text[end] == '|') outline.emplace_back();
    at = end + 1;
  }
  return outline;
}
/// The fields a row leaves empty: x_mm and y_mm together (a place not measured), force_N (a force
/// not measured; its pressure then empty too). Each empty numeric field of `line` is replaced by 0
/// so that the row parses as a full one; the caller sets what was empty to NaN after.
/// \throw InvalidInput naming `where` for one of x_mm, y_mm empty alone, or another field empty.
struct EmptyFields {
  bool place = false, force = false;
};

EmptyFields fill_empty_fields(std::string& line, bool with_z, const std::string& where) {
  // The numeric fields' indices: frame, x, y, [z,] radius, force, pressure.
  const int x = 1, y = 2, z = with_z ? 3 : -1, radius = with_z ? 4 : 3, force = radius + 1, pressure = force + 1;
  std::vector<bool> empty;
  std::string filled;
  std::size_t at = 0;
  for (int k = 0; k <= pressure; ++k) {
    const std::size_t end = line.find(',', at);
    const std::string field = line.substr(at, end == std::string::npos ? std::string::npos : end - at);
    const bool blank = field.find_first_not_of(" \t") == std::string::npos;
    empty.push_back(blank);
    filled += (k > 0 ? "," : "") + (blank ? std::string("0") : field);
    if (end == std::string::npos) {
      at = std::string::npos;
      break;
    }
    at = end + 1;
  }
  if (std::none_of(empty.begin(), empty.end(), [](bool e) { return e; })) return {};
  const auto is_empty = [&](int k) {
    return k >= 0 && static_cast<std::size_t>(k) < empty.size() && empty[static_cast<std::size_t>(k)];
  };
  EmptyFields fields{is_empty(x) && is_empty(y), is_empty(force)};
  if (is_empty(x) != is_empty(y))
    throw InvalidInput(where + ": x_mm and y_mm are empty together (a place not measured) or both given, got " +
                       quote_input(line));
  for (int k = 0; k < static_cast<int>(empty.size()); ++k)
    if (is_empty(k) && k != x && k != y && k != force && !(k == z && fields.place) && !(k == pressure && fields.force))
      throw InvalidInput(where +
                         ": only x_mm,y_mm (a place not measured) and force_N (a force not measured) may be "
                         "empty, got " +
                         quote_input(line));
  if (at != std::string::npos) filled += "," + line.substr(at);
  line = filled;
  return fields;
}

}  // namespace

void write_presses_csv(const std::string& path, const PressSequence& sequence) {
  OutputFile file({"", path});
  write_presses_csv(file.stream(), sequence);
  file.commit();
}

void write_presses_csv(std::ostream& out, const PressSequence& sequence) {
  // The profile column only when some press is not flat, so files of flat presses stay as they were.
  // Likewise the z column only where some press is off the plane (a curved sheet).
  // And the outline column only where some press has one (its profile written before it).
  bool profiles = false, heights = false, outlines = false;
  for (const auto& frame : sequence)
    for (const Press& p : frame) {
      profiles = profiles || p.profile != PressProfile::flat;
      heights = heights || (place_known(p) && p.z_mm != 0);
      outlines = outlines || !p.outline_mm.empty();
    }
  profiles = profiles || outlines;
  out << (heights ? header_with_z : header) << (profiles ? ",profile" : "") << (outlines ? ",outline" : "") << '\n';
  char row[256];
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t f = 0; f < sequence.size(); ++f)
    for (const Press& p : sequence[f]) {
      // A place or a force not measured (NaN: sensor/press.hpp) is an empty field, and so is the
      // pressure of a force not measured.
      int used = std::snprintf(row, sizeof row, "%zu", f);
      const auto field = [&](const char* format, double value) {
        used += std::snprintf(row + used, sizeof row - static_cast<std::size_t>(used), ",");
        if (std::isfinite(value))
          used += std::snprintf(row + used, sizeof row - static_cast<std::size_t>(used), format, value);
      };
      const bool place = place_known(p), force = force_known(p);
      field("%.4f", place ? p.x_mm : nan);
      field("%.4f", place ? p.y_mm : nan);
      if (heights) field("%.4f", place ? p.z_mm : nan);
      field("%.4f", p.radius_mm);
      field("%.6f", force ? p.force_N : nan);
      field("%.6f", force ? p.pressure_N_per_mm2() : nan);
      out << row;
      if (profiles) out << ',' << profile_name(p.profile);
      if (outlines) out << ',' << outline_text(p.outline_mm);
      out << '\n';
    }
}

PressSequence read_presses_csv(const std::string& path, std::size_t max_frames, UnknownPresses unknowns) {
  LineReader lines(path, "presses file");
  std::string line;
  const bool read = lines.next(line);
  const bool with_z = read && line.rfind("frame,x_mm,y_mm,z_mm,radius_mm,force_N", 0) == 0;
  if (!read || (!with_z && line.rfind("frame,x_mm,y_mm,radius_mm,force_N", 0) != 0))
    throw InvalidInput(path + ":1: expected the header \"" + std::string(header) +
                       "\" (or with z_mm after y_mm), got " + quote_input(line));
  const std::string expected = with_z ? ": expected frame,x_mm,y_mm,z_mm,radius_mm,force_N[,pressure_N_per_mm2], got "
                                      : ": expected frame,x_mm,y_mm,radius_mm,force_N[,pressure_N_per_mm2], got ";
  // The outline column only where the header names it: another 8th column stays an error.
  const bool with_outline = line.find(",profile,outline") != std::string::npos;
  PressSequence sequence;
  while (lines.next(line)) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const std::string original = line;  // quoted in errors; `line` has its empty fields filled
    const EmptyFields empty = fill_empty_fields(line, with_z, lines.where());
    if (empty.place && unknowns == UnknownPresses::refused)
      throw InvalidInput(lines.where() + ": place unknown: only emit calibrate takes presses without a place");
    if (empty.force && unknowns == UnknownPresses::refused)
      throw InvalidInput(lines.where() + ": force unknown: only emit calibrate takes presses without a force");
    long frame = -1;
    Press p;
    double pressure = 0;
    int consumed = 0;
    // glibc's sscanf converts as strtol and strtod do (saturating on overflow); the field count
    // and the end of the line reject a malformed line, the check below a negative frame.
    // With z the fields are counted as without it: 5 required, a 6th the pressure.
    // NOLINTBEGIN(cert-err34-c)
    const int fields = with_z ? std::sscanf(line.c_str(), "%ld,%lf,%lf,%lf,%lf,%lf%n,%lf%n", &frame, &p.x_mm, &p.y_mm,
                                            &p.z_mm, &p.radius_mm, &p.force_N, &consumed, &pressure, &consumed) -
                                    1
                              : std::sscanf(line.c_str(), "%ld,%lf,%lf,%lf,%lf%n,%lf%n", &frame, &p.x_mm, &p.y_mm,
                                            &p.radius_mm, &p.force_N, &consumed, &pressure, &consumed);
    // NOLINTEND(cert-err34-c)
    // An optional 7th column after the pressure: the profile, flat or spherical.
    const auto rest = static_cast<std::size_t>(consumed);
    // A word there that is not a profile is named as such; a number stays a malformed line.
    if (fields == 6 && rest + 1 < line.size() && line[rest] == ',' &&
        std::isalpha(static_cast<unsigned char>(line[rest + 1]))) {
      std::string name = line.substr(rest + 1);
      if (const std::size_t comma = name.find(','); with_outline && comma != std::string::npos) {  // an outline
        p.outline_mm = parse_outline_text(name.substr(comma + 1), lines.where());
        name.erase(comma);
      }
      name.erase(name.find_last_not_of(" \t") + 1);
      try {
        p.profile = parse_press_profile(name);
      } catch (const InvalidInput&) {
        throw InvalidInput(lines.where() + ": profile " + quote_input(name) + " is not flat or spherical");
      }
      consumed = static_cast<int>(line.size());
    }
    const bool whole_line =
        consumed > 0 && line.find_first_not_of(" \t", static_cast<std::size_t>(consumed)) == std::string::npos;
    if (fields < 5 || !whole_line || frame < 0) throw InvalidInput(lines.where() + expected + quote_input(original));
    if (!std::isfinite(p.x_mm) || !std::isfinite(p.y_mm) || !std::isfinite(p.z_mm) || !(p.radius_mm > 0) ||
        !std::isfinite(p.radius_mm) || !(p.force_N >= 0) || !std::isfinite(p.force_N))
      throw InvalidInput(lines.where() + ": a press needs a finite place, a radius > 0 and a force >= 0, got " +
                         quote_input(original));
    if (empty.place) p.x_mm = p.y_mm = p.z_mm = std::numeric_limits<double>::quiet_NaN();
    if (empty.force) p.force_N = std::numeric_limits<double>::quiet_NaN();
    if (!p.outline_mm.empty()) {
      validate_outline(p.outline_mm, lines.where());
      if (p.profile != PressProfile::flat) throw InvalidInput(lines.where() + ": an outline press must be flat");
    }
    if (static_cast<std::size_t>(frame) >= max_frames)
      throw InvalidInput(lines.where() + ": frame " + std::to_string(frame) + " is beyond the " +
                         std::to_string(max_frames) + " frames it describes");
    if (static_cast<std::size_t>(frame) >= sequence.size()) sequence.resize(static_cast<std::size_t>(frame) + 1);
    sequence[static_cast<std::size_t>(frame)].push_back(p);
  }
  return sequence;
}

}  // namespace emit
