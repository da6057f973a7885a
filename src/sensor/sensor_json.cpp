#include "emit/sensor/sensor_json.hpp"

#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/sensor/electrode_layout.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

using nlohmann::json;

namespace {

enum class Sign { any, positive, non_negative };

/// The most points a polygon outline may have (shape.points_mm).
constexpr std::size_t max_polygon_points = 20000;

/// A value as an error message shows it: as written, unless it nests lists or objects, then by its
/// kind only (dump() recurses once per level: a file nested some 10^4 levels deep overflowed the
/// stack; tests/fuzz/sensor_json_fuzz.cpp found it).
std::string shown(const json& v) {
  if (v.is_structured())
    for (const json& item : v)
      if (item.is_structured()) return std::string("a nested JSON ") + v.type_name();
  return v.dump();
}

/// A number as a person writes it: "20", "2.5", "1e-15".
std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

/// Reads one JSON object key by key and, on finish(), rejects keys nobody asked for. Every error
/// names the full key path ("contact_law.gamma"), so the user knows exactly what to fix.
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string path) : object_(object), path_(std::move(path)) {
    if (!object_.is_object()) fail(path_, "must be a JSON object");
  }

  [[noreturn]] static void fail(const std::string& key_path, const std::string& what) {
    throw InvalidInput(key_path + ": " + what);
  }
  std::string key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  bool has(const std::string& key) const { return object_.contains(key); }

  const json& value(const std::string& key) {
    used_.insert(key);
    if (!object_.contains(key)) fail(key_path(key), "missing");
    return object_.at(key);
  }

  double number(const std::string& key, Sign sign) { return check_number(key, value(key), sign); }
  double number_or(const std::string& key, double fallback, Sign sign) {
    return has(key) ? number(key, sign) : fallback;
  }
  int integer_or(const std::string& key, int fallback, int min_value, int max_value) {
    if (!has(key)) return fallback;
    const json& v = value(key);
    if (!v.is_number_integer()) fail(key_path(key), "must be an integer, got " + shown(v));
    const auto i = v.get<long long>();
    if (i < min_value || i > max_value)
      fail(key_path(key), "must be between " + std::to_string(min_value) + " and " + std::to_string(max_value) +
                              ", got " + std::to_string(i));
    return static_cast<int>(i);
  }
  std::string string(const std::string& key) {
    const json& v = value(key);
    if (!v.is_string()) fail(key_path(key), "must be a string, got " + shown(v));
    return v.get<std::string>();
  }
  Vector2 point(const std::string& key) { return check_point(key_path(key), value(key)); }

  void finish() const {
    for (const auto& item : object_.items())
      if (!used_.count(item.key())) fail(key_path(item.key()), "unknown key");
  }

  static Vector2 check_point(const std::string& key_path, const json& v) {
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
      fail(key_path, "must be a point [x, y] in mm, got " + shown(v));
    Vector2 p(v[0].get<double>(), v[1].get<double>());  // not const: returned by move
    if (!p.allFinite()) fail(key_path, "must be finite");
    return p;
  }

 private:
  double check_number(const std::string& key, const json& v, Sign sign) const {
    if (!v.is_number()) fail(key_path(key), "must be a number, got " + shown(v));
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(key_path(key), "must be a finite number, got " + number_text(x));
    if (sign == Sign::positive && !(x > 0)) fail(key_path(key), "must be positive, got " + v.dump());
    if (sign == Sign::non_negative && x < 0) fail(key_path(key), "must not be negative, got " + v.dump());
    return x;
  }

  const json& object_;
  std::string path_;
  std::set<std::string> used_;
};

