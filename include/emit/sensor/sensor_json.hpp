#pragma once
/// \file sensor_json.hpp
/// Reading a sensor description from JSON (README, "Sensor description"), with validation that names the offending key.
///
/// Keys (all others are errors; a test holds this list to the parser):
///   name                                  optional string
///   shape        {type: rectangle, width_mm, height_mm}
///              | {type: circle, radius_mm, center_mm: [x, y] (default [r, r])}
///              | {type: polygon, points_mm: [[x, y], ...]}
///              | {type: spherical_cap, sphere_radius_mm, base_radius_mm}   a dome (sensor/surface.hpp)
///              | {type: cylinder, radius_mm, length_mm, angle_deg}        a patch, or a sleeve at 360
///              | {type: mesh, file: "sheet.msh" | .stl | .step | .iges}    (path relative to the sensor file)
///   electrodes   {count, width_mm}  laid out by the default rule (electrode_layout.hpp)
///              | [{x_mm, y_mm, width_mm}, ...]  centres on the border, in electrode order
///              | [{angle_deg, width_mm}, ...]   on a circle's or a cap's rim
///              | [{x_mm, angle_deg, width_mm}, ...]  on a cylinder: along its axis and around it
///              | [{at_mm: [x, y, z]}, ...]  a CAD sheet's border curves; an STL's with width_mm
///   drive_voltage_V, probing_sheet_resistance_ohm_per_sq
///   series_resistance_ohm                 one for every electrode, or a list of one per electrode [Ω]
///   contact_law  {alpha_ohm_mm2, gamma, min_pressure_N_per_mm2}
///   adc          {bits, vref_V, noise_V}
///   excitation   {current_A, frequency_Hz, drive: "adjacent" | "opposite" | "skip-s" | [[source, sink], ...],
///                 measure: "adjacent" | [[+, -], ...], skip_driving_electrodes, contact_impedance_ohm_mm}
///              | {..., drive, readings: [[drive, +, -], ...]}  a current-injection skin (sensor/excitation.hpp)
///   mesh         {element_size_mm, twin_refinement, max_triangles}
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "emit/sensor/sensor.hpp"

namespace emit {

/// Parse and validate. `base_dir` resolves a relative mesh file path.
/// \throw InvalidInput with a message of the form "<where>: <key>: <what is wrong>".
Sensor parse_sensor(const nlohmann::json& j, const std::string& where = "sensor", const std::string& base_dir = ".");

/// Read a sensor file. \throw IoError if unreadable, InvalidInput if malformed or invalid.
Sensor load_sensor(const std::string& path);

/// The built-in default sensor: the paper's 60 × 60 mm sheet with 16 electrodes 3 mm wide.
Sensor default_sensor();

/// The sensor back as JSON (explicit electrode list), e.g. to record what a run used.
nlohmann::json sensor_to_json(const Sensor& sensor);

}  // namespace emit
