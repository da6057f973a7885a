#pragma once
/// \file twin.hpp
/// The digital twin: presses → contact conductance (resolved inside elements) → one solve per
/// grounding → frame → ADC. It meshes the sheet finer than the reconstruction does (docs/physics.md, "The digital
/// twin": no inverse crime) and grades the mesh into the electrodes' ends.
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <vector>

#include "emit/fem/forward_model.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/press.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct TwinOptions {
  int mesh_seed = 1;                ///< another seed, another (equally fine) mesh
  std::optional<MeshOptions> mesh;  ///< overrides twin_mesh_options(sensor, mesh_seed)
  bool adc = true;                  ///< quantise, add noise and clip as the sensor's ADC does
  std::uint64_t noise_seed = 1;     ///< seed of the ADC's Gaussian noise
  int quadrature_levels = 6;        ///< subdivision depth on triangles a disc's edge cuts
  int dead_electrode = -1;          ///< simulate this electrode disconnected (electrode_health.hpp)
  /// A sheet that is not uniform: the sheet resistance varies linearly along x by ± this
  /// fraction across the sheet (0.2: from 0.8·Rs at the left to 1.2·Rs at the right).
  double sheet_resistance_variation = 0;
  /// Any sheet-resistance field: Rs at p is multiplied by this factor (> 0), taken at each
  /// triangle's centroid, on top of the linear variation (sheet_field.hpp draws a smooth random
  /// one). Empty: 1 everywhere.
  std::function<double(const Vector2&)> sheet_resistance_factor;
  /// Each electrode's series resistance to ground when grounded (its contact and the
  /// multiplexer's switch) [Ω], one per electrode (forward_model.hpp); empty: the sensor's own
  /// (Sensor::series_resistance_ohm, none if it has none).
  std::vector<double> series_resistance_ohm;
  /// The elastomer cover spreads each press's pressure by a Gaussian of this standard deviation
  /// [mm] (press_pressure.hpp); 0: none, the indenter's own profile.
  double cover_blur_mm = 0;
  /// A driving layer with this sheet resistance, fed along a bus bar at the bottom of the sheet
  /// (driving_layer.hpp); 0: an equipotential driving layer, as the reconstruction assumes.
  double driving_sheet_resistance_ohm_per_sq = 0;
  /// Frames by condensing each press onto a skeleton of the twin's mesh (fem/forward_model.hpp,
  /// condense_contacts) instead of factorising it: the same frames to rounding (1e-9 of the largest
  /// potential, tests/twin/twin_test.cpp), several times faster a frame, for a second or so of
  /// setup and tens of MB. The live simulator's (sim_source.hpp). Not with a resistive driving layer.
  bool condensed_frames = false;
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

class Twin {
 public:
  /// Meshes the sheet and assembles the forward model. \throw InvalidInput.
  explicit Twin(Sensor sensor, const TwinOptions& options = {});

  const Sensor& sensor() const { return sensor_; }
  const Mesh& mesh() const { return model_.mesh(); }

  /// The noise-free frame of the physics, before the ADC. \throw InvalidInput for a bad press.
  Frame exact_frame(const std::vector<Press>& presses);
  /// The frame as the board reads it (ADC applied if enabled). Each call draws fresh noise.
  /// `codes`, if given, gets the ADC's codes of it (N·N, ground-major; with the ADC off, those of
  /// the exact volts).
  Frame frame(const std::vector<Press>& presses, std::vector<std::uint16_t>* codes = nullptr);
  /// Node potentials, #V by N (column l: electrode l grounded), for pictures.
  Matrix potentials(const std::vector<Press>& presses);
  /// The presses as every frame applies them: each validated (validate_press; a mesh file's
  /// sheet asks its mesh) and centred on the surface at the point its chart point names.
  /// \throw InvalidInput "press i: …" as frame() does for a bad press.
  std::vector<Press> placed(const std::vector<Press>& presses) const;

 private:
  ContactLoad contact_of(const std::vector<Press>& presses) const;
  Sensor sensor_;
  TwinOptions options_;
  ForwardModel model_;
  std::mt19937_64 rng_;
};

}  // namespace emit