Shape parse_shape(const json& j, const std::string& base_dir) {
  ObjectReader r(j, "shape");
  Shape shape;
  const std::string type = r.string("type");
  if (type == "rectangle") {
    shape.kind = ShapeKind::rectangle;
    shape.width_mm = r.number("width_mm", Sign::positive);
    shape.height_mm = r.number("height_mm", Sign::positive);
  } else if (type == "circle") {
    shape.kind = ShapeKind::circle;
    shape.radius_mm = r.number("radius_mm", Sign::positive);
    shape.center_mm = r.has("center_mm") ? r.point("center_mm") : Vector2(shape.radius_mm, shape.radius_mm);
  } else if (type == "polygon") {
    shape.kind = ShapeKind::polygon;
    const json& points = r.value("points_mm");
    if (!points.is_array()) ObjectReader::fail("shape.points_mm", "must be a list of points [x, y]");
    // Checking an outline for crossings takes time that grows up to the square of its points (a
    // point is a border curve for Gmsh, too): the bound keeps the worst under a second.
    if (points.size() > max_polygon_points)
      ObjectReader::fail("shape.points_mm", std::to_string(points.size()) + " points, more than the " +
                                                std::to_string(max_polygon_points) +
                                                " a polygon may have: simplify the outline (a point every 0.1 mm of "
                                                "a 2 m border is still fewer)");
    for (std::size_t i = 0; i < points.size(); ++i)
      shape.points_mm.push_back(ObjectReader::check_point("shape.points_mm[" + std::to_string(i) + "]", points[i]));
  } else if (type == "spherical_cap") {
    shape.kind = ShapeKind::spherical_cap;
    shape.sphere_radius_mm = r.number("sphere_radius_mm", Sign::positive);
    shape.radius_mm = r.number("base_radius_mm", Sign::positive);
    shape.center_mm = Vector2::Zero();
    if (shape.radius_mm > shape.sphere_radius_mm)
      ObjectReader::fail("shape.base_radius_mm", "must not exceed sphere_radius_mm (" +
                                                     number_text(shape.sphere_radius_mm) + "), got " +
                                                     number_text(shape.radius_mm));
  } else if (type == "cylinder") {
    shape.kind = ShapeKind::cylinder;
    shape.radius_mm = r.number("radius_mm", Sign::positive);
    shape.length_mm = r.number("length_mm", Sign::positive);
    shape.angle_deg = r.number("angle_deg", Sign::any);
    if (!(shape.angle_deg > 0 && shape.angle_deg <= 360))
      ObjectReader::fail("shape.angle_deg",
                         "must be in (0, 360] (360 is a sleeve), got " + number_text(shape.angle_deg));
  } else if (type == "mesh") {
    shape.kind = ShapeKind::mesh_file;
    const std::filesystem::path file = r.string("file");
    shape.mesh_path = (file.is_absolute() ? file : std::filesystem::path(base_dir) / file).string();
    if (!is_msh_file(shape.mesh_path) && !is_stl_file(shape.mesh_path) && !is_cad_file(shape.mesh_path)) {
      const std::string extension = file.extension().string();
      ObjectReader::
          fail("shape.file",
               quote_input(file.string(), 40) +
                   (extension.empty() ? " has no extension" : " is a " + quote_input(extension, 16) + " file") +
                   ": a sheet's file is a Gmsh mesh (.msh), an STL surface (.stl) or CAD (.step, .stp, .iges, .igs)");
    }
  } else {
    ObjectReader::fail("shape.type",
                       "must be rectangle, circle, polygon, spherical_cap, cylinder or mesh, got \"" + type + "\"");
  }
  r.finish();
  return shape;
}

Border border_of(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::rectangle: return Border::rectangle(shape.width_mm, shape.height_mm);
    case ShapeKind::circle: return Border::circle(shape.center_mm, shape.radius_mm);
    case ShapeKind::spherical_cap: return Border::circle(Vector2::Zero(), shape.radius_mm);
    case ShapeKind::cylinder:  // the chart's rectangle (sensor/surface.hpp)
      return Border::rectangle(shape.length_mm, shape.radius_mm * shape.angle_deg * std::numbers::pi / 180);
    case ShapeKind::polygon: try { return Border::polygon(shape.points_mm);
      } catch (const InvalidInput& e) {
        ObjectReader::fail("shape.points_mm", e.what());
      }
    case ShapeKind::mesh_file: break;
  }
  throw std::logic_error("border_of: no analytic border for a mesh file");
}

