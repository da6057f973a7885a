#pragma once
/// \file sensor.hpp
/// The sensor description (README, "Sensor description"): the probing sheet's shape, its electrodes, the drive,
/// the materials, the ADC and the mesh size. Built from JSON by `load_sensor` (sensor_json.hpp),
/// validated there; every field here is in the units its name says.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/sensor/border.hpp"
#include "emit/sensor/excitation.hpp"
#include "emit/sensor/height_field.hpp"

namespace emit {

enum class ShapeKind { rectangle, circle, polygon, mesh_file, spherical_cap, cylinder };

struct Shape {
  ShapeKind kind = ShapeKind::rectangle;
  double width_mm = 0, height_mm = 0;  ///< rectangle
  double radius_mm = 0;                ///< circle; spherical_cap: the rim's (base) radius; cylinder: its radius
  Vector2 center_mm{0, 0};             ///< circle; spherical_cap: the origin
  /// spherical_cap: a cap of this sphere, apex up (+z), its rim the circle of radius_mm in the
  /// plane z = 0 about the z axis (README "Sensor description"; sensor/surface.hpp).
  double sphere_radius_mm = 0;
  /// cylinder: a patch of the side of the cylinder of radius radius_mm about the x axis, this
  /// long along it (x from −length/2 to length/2) and spanning this angle about it, centred on
  /// +z; 360° is a sleeve (README "Sensor description"; sensor/surface.hpp).
  double length_mm = 0, angle_deg = 0;
  std::vector<Vector2> points_mm;  ///< polygon, as given
  std::string mesh_path;           ///< mesh_file: a Gmsh .msh with "electrode <i>" curves, or CAD (STEP/IGES)
  /// mesh_file from CAD (is_cad_file): electrode i is the border curve of the file's surface
  /// nearest this point; from STL (is_stl_file): the border's stretch electrode_width_mm[i] long
  /// centred on its point nearest this one (mesh/generate_mesh.hpp).
  std::vector<Vector3> electrode_at_mm;
  std::vector<double> electrode_width_mm;  ///< STL only
  /// mesh_file: the file's surface, once read (mesh/sheet_file.hpp): its chart is (x, y).
  std::shared_ptr<const HeightField> surface;
};

/// Whether a mesh file is CAD (STEP or IGES, by its extension, any case), which Gmsh's
/// OpenCASCADE kernel reads and emit meshes, rather than a Gmsh mesh.
bool is_cad_file(const std::string& path);
/// Whether a CAD file is STEP (.step, .stp, any case), rather than IGES.
bool is_step_file(const std::string& path);
/// Whether a mesh file is an STL surface (by its extension, any case): its triangles are the mesh.
bool is_stl_file(const std::string& path);
/// Whether a mesh file is a Gmsh mesh (.msh, any case): its triangles and "electrode <i>" curves
/// are the mesh. A sheet's file is one of the three kinds (sensor_json.hpp refuses any other).
bool is_msh_file(const std::string& path);

/// One electrode: an arc-length interval of the border, [start_s_mm, start_s_mm + width_mm]
/// (wrapping past the end of the border if need be).
struct Electrode {
  Vector2 center_mm{0, 0};
  double width_mm = 0;
  double center_s_mm = 0;  ///< arc length of the centre along the border
};

/// Contact resistance per unit area r_c = alpha · P^gamma [Ω·mm²], P in N/mm² (paper eq. 2);
/// no contact below the separator's minimum pressure.
struct ContactLaw {
  double alpha_ohm_mm2 = 2.0e5;
  double gamma = -1.2;
  double min_pressure_N_per_mm2 = 0.002;
  /// g = 1/r_c [S/mm²]; 0 below the minimum pressure.
  double conductance_S_per_mm2(double pressure_N_per_mm2) const;
  /// The inverse (paper eq. 2 solved for P); 0 for g ≤ 0.
  double pressure_N_per_mm2(double conductance_S_per_mm2) const;
};

/// The acquisition's ADC (paper §3.1: the ESP32's 12-bit ADC at 3.3 V).
struct AdcSpec {
  int bits = 12;
  double vref_V = 3.3;
  double noise_V = 0.001;  ///< standard deviation of Gaussian noise added before quantisation
};

struct MeshSpec {
  /// Target edge length of the reconstruction mesh. 1.2 mm gives the paper's ~6000 triangles on
  /// the 60 mm sheet (paper §3.1).
  double element_size_mm = 1.2;
  /// The twin's mesh is this many times finer in edge length (2 → about 4× the triangles).
  double twin_refinement = 2.0;
  /// Meshing refuses a sheet that would have more triangles than this (an estimate made before
  /// meshing: a typo in a size must not eat the machine's memory). 1 M triangles take ~1 GB to
  /// mesh; the reconstruction's operators grow with them too.
  double max_triangles = 1e6;
};

struct Sensor {
  std::string name;
  Shape shape;
  /// For shape mesh_file the border is not analytic; border is empty and electrodes come from
  /// the mesh file's groups.
  std::optional<Border> border;
  std::vector<Electrode> electrodes;
  double drive_voltage_V = 3.3;
  double sheet_resistance_ohm_per_sq = 5000.0;
  /// Each electrode's series resistance [Ω]: its contact with the sheet plus the multiplexer's
  /// switch. A grounded electrode reaches ground through it (frame_predictor.hpp); a sensing one
  /// draws no current. Empty: none (ideal grounds). `emit calibrate` fits it from presses.
  std::vector<double> series_resistance_ohm;
  ContactLaw contact;
  AdcSpec adc;
  /// A current-injection skin: its drives and readings, the frame's order. Empty: the
  /// EMIT protocol (ground each electrode in turn, read the others).
  std::optional<Excitation> excitation;
  MeshSpec mesh;

  int electrode_count() const { return static_cast<int>(electrodes.size()); }
};

/// For the commands that model an EMIT sheet (simulate, reconstruct, calibrate, live, bench):
/// \throw InvalidInput "<where>: is a current-injection skin (its \"excitation\") …" when the
/// sensor has an excitation, pointing to `emit eval --real`.
void require_emit_protocol(const Sensor& sensor, const std::string& where);

}  // namespace emit
