#include "emit/io/calibration_json.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/core/output_file.hpp"

namespace emit {

namespace {

/// n finite numbers, or an error naming the key.
std::vector<double> numbers(const std::string& where, const nlohmann::json& value, std::size_t n) {
  if (!value.is_array() || value.size() != n)
    throw InvalidInput(where + ": must be an array of " + std::to_string(n) + " numbers");
  std::vector<double> out;
  for (const auto& v : value) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) throw InvalidInput(where + ": must hold finite numbers");
    out.push_back(v.get<double>());
  }
  return out;
}

/// {"box_mm": [x0, y0, x1, y1], "log_conductance": [θ1 … θ5] or [θ1 … θ9]}
SheetCorrection sheet_correction_from_json(const std::string& path, const nlohmann::json& j) {
  const std::string where = path + ": sheet_correction";
  if (!j.is_object()) throw InvalidInput(where + ": must be an object {\"box_mm\", \"log_conductance\"}");
  for (const auto& item : j.items())
    if (item.key() != "box_mm" && item.key() != "log_conductance")
      throw InvalidInput(where + ": " + item.key() + ": unknown key");
  for (const char* key : {"box_mm", "log_conductance"})
    if (!j.contains(key)) throw InvalidInput(where + ": " + key + ": missing");
  const std::vector<double> box = numbers(where + ".box_mm", j["box_mm"], 4);
  const std::size_t terms =
      j["log_conductance"].is_array() && j["log_conductance"].size() == SheetCorrection::cubic_terms
          ? SheetCorrection::cubic_terms
          : SheetCorrection::quadratic_terms;  // else the error says 5
  const std::vector<double> theta = numbers(where + ".log_conductance", j["log_conductance"], terms);
  if (!(box[2] > box[0] && box[3] > box[1]))
    throw InvalidInput(where + ".box_mm: must be [x0, y0, x1, y1] with x1 > x0, y1 > y0");
  SheetCorrection c;
  c.lower_mm = {box[0], box[1]};
  c.upper_mm = {box[2], box[3]};
  c.log_conductance = theta;
  return c;
}

/// {"b1_V_mm2", "b2", "b3", "log_std", "indenter_radius_mm"}, every key required
/// (model/force_law.hpp).
ImageForceLaw force_law_from_json(const std::string& path, const nlohmann::json& j) {
  const std::string where = path + ": force_law";
  if (!j.is_object())
    throw InvalidInput(where +
                       ": must be an object {\"b1_V_mm2\", \"b2\", \"b3\", \"log_std\", "
                       "\"indenter_radius_mm\"}");
  ImageForceLaw law;
  const std::pair<const char*, double*> fields[] = {{"b1_V_mm2", &law.b1_V_mm2},
                                                    {"b2", &law.b2},
                                                    {"b3", &law.b3},
                                                    {"log_std", &law.log_std},
                                                    {"indenter_radius_mm", &law.indenter_radius_mm}};
  for (const auto& item : j.items())
    if (std::none_of(std::begin(fields), std::end(fields), [&](const auto& f) { return item.key() == f.first; }))
      throw InvalidInput(where + ": " + item.key() + ": unknown key");
  for (const auto& [key, value] : fields) {
    if (!j.contains(key)) throw InvalidInput(where + ": " + key + ": missing");
    if (!j[key].is_number() || !std::isfinite(j[key].get<double>()))
      throw InvalidInput(where + ": " + key + ": must be a finite number");
    *value = j[key].get<double>();
  }
  if (!(law.b1_V_mm2 >= 0)) throw InvalidInput(where + ": b1_V_mm2 must not be negative");
  if (!(law.b3 < 0)) throw InvalidInput(where + ": b3 must be negative (the force grows with the image)");
  if (!(law.log_std >= 0)) throw InvalidInput(where + ": log_std must not be negative");
  if (!(law.indenter_radius_mm > 0)) throw InvalidInput(where + ": indenter_radius_mm must be positive");
  return law;
}

}  // namespace