/// A cylinder's electrode centre {x_mm, angle_deg} as its chart point (sensor/surface.hpp): it must
/// be on a rim (x = ±L/2) or, on a patch, on a straight side (θ = ±α/2).
Vector2 cylinder_electrode_chart_mm(ObjectReader& r, const std::string& where, const Shape& shape,
                                    const Border& border) {
  if (r.has("y_mm"))
    ObjectReader::fail(where + ".y_mm",
                       "a cylinder's electrodes are placed by x_mm (along its axis) and angle_deg; remove y_mm");
  const double x_mm = r.number("x_mm", Sign::any);
  const double angle_deg = r.number("angle_deg", Sign::any);
  const double half_length = shape.length_mm / 2, half_angle = shape.angle_deg / 2;
  const bool sleeve = is_sleeve(shape);
  if (sleeve && !(angle_deg > -180 && angle_deg <= 180))
    ObjectReader::fail(where + ".angle_deg", "must be in (-180, 180] on a sleeve, got " + number_text(angle_deg));
  if (!sleeve && std::abs(angle_deg) > half_angle * (1 + 1e-12))
    ObjectReader::fail(where + ".angle_deg", "must be within +-" + number_text(half_angle) + " (the patch's angle is " +
                                                 number_text(shape.angle_deg) + "), got " + number_text(angle_deg));
  if (std::abs(x_mm) > half_length * (1 + 1e-12))
    ObjectReader::fail(where + ".x_mm",
                       "must be within +-" + number_text(half_length) + " (half the length), got " + number_text(x_mm));
  const double tolerance_mm = border_tolerance_mm(border);
  const bool on_rim = std::abs(std::abs(x_mm) - half_length) <= tolerance_mm;
  const bool on_side =
      std::abs(half_angle - std::abs(angle_deg)) * std::numbers::pi / 180 * shape.radius_mm <= tolerance_mm;
  // On a sleeve θ = 180 between the rims is on the seam: validate_sleeve_electrodes says so.
  if (!on_rim && !on_side)
    ObjectReader::fail(where, "(x_mm " + number_text(x_mm) + ", angle_deg " + number_text(angle_deg) +
                                  ") is not on the border: give x_mm = +-" + number_text(half_length) + " (a rim)" +
                                  (sleeve ? "" : " or angle_deg = +-" + number_text(half_angle) + " (a side)"));
  return {x_mm + half_length, shape.radius_mm * (angle_deg + half_angle) * std::numbers::pi / 180};
}

std::vector<Electrode> parse_electrodes(const json& j, const Shape& shape, const Border& border) {
  std::vector<Electrode> electrodes;
  if (j.is_object()) {
    ObjectReader r(j, "electrodes");
    const int count = r.integer_or("count", 16, 0, 1024);
    if (!r.has("count")) r.value("count");  // required: reports "electrodes.count: missing"
    const double width_mm = r.number("width_mm", Sign::positive);
    r.finish();
    electrodes = default_electrode_layout(shape, border, count, width_mm);
  } else if (j.is_array()) {
    std::vector<Vector2> centers;
    std::vector<double> widths;
    const bool round = shape.kind == ShapeKind::circle || shape.kind == ShapeKind::spherical_cap;
    for (std::size_t i = 0; i < j.size(); ++i) {
      const std::string where = "electrodes[" + std::to_string(i) + "]";
      ObjectReader r(j[i], where);
      if (shape.kind == ShapeKind::cylinder) {
        centers.push_back(cylinder_electrode_chart_mm(r, where, shape, border));
      } else if (r.has("angle_deg")) {  // on a round border: the angle from +x, counter-clockwise seen from +z
        if (!round && r.has("x_mm") && !r.has("y_mm"))
          ObjectReader::fail(where + ".angle_deg", "with x_mm is for a cylinder; give x_mm, y_mm");
        if (!round)
          ObjectReader::fail(where + ".angle_deg", "is for a circle's or a spherical cap's rim; give x_mm, y_mm");
        if (r.has("x_mm") || r.has("y_mm")) ObjectReader::fail(where, "give angle_deg or x_mm, y_mm, not both");
        const double angle_rad = r.number("angle_deg", Sign::any) * std::numbers::pi / 180;
        centers.emplace_back(shape.center_mm + shape.radius_mm * Vector2(std::cos(angle_rad), std::sin(angle_rad)));
      } else {
        centers.emplace_back(r.number("x_mm", Sign::any), r.number("y_mm", Sign::any));
      }
      widths.push_back(r.number("width_mm", Sign::positive));
      r.finish();
    }
    electrodes = place_electrodes(border, centers, widths);
  } else {
    ObjectReader::fail("electrodes",
                       "must be {count, width_mm} or a list of {x_mm, y_mm, width_mm} (or {angle_deg, width_mm}, or "
                       "on a cylinder {x_mm, angle_deg, width_mm})");
  }
  validate_electrodes(border, electrodes);
  validate_sleeve_electrodes(shape, border, electrodes);
  return electrodes;
}

