// libFuzzer target for the calibration JSON (io/calibration_json.hpp): any bytes as the file read
// by load_calibration. It must return a calibration or throw an emit::Error (fuzz_support.hpp).
#include <cstddef>
#include <cstdint>

#include "emit/io/calibration_json.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = emit::fuzz::input_file(data, size, ".json");
  emit::fuzz::expect_only_emit_errors([&] { (void)emit::load_calibration(path); });
  return 0;
}
