// libFuzzer target for the presses CSV (io/presses_csv.hpp): any bytes as the file read by
// read_presses_csv, as every reader does and as calibration does (empty places and forces allowed).
// It must return the presses or throw an emit::Error (fuzz_support.hpp).
#include <cstddef>
#include <cstdint>

#include "emit/io/presses_csv.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = emit::fuzz::input_file(data, size, ".csv");
  emit::fuzz::expect_only_emit_errors([&] { (void)emit::read_presses_csv(path); });
  emit::fuzz::expect_only_emit_errors(
      [&] { (void)emit::read_presses_csv(path, emit::default_max_press_frames, emit::UnknownPresses::allowed); });
  return 0;
}
