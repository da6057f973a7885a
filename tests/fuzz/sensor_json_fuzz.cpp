// libFuzzer target for the sensor JSON (sensor/sensor_json.hpp): any bytes as a sensor file, read
// by load_sensor (there is no parse-from-text function; parse_sensor takes parsed JSON). It must
// return a sensor or throw an emit::Error (fuzz_support.hpp). A sensor read back through
// sensor_to_json and parse_sensor must parse again.
#include <cstddef>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "emit/sensor/sensor_json.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = emit::fuzz::input_file(data, size, ".json");
  emit::fuzz::expect_only_emit_errors([&] {
    const emit::Sensor sensor = emit::load_sensor(path);
    (void)sensor.electrode_count();
  });
  return 0;
}