/// "series_resistance_ohm": one number for every electrode, or one per electrode; ≥ 0 Ω.
std::vector<double> parse_series_resistance(ObjectReader& r, const Sensor& sensor) {
  const std::string key = "series_resistance_ohm";
  const json& v = r.value(key);
  const auto ohm = [&](const json& x) {
    if (!x.is_number() || !std::isfinite(x.get<double>()) || x.get<double>() < 0)
      ObjectReader::fail(key, "must be a number of ohms, not negative, or a list of them; got " + shown(x));
    return x.get<double>();
  };
  if (v.is_number()) {
    if (sensor.shape.kind == ShapeKind::mesh_file)
      ObjectReader::fail(key, "give one value per electrode for a mesh-file sensor");
    return std::vector<double>(sensor.electrodes.size(), ohm(v));
  }
  if (!v.is_array()) ObjectReader::fail(key, "must be a number of ohms or a list of one per electrode");
  std::vector<double> values;
  for (const json& x : v) values.push_back(ohm(x));
  if (sensor.shape.kind != ShapeKind::mesh_file && values.size() != sensor.electrodes.size())
    ObjectReader::fail(key, std::to_string(values.size()) + " values for " + std::to_string(sensor.electrodes.size()) +
                                " electrodes");
  return values;
}

/// An electrode index in a protocol's list: an integer in [0, N).
int electrode_index(const json& v, int electrode_count, const std::string& where) {
  if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() >= electrode_count)
    ObjectReader::fail(where,
                       "must be an electrode number 0 to " + std::to_string(electrode_count - 1) + ", got " + shown(v));
  return static_cast<int>(v.get<long long>());
}

/// A list of [a, b] electrode pairs (drives: [source, sink]; readings: [+, −]), a ≠ b.
std::vector<std::array<int, 2>> electrode_pairs(const json& v, int electrode_count, const std::string& where,
                                                const char* form) {
  if (!v.is_array() || v.empty()) ObjectReader::fail(where, std::string("must be a list of ") + form);
  std::vector<std::array<int, 2>> pairs;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    if (!v[i].is_array() || v[i].size() != 2)
      ObjectReader::fail(at, std::string("must be ") + form + ", got " + shown(v[i]));
    const int a = electrode_index(v[i][0], electrode_count, at);
    const int b = electrode_index(v[i][1], electrode_count, at);
    if (a == b) ObjectReader::fail(at, "names electrode " + std::to_string(a) + " twice");
    pairs.push_back({a, b});
  }
  return pairs;
}