Calibration load_calibration(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open calibration file (" + std::strerror(errno) + ")");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InvalidInput(path + ": not valid JSON (" + e.what() + ")");
  } catch (const nlohmann::json::out_of_range& e) {  // a number beyond a double's range: 1e999
    throw InvalidInput(path + ": a number out of range (" + e.what() + ")");
  }
  if (!j.is_object())
    throw InvalidInput(path + ": must be a JSON object {\"a1\", \"a2\", \"a3\"} or {\"alpha_ohm_mm2\", \"gamma\"}");
  LinearCalibration linear;
  FitCalibration fit;
  const bool law = j.contains("alpha_ohm_mm2") || j.contains("gamma");
  for (const auto& item : j.items()) {
    if (law && item.key() == "sheet_correction") {
      fit.sheet_correction = sheet_correction_from_json(path, item.value());
      continue;
    }
    if (law && item.key() == "electrode_shift_mm") {
      const nlohmann::json& v = item.value();
      fit.electrode_shift_mm = numbers(path + ": electrode_shift_mm", v, v.is_array() ? v.size() : 1);
      continue;
    }
    if (law && item.key() == "series_resistance_ohm") {
      const nlohmann::json& v = item.value();
      fit.series_resistance_ohm = numbers(path + ": series_resistance_ohm", v, v.is_array() ? v.size() : 1);
      for (double r : fit.series_resistance_ohm)
        if (r < 0) throw InvalidInput(path + ": series_resistance_ohm: must not be negative");
      continue;
    }
    if (law && item.key() == "sensor") {
      if (!item.value().is_string()) throw InvalidInput(path + ": sensor: must be the sensor's name, a string");
      fit.sensor_name = item.value().get<std::string>();
      continue;
    }
    if (item.key() == "force_law") {
      if (law) throw InvalidInput(path + ": force_law: unknown key in a contact-fitting calibration");
      linear.force_law = force_law_from_json(path, item.value());
      continue;
    }
    if (law && item.key() == "report") {
      if (!item.value().is_object()) throw InvalidInput(path + ": report: must be an object");
      continue;  // what the calibration found, for people: not read back
    }
    if (!item.value().is_number() || !std::isfinite(item.value().get<double>()))
      throw InvalidInput(path + ": " + item.key() + ": must be a finite number");
    const double v = item.value().get<double>();
    if (!law && item.key() == "a1") linear.a1 = v;
    else if (!law && item.key() == "a2") linear.a2 = v;
    else if (!law && item.key() == "a3") linear.a3 = v;
    else if (law && item.key() == "alpha_ohm_mm2") fit.contact_law.alpha_ohm_mm2 = v;
    else if (law && item.key() == "gamma") fit.contact_law.gamma = v;
    else if (law && item.key() == "indenter_radius_mm" && v > 0) fit.indenter_radius_mm = v;
    else if (law && item.key() == "indenter_radius_mm")
      throw InvalidInput(path + ": indenter_radius_mm must be positive");
    else if (law && item.key() == "drive_voltage_V" && v > 0) fit.drive_voltage_V = v;
    else if (law && item.key() == "drive_voltage_V") throw InvalidInput(path + ": drive_voltage_V must be positive");
    else if (law && item.key() == "electrode_count" && v >= 3 && v == std::floor(v) && v < 1e6)
      fit.electrode_count = static_cast<int>(v);
    else if (law && item.key() == "electrode_count")
      throw InvalidInput(path + ": electrode_count must be a whole number of at least 3");
    else
      throw InvalidInput(path + ": " + item.key() + ": unknown key" + (law ? " in a contact-fitting calibration" : ""));
  }
  for (const char* key :
       law ? std::vector<const char*>{"alpha_ohm_mm2", "gamma"} : std::vector<const char*>{"a1", "a2", "a3"})
    if (!j.contains(key)) throw InvalidInput(path + ": " + key + ": missing");
  if (!law) return linear;
  if (!(fit.contact_law.alpha_ohm_mm2 > 0 && fit.contact_law.gamma < 0))
    throw InvalidInput(path + ": alpha_ohm_mm2 must be positive and gamma negative");
  return fit;
}

