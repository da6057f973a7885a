#include "emit/io/calibration_json.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

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
  if (!j.is_object()) throw InvalidInput(path + ": must be a JSON object {\"a1\", \"a2\", \"a3\"}");
  PressureCalibration c;
  c.calibrated = true;
  for (const auto& item : j.items()) {
    if (!item.value().is_number() || !std::isfinite(item.value().get<double>()))
      throw InvalidInput(path + ": " + item.key() + ": must be a finite number");
    const double v = item.value().get<double>();
    if (item.key() == "a1") c.a1 = v;
    else if (item.key() == "a2") c.a2 = v;
    else if (item.key() == "a3") c.a3 = v;
    else throw InvalidInput(path + ": " + item.key() + ": unknown key");
  }
  for (const char* key : {"a1", "a2", "a3"})
    if (!j.contains(key)) throw InvalidInput(path + ": " + key + ": missing");
  return c;
}

void write_calibration(const std::string& path, const PressureCalibration& c) {
  AtomicFile file(path);
  file.stream() << nlohmann::json{{"a1", c.a1}, {"a2", c.a2}, {"a3", c.a3}}.dump(2) << '\n';
  file.commit();
}

}  // namespace emit