/// "excitation": a current-injection protocol (sensor/excitation.hpp). The frame's values are the
/// readings in order: drive by drive, each drive's pairs as "measure" lists them (less those that
/// touch the drive, if "skip_driving_electrodes"), or exactly "readings" ([drive, +, −] each).
Excitation parse_excitation(const json& j, int electrode_count, double sheet_resistance_ohm_per_sq) {
  ObjectReader r(j, "excitation");
  Excitation e;
  e.current_A = r.number_or("current_A", e.current_A, Sign::positive);
  e.frequency_Hz = r.number_or("frequency_Hz", e.frequency_Hz, Sign::non_negative);
  if (electrode_count < 3) ObjectReader::fail("excitation", "a current-injection skin needs at least 3 electrodes");
  const json& drive = r.value("drive");
  if (drive.is_string()) {
    try {
      e.drives = drive_pattern(drive.get<std::string>(), electrode_count);
    } catch (const InvalidInput& error) {
      ObjectReader::fail("excitation.drive", error.what());
    }
  } else {
    for (const auto& [source, sink] : electrode_pairs(drive, electrode_count, "excitation.drive", "[source, sink]"))
      e.drives.push_back({source, sink});
  }
  const int drives = static_cast<int>(e.drives.size());
  if (r.has("readings")) {
    if (r.has("measure") || r.has("skip_driving_electrodes"))
      ObjectReader::fail("excitation.readings", "lists every reading: give it or \"measure\", not both");
    const json& v = r.value("readings");
    if (!v.is_array() || v.empty()) ObjectReader::fail("excitation.readings", "must be a list of [drive, +, -]");
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string at = "excitation.readings[" + std::to_string(i) + "]";
      if (!v[i].is_array() || v[i].size() != 3) ObjectReader::fail(at, "must be [drive, +, -], got " + shown(v[i]));
      if (!v[i][0].is_number_integer() || v[i][0].get<long long>() < 0 || v[i][0].get<long long>() >= drives)
        ObjectReader::fail(at, "its drive must be 0 to " + std::to_string(drives - 1) + ", got " + shown(v[i][0]));
      const int plus = electrode_index(v[i][1], electrode_count, at),
                minus = electrode_index(v[i][2], electrode_count, at);
      if (plus == minus) ObjectReader::fail(at, "reads electrode " + std::to_string(plus) + " against itself");
      e.readings.push_back({static_cast<int>(v[i][0].get<long long>()), plus, minus});
    }
  } else {
    bool skip = false;
    if (r.has("skip_driving_electrodes")) {
      const json& v = r.value("skip_driving_electrodes");
      if (!v.is_boolean())
        ObjectReader::fail("excitation.skip_driving_electrodes", "must be true or false, got " + shown(v));
      skip = v.get<bool>();
    }
    const json& measure = r.has("measure") ? r.value("measure") : json("adjacent");
    if (measure.is_string()) {
      if (measure.get<std::string>() != "adjacent")
        ObjectReader::fail("excitation.measure",
                           "must be \"adjacent\" or a list of [+, -] pairs, got " + shown(measure));
      e.readings = adjacent_readings(e.drives, electrode_count, skip);
    } else {
      const auto pairs = electrode_pairs(measure, electrode_count, "excitation.measure", "[+, -]");
      for (int d = 0; d < drives; ++d)
        for (const auto& [plus, minus] : pairs) {
          const EitDrive& drive_d = e.drives[static_cast<std::size_t>(d)];
          const auto driving = [&](int k) { return k == drive_d.source || k == drive_d.sink; };
          if (!skip || !(driving(plus) || driving(minus))) e.readings.push_back({d, plus, minus});
        }
    }
    if (e.readings.empty()) ObjectReader::fail("excitation.measure", "leaves no reading");
  }
  if (r.has("contact_impedance_ohm_mm")) {
    const json& v = r.value("contact_impedance_ohm_mm");
    const auto ohm_mm = [&](const json& x) {
      if (!x.is_number() || !std::isfinite(x.get<double>()) || x.get<double>() < 0)
        ObjectReader::fail("excitation.contact_impedance_ohm_mm",
                           "must be a number of ohm mm, not negative, or a list of one per electrode; got " + shown(x));
      const double z = x.get<double>();
      // z / R□ is the stretch of sheet whose resistance equals the contact's (sensor/excitation.hpp).
      const double low = Excitation::min_contact_length_mm * sheet_resistance_ohm_per_sq,
                   high = Excitation::max_contact_length_mm * sheet_resistance_ohm_per_sq;
      if (z != 0 && !(z >= low * (1 - 1e-12) && z <= high * (1 + 1e-12)))  // the ends as written are in
        ObjectReader::fail("excitation.contact_impedance_ohm_mm",
                           "must be 0 (the shunt model) or from " + number_text(low) + " to " + number_text(high) +
                               " (" + number_text(Excitation::min_contact_length_mm) + " to " +
                               number_text(Excitation::max_contact_length_mm) + " mm of the sheet's " +
                               number_text(sheet_resistance_ohm_per_sq) +
                               " ohm/sq: less is a perfect contact, give 0; more cuts the electrode off), got " +
                               number_text(z));
      return z;
    };
    if (v.is_array()) {
      for (const json& x : v) e.contact_impedance_ohm_mm.push_back(ohm_mm(x));
      if (static_cast<int>(e.contact_impedance_ohm_mm.size()) != electrode_count)
        ObjectReader::fail("excitation.contact_impedance_ohm_mm",
                           std::to_string(v.size()) + " values for " + std::to_string(electrode_count) + " electrodes");
    } else {
      e.contact_impedance_ohm_mm.assign(static_cast<std::size_t>(electrode_count), ohm_mm(v));
    }
  }
  r.finish();
  return e;
}

}  // namespace