namespace {

nlohmann::json to_json(const LinearCalibration& c) {
  nlohmann::json j{{"a1", c.a1}, {"a2", c.a2}, {"a3", c.a3}};
  if (const std::optional<ImageForceLaw>& f = c.force_law)
    j["force_law"] = {{"b1_V_mm2", f->b1_V_mm2},
                      {"b2", f->b2},
                      {"b3", f->b3},
                      {"log_std", f->log_std},
                      {"indenter_radius_mm", f->indenter_radius_mm}};
  return j;
}

nlohmann::json to_json(const FitCalibration& c) {
  nlohmann::json j{{"alpha_ohm_mm2", c.contact_law.alpha_ohm_mm2}, {"gamma", c.contact_law.gamma}};
  if (c.indenter_radius_mm > 0) j["indenter_radius_mm"] = c.indenter_radius_mm;
  if (!c.sensor_name.empty()) j["sensor"] = c.sensor_name;
  if (c.electrode_count > 0) j["electrode_count"] = c.electrode_count;
  if (c.drive_voltage_V > 0) j["drive_voltage_V"] = c.drive_voltage_V;
  if (!c.series_resistance_ohm.empty()) j["series_resistance_ohm"] = c.series_resistance_ohm;
  if (!c.electrode_shift_mm.empty()) j["electrode_shift_mm"] = c.electrode_shift_mm;
  if (c.sheet_correction) {
    const SheetCorrection& s = *c.sheet_correction;
    j["sheet_correction"] = {{"box_mm", {s.lower_mm.x(), s.lower_mm.y(), s.upper_mm.x(), s.upper_mm.y()}},
                             {"log_conductance", s.log_conductance}};
  }
  return j;
}

nlohmann::json to_json(const SensorCalibration& r) {
  nlohmann::json parameters = nlohmann::json::array();
  for (const CalibratedParameter& p : r.parameters)
    parameters.push_back({{"name", p.name},
                          {"value", p.value},
                          {"std", p.std},
                          {"prior_std", p.prior_std},
                          {"determined", p.determined}});
  nlohmann::json placed = nlohmann::json::array();  // the presses whose place was fitted
  for (std::size_t i = 0; i < r.centres_mm.size(); ++i)
    if (r.place_fitted[i])
      placed.push_back({{"press", i}, {"x_mm", r.centres_mm[i].x()}, {"y_mm", r.centres_mm[i].y()}});
  return {{"presses", r.presses},
          {"fitted_places", placed},
          {"rms_misfit_nominal_mV", 1e3 * r.rms_misfit_nominal_V},
          {"rms_misfit_calibrated_mV", 1e3 * r.rms_misfit_corrected_V},
          {"chi2_per_reading", r.chi2_per_reading},
          {"parameters", parameters},
          {"not_determined_by_presses",
           {"the sheet's overall resistance (only series resistance x sheet conductance is seen; the contact law "
            "absorbs the rest)",
            "the contact's radial spread (indenter profile, cover blur): the contact law absorbs it"}},
          {"warnings", r.warnings}};
}

}  // namespace

void write_calibration(const std::string& path, const Calibration& calibration, const SensorCalibration* report) {
  OutputFile file({"", path});
  write_calibration(file.stream(), calibration, report);
  file.commit();
}

void write_calibration(std::ostream& out, const Calibration& calibration, const SensorCalibration* report) {
  nlohmann::json j = std::visit([](const auto& c) { return to_json(c); }, calibration);
  if (report) j["report"] = to_json(*report);
  out << j.dump(2) << '\n';
}

}  // namespace emit
