#include "emit/twin/twin.hpp"

#include <cmath>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/sensor/adc.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/adc_noise.hpp"
#include "emit/twin/press_contact.hpp"

namespace emit {

namespace {

/// Sheet conductance per triangle: uniform, or varying linearly along x by ± `variation`, times
/// the options' resistance factor at the centroid if there is one.
Vector sheet_conductance_S(const Mesh& mesh, double sheet_resistance_ohm_per_sq, const TwinOptions& options) {
  const double variation = options.sheet_resistance_variation;
  const double x_min = mesh.nodes_mm.col(0).minCoeff(), x_max = mesh.nodes_mm.col(0).maxCoeff();
  Vector conductance(mesh.triangle_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const Vector3 centroid = mesh.triangle_centroid_mm(t);
    const double across = (centroid.x() - x_min) / (x_max - x_min);  // 0 … 1
    conductance[t] = 1.0 / (sheet_resistance_ohm_per_sq * (1.0 + variation * (2.0 * across - 1.0)));
    if (options.sheet_resistance_factor) {
      const double factor = options.sheet_resistance_factor(centroid.head<2>());
      if (!(factor > 0) || !std::isfinite(factor))
        throw InvalidInput("sheet resistance factor must be positive and finite");
      conductance[t] /= factor;
    }
  }
  return conductance;
}

ForwardModel twin_model(const Sensor& sensor, const TwinOptions& options) {
  options.validate();  // before meshing
  require_emit_protocol(sensor, "sensor \"" + sensor.name + "\"");
  Mesh mesh = generate_mesh(sensor, options.mesh ? *options.mesh : twin_mesh_options(sensor, options.mesh_seed));
  const Vector conductance = sheet_conductance_S(mesh, sensor.sheet_resistance_ohm_per_sq, options);
  std::optional<DrivingLayer> driving;
  if (options.driving_sheet_resistance_ohm_per_sq != 0)
    driving = bottom_fed_driving_layer(mesh, options.driving_sheet_resistance_ohm_per_sq);
  ForwardModel model(std::move(mesh), conductance, driving);
  // The twin's own departure, else what the sensor description says (sensor.hpp).
  model.set_series_resistance(options.series_resistance_ohm.empty() ? sensor.series_resistance_ohm
                                                                    : options.series_resistance_ohm);
  if (options.condensed_frames) model.condense_contacts();
  return model;
}

}  // namespace

Twin::Twin(Sensor sensor, const TwinOptions& options)
    : sensor_(std::move(sensor)), options_(options), model_(twin_model(sensor_, options)), rng_(options.noise_seed) {}

ContactLoad Twin::contact_of(const std::vector<Press>& presses) const {
  return press_contact_load(mesh(), placed(presses), sensor_.contact, options_.quadrature_levels,
                            options_.cover_blur_mm);
}

std::vector<Press> Twin::placed(const std::vector<Press>& presses) const {
  std::vector<Press> on_sheet = presses;
  for (std::size_t i = 0; i < presses.size(); ++i) {
    const std::string where = "press " + std::to_string(i);
    validate_press(sensor_, presses[i], where);
    // A mesh-file sheet has no analytic border: ask the mesh.
    const Vector2 chart = press_chart_mm(sensor_.shape, presses[i]);
    if (!sensor_.border && !mesh().contains_xy(chart)) throw InvalidInput(where + ": centre is off the sheet");
    // On a curved sheet the press is centred on the surface, at the point its chart point names.
    const Vector3 point = surface_point_mm(sensor_.shape, chart);
    on_sheet[i].x_mm = point.x(), on_sheet[i].y_mm = point.y(), on_sheet[i].z_mm = point.z();
  }
  return on_sheet;
}

Frame Twin::exact_frame(const std::vector<Press>& presses) {
  return model_.solve_frame(contact_of(presses), sensor_.drive_voltage_V);
}

Frame Twin::frame(const std::vector<Press>& presses, std::vector<std::uint16_t>* codes) {
  Frame f = exact_frame(presses);
  if (const int e = options_.dead_electrode; e >= 0 && e < f.rows()) {
    // Disconnected: as the sensed electrode its input is pulled to 0 V; as the ground it grounds
    // nothing, so a pressed sheet floats up to the drive (an unpressed one stays at 0 V).
    const bool pressed = f.maxCoeff() > 0;
    f.col(e).setZero();
    f.row(e).setConstant(pressed ? sensor_.drive_voltage_V : 0.0);
  }
  if (codes) codes->resize(static_cast<std::size_t>(f.size()));
  if (options_.adc) apply_adc(sensor_.adc, f, rng_, codes ? codes->data() : nullptr);
  else if (codes)
    for (Index i = 0; i < f.size(); ++i) (*codes)[static_cast<std::size_t>(i)] = adc_code(sensor_.adc, f.data()[i]);
  return f;
}

Matrix Twin::potentials(const std::vector<Press>& presses) {
  return model_.solve_potentials(contact_of(presses), sensor_.drive_voltage_V);
}

void TwinOptions::validate() const {
  if (mesh) mesh->validate();
  option_check::within("TwinOptions", "quadrature_levels", quadrature_levels, 0, 10);
  option_check::at_least("TwinOptions", "dead_electrode", dead_electrode, -1);
  if (!(std::abs(sheet_resistance_variation) < 1))
    option_check::fail("TwinOptions", "sheet_resistance_variation", "a fraction in (-1, 1)",
                       std::to_string(sheet_resistance_variation));
  for (const double ohm : series_resistance_ohm)
    option_check::non_negative("TwinOptions", "series_resistance_ohm", ohm);
  option_check::non_negative("TwinOptions", "cover_blur_mm", cover_blur_mm);
  option_check::non_negative("TwinOptions", "driving_sheet_resistance_ohm_per_sq", driving_sheet_resistance_ohm_per_sq);
  if (condensed_frames && driving_sheet_resistance_ohm_per_sq != 0)
    option_check::fail("TwinOptions", "condensed_frames", "off with a resistive driving layer", "on");
}
}  // namespace emit