namespace {

std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace

bool is_cad_file(const std::string& path) {
  const std::string extension = lower_extension(path);
  return extension == ".step" || extension == ".stp" || extension == ".iges" || extension == ".igs";
}

bool is_step_file(const std::string& path) {
  const std::string extension = lower_extension(path);
  return extension == ".step" || extension == ".stp";
}

bool is_stl_file(const std::string& path) { return lower_extension(path) == ".stl"; }

bool is_msh_file(const std::string& path) { return lower_extension(path) == ".msh"; }

namespace {

/// A CAD or STL sheet's electrodes, in order: [{"at_mm": [x, y, z]}, ...] (CAD: each names the
/// border curve of the file's surface nearest that point), or with "width_mm" (STL: the border's
/// stretch of that length centred on its point nearest; mesh/generate_mesh.hpp).
void parse_file_electrodes(const json& v, bool with_width, Shape& shape) {
  const std::string form = with_width ? "{\"at_mm\": [x, y, z], \"width_mm\": w}" : "{\"at_mm\": [x, y, z]}";
  if (!v.is_array() || v.size() < 2)
    ObjectReader::fail("electrodes", "must be a list of at least 2 " + form + ", got " + shown(v));
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string where = "electrodes[" + std::to_string(i) + "]";
    ObjectReader r(v[i], where);
    const json& p = r.value("at_mm");
    if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
      ObjectReader::fail(where + ".at_mm", "must be a point [x, y, z] in mm, got " + shown(p));
    shape.electrode_at_mm.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    if (!shape.electrode_at_mm.back().allFinite()) ObjectReader::fail(where + ".at_mm", "must be finite");
    if (with_width) shape.electrode_width_mm.push_back(r.number("width_mm", Sign::positive));
    r.finish();
  }
}

void parse_sections(const json& j, Sensor& sensor, const std::string& base_dir) {
  ObjectReader r(j, "");
  if (r.has("name")) sensor.name = r.string("name");
  sensor.shape = parse_shape(r.value("shape"), base_dir);
  if (sensor.shape.kind != ShapeKind::mesh_file) {
    sensor.border = border_of(sensor.shape);
    sensor.electrodes = parse_electrodes(r.value("electrodes"), sensor.shape, *sensor.border);
  } else if (r.has("electrodes")) {
    const bool stl = is_stl_file(sensor.shape.mesh_path);
    if (!stl && !is_cad_file(sensor.shape.mesh_path))
      ObjectReader::fail("electrodes",
                         "a .msh sensor takes its electrodes from the file's "
                         "\"electrode <i>\" curves; remove this key");
    parse_file_electrodes(r.value("electrodes"), stl, sensor.shape);
  } else if (is_cad_file(sensor.shape.mesh_path)) {
    ObjectReader::fail("electrodes",
                       "missing: a CAD sheet names each electrode's border curve, [{\"at_mm\": [x, y, z]}, ...]");
  } else if (is_stl_file(sensor.shape.mesh_path)) {
    ObjectReader::fail("electrodes",
                       "missing: an STL sheet places each electrode on its border, [{\"at_mm\": [x, y, z], "
                       "\"width_mm\": w}, ...]");
  }
  sensor.drive_voltage_V = r.number_or("drive_voltage_V", sensor.drive_voltage_V, Sign::positive);
  sensor.sheet_resistance_ohm_per_sq =
      r.number_or("probing_sheet_resistance_ohm_per_sq", sensor.sheet_resistance_ohm_per_sq, Sign::positive);
  if (r.has("series_resistance_ohm")) sensor.series_resistance_ohm = parse_series_resistance(r, sensor);
  if (r.has("contact_law")) {
    ObjectReader c(r.value("contact_law"), "contact_law");
    sensor.contact.alpha_ohm_mm2 = c.number_or("alpha_ohm_mm2", sensor.contact.alpha_ohm_mm2, Sign::positive);
    sensor.contact.gamma = c.number_or("gamma", sensor.contact.gamma, Sign::any);
    sensor.contact.min_pressure_N_per_mm2 =
        c.number_or("min_pressure_N_per_mm2", sensor.contact.min_pressure_N_per_mm2, Sign::non_negative);
    c.finish();
    if (sensor.contact.gamma >= 0)
      ObjectReader::fail("contact_law.gamma", "must be negative (resistance falls as pressure rises), got " +
                                                  std::to_string(sensor.contact.gamma));
  }
  if (r.has("adc")) {
    ObjectReader a(r.value("adc"), "adc");
    sensor.adc.bits = a.integer_or("bits", sensor.adc.bits, 1, 24);
    sensor.adc.vref_V = a.number_or("vref_V", sensor.adc.vref_V, Sign::positive);
    sensor.adc.noise_V = a.number_or("noise_V", sensor.adc.noise_V, Sign::non_negative);
    a.finish();
  }
  if (r.has("excitation")) {
    const Shape& shape = sensor.shape;
    const bool file_electrodes = shape.kind == ShapeKind::mesh_file;
    if (file_electrodes && shape.electrode_at_mm.empty())
      ObjectReader::fail("excitation",
                         "a .msh sensor's electrodes are counted only when its file is read; "
                         "give the sheet as CAD or STL with its electrodes listed");
    const int count = file_electrodes ? static_cast<int>(shape.electrode_at_mm.size()) : sensor.electrode_count();
    sensor.excitation = parse_excitation(r.value("excitation"), count, sensor.sheet_resistance_ohm_per_sq);
  }
  if (r.has("mesh")) {
    ObjectReader m(r.value("mesh"), "mesh");
    sensor.mesh.element_size_mm = m.number_or("element_size_mm", sensor.mesh.element_size_mm, Sign::positive);
    sensor.mesh.twin_refinement = m.number_or("twin_refinement", sensor.mesh.twin_refinement, Sign::positive);
    sensor.mesh.max_triangles = m.number_or("max_triangles", sensor.mesh.max_triangles, Sign::positive);
    m.finish();
    if (sensor.mesh.twin_refinement < 1)
      ObjectReader::fail("mesh.twin_refinement", "must be at least 1 (the twin's mesh is never coarser)");
  }
  r.finish();
  if (sensor.border && sensor.mesh.element_size_mm > 0.25 * sensor.border->size_mm())
    ObjectReader::fail("mesh.element_size_mm", "is larger than a quarter of the sheet");
}

}  // namespace

