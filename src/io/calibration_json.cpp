#include "emit/io/calibration_json.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "emit/errors.hpp"
#include "emit/io/atomic_file.hpp"

namespace emit {

PressureCalibration load_calibration(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open calibration file (" + std::strerror(errno) + ")");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InvalidInput(path + ": not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object()) throw InvalidInput(path + ": must be a JSON object {\"a1\", \"a2\", \"a3\"} or {\"alpha_ohm_mm2\", \"gamma\"}");
  PressureCalibration c;
  c.calibrated = true;
  const bool law = j.contains("alpha_ohm_mm2") || j.contains("gamma");
  if (law) c.fitted_contact_law = ContactLaw{};
  for (const auto& item : j.items()) {
    if (!item.value().is_number() || !std::isfinite(item.value().get<double>()))
      throw InvalidInput(path + ": " + item.key() + ": must be a finite number");
    const double v = item.value().get<double>();
    if (!law && item.key() == "a1") c.a1 = v;
    else if (!law && item.key() == "a2") c.a2 = v;
    else if (!law && item.key() == "a3") c.a3 = v;
    else if (law && item.key() == "alpha_ohm_mm2") c.fitted_contact_law->alpha_ohm_mm2 = v;
    else if (law && item.key() == "gamma") c.fitted_contact_law->gamma = v;
    else throw InvalidInput(path + ": " + item.key() + ": unknown key" + (law ? " in a contact-fitting calibration" : ""));
  }
  for (const char* key : law ? std::vector<const char*>{"alpha_ohm_mm2", "gamma"} : std::vector<const char*>{"a1", "a2", "a3"})
    if (!j.contains(key)) throw InvalidInput(path + ": " + key + ": missing");
  if (law && !(c.fitted_contact_law->alpha_ohm_mm2 > 0 && c.fitted_contact_law->gamma < 0))
    throw InvalidInput(path + ": alpha_ohm_mm2 must be positive and gamma negative");
  return c;
}

void write_calibration(const std::string& path, const PressureCalibration& c) {
  AtomicFile file(path);
  const nlohmann::json j = c.fitted_contact_law
                              ? nlohmann::json{{"alpha_ohm_mm2", c.fitted_contact_law->alpha_ohm_mm2},
                                               {"gamma", c.fitted_contact_law->gamma}}
                              : nlohmann::json{{"a1", c.a1}, {"a2", c.a2}, {"a3", c.a3}};
  file.stream() << j.dump(2) << '\n';
  file.commit();
}

}  // namespace emit
