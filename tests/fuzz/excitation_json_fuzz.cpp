// libFuzzer target for a sensor's "excitation" block (sensor/sensor_json.hpp, sensor/excitation.hpp):
// the first byte chooses the electrode count (3 to 34) of a circle sensor, the rest is the block's
// JSON, read by parse_sensor. Text that is not JSON is passed over (sensor_json_fuzz reads whole
// files); the sensor must parse or throw an emit::Error (fuzz_support.hpp), and a sensor it
// accepts must read back (sensor_to_json, parse_sensor) to the same drives and readings.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "emit/sensor/sensor_json.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int electrodes = 3 + data[0] % 32;
  nlohmann::json excitation;
  try {
    excitation = nlohmann::json::parse(data + 1, data + size);
  } catch (const nlohmann::json::exception&) {
    return 0;
  }
  const nlohmann::json sensor = {{"shape", {{"type", "circle"}, {"radius_mm", 40}}},
                                 {"electrodes", {{"count", electrodes}, {"width_mm", 1}}},
                                 {"excitation", excitation}};
  emit::fuzz::expect_only_emit_errors([&] {
    const emit::Sensor parsed = emit::parse_sensor(sensor, "fuzz");
    if (!parsed.excitation) std::abort();
    const emit::Sensor again = emit::parse_sensor(emit::sensor_to_json(parsed), "fuzz again");
    const emit::Excitation& a = *parsed.excitation;
    const emit::Excitation& b = *again.excitation;
    if (a.drives.size() != b.drives.size() || a.readings.size() != b.readings.size()) std::abort();
    for (std::size_t i = 0; i < a.drives.size(); ++i)
      if (a.drives[i].source != b.drives[i].source || a.drives[i].sink != b.drives[i].sink) std::abort();
    for (std::size_t i = 0; i < a.readings.size(); ++i)
      if (a.readings[i].drive != b.readings[i].drive || a.readings[i].plus != b.readings[i].plus ||
          a.readings[i].minus != b.readings[i].minus)
        std::abort();
  });
  return 0;
}