double ContactLaw::conductance_S_per_mm2(double pressure_N_per_mm2) const {
  if (!(pressure_N_per_mm2 >= min_pressure_N_per_mm2) || pressure_N_per_mm2 <= 0) return 0.0;
  return 1.0 / (alpha_ohm_mm2 * std::pow(pressure_N_per_mm2, gamma));
}

double ContactLaw::pressure_N_per_mm2(double conductance_S_per_mm2) const {
  if (!(conductance_S_per_mm2 > 0)) return 0.0;
  return std::pow(alpha_ohm_mm2 * conductance_S_per_mm2, -1.0 / gamma);  // g = 1/(α P^γ)
}

Sensor parse_sensor(const json& j, const std::string& where, const std::string& base_dir) {
  Sensor sensor;
  try {
    parse_sections(j, sensor, base_dir);
  } catch (const InvalidInput& e) {
    throw InvalidInput(where + ": " + e.what());
  }
  return sensor;
}

Sensor load_sensor(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open sensor file (" + std::strerror(errno) + ")");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    throw InvalidInput(path + ": not valid JSON (" + e.what() + ")");
  } catch (const json::out_of_range& e) {  // a number beyond a double's range: 1e999
    throw InvalidInput(path + ": a number out of range (" + e.what() + ")");
  }
  const auto parent = std::filesystem::path(path).parent_path();
  Sensor sensor = parse_sensor(j, path, parent.empty() ? "." : parent.string());
  if (sensor.name.empty()) sensor.name = std::filesystem::path(path).stem().string();
  return sensor;
}

Sensor default_sensor() {
  const json j = {{"name", "default 60 mm"},
                  {"shape", {{"type", "rectangle"}, {"width_mm", 60.0}, {"height_mm", 60.0}}},
                  {"electrodes", {{"count", 16}, {"width_mm", 3.0}}}};
  return parse_sensor(j, "built-in default sensor");
}

json sensor_to_json(const Sensor& sensor) {
  json j;
  if (!sensor.name.empty()) j["name"] = sensor.name;
  const Shape& s = sensor.shape;
  switch (s.kind) {
    case ShapeKind::rectangle:
      j["shape"] = {{"type", "rectangle"}, {"width_mm", s.width_mm}, {"height_mm", s.height_mm}};
      break;
    case ShapeKind::circle:
      j["shape"] = {{"type", "circle"}, {"radius_mm", s.radius_mm}, {"center_mm", {s.center_mm.x(), s.center_mm.y()}}};
      break;
    case ShapeKind::polygon: {
      json points = json::array();
      for (const auto& p : s.points_mm) points.push_back({p.x(), p.y()});
      j["shape"] = {{"type", "polygon"}, {"points_mm", points}};
      break;
    }
    case ShapeKind::mesh_file: {
      j["shape"] = {{"type", "mesh"}, {"file", s.mesh_path}};
      json electrodes = json::array();
      for (std::size_t e = 0; e < s.electrode_at_mm.size(); ++e) {
        const Vector3& p = s.electrode_at_mm[e];
        electrodes.push_back({{"at_mm", {p.x(), p.y(), p.z()}}});
        if (e < s.electrode_width_mm.size()) electrodes.back()["width_mm"] = s.electrode_width_mm[e];
      }
      if (!s.electrode_at_mm.empty()) j["electrodes"] = electrodes;
      break;
    }
    case ShapeKind::spherical_cap:
      j["shape"] = {{"type", "spherical_cap"},
                    {"sphere_radius_mm", s.sphere_radius_mm},
                    {"base_radius_mm", s.radius_mm}};
      break;
    case ShapeKind::cylinder:
      j["shape"] = {{"type", "cylinder"},
                    {"radius_mm", s.radius_mm},
                    {"length_mm", s.length_mm},
                    {"angle_deg", s.angle_deg}};
      break;
  }
  if (s.kind == ShapeKind::cylinder) {
    // A chart point is not a point in space: each electrode by its place along the axis and its angle.
    json electrodes = json::array();
    for (const auto& e : sensor.electrodes)
      electrodes.push_back({{"x_mm", e.center_mm.x() - s.length_mm / 2},
                            {"angle_deg", e.center_mm.y() / s.radius_mm * 180 / std::numbers::pi - s.angle_deg / 2},
                            {"width_mm", e.width_mm}});
    j["electrodes"] = electrodes;
  } else if (s.kind != ShapeKind::mesh_file) {
    json electrodes = json::array();
    for (const auto& e : sensor.electrodes)
      electrodes.push_back({{"x_mm", e.center_mm.x()}, {"y_mm", e.center_mm.y()}, {"width_mm", e.width_mm}});
    j["electrodes"] = electrodes;
  }
  j["drive_voltage_V"] = sensor.drive_voltage_V;
  j["probing_sheet_resistance_ohm_per_sq"] = sensor.sheet_resistance_ohm_per_sq;
  if (!sensor.series_resistance_ohm.empty()) j["series_resistance_ohm"] = sensor.series_resistance_ohm;
  j["contact_law"] = {{"alpha_ohm_mm2", sensor.contact.alpha_ohm_mm2},
                      {"gamma", sensor.contact.gamma},
                      {"min_pressure_N_per_mm2", sensor.contact.min_pressure_N_per_mm2}};
  if (const auto& e = sensor.excitation) {
    json readings = json::array(), drives = json::array();
    for (const EitDrive& d : e->drives) drives.push_back({d.source, d.sink});
    for (const EitReading& m : e->readings) readings.push_back({m.drive, m.plus, m.minus});
    j["excitation"] = {{"current_A", e->current_A},
                       {"frequency_Hz", e->frequency_Hz},
                       {"drive", drives},
                       {"readings", readings}};
    if (!e->contact_impedance_ohm_mm.empty()) j["excitation"]["contact_impedance_ohm_mm"] = e->contact_impedance_ohm_mm;
  }
  j["adc"] = {{"bits", sensor.adc.bits}, {"vref_V", sensor.adc.vref_V}, {"noise_V", sensor.adc.noise_V}};
  j["mesh"] = {{"element_size_mm", sensor.mesh.element_size_mm},
               {"twin_refinement", sensor.mesh.twin_refinement},
               {"max_triangles", sensor.mesh.max_triangles}};
  return j;
}

}  // namespace emit
