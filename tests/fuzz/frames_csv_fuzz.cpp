// libFuzzer target for the frames CSV (io/frames_csv.hpp): the first byte chooses the electrode
// count (3..16), the rest is the file read by read_frames_csv. It must return frames of N×N
// values or throw an emit::Error (fuzz_support.hpp).
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "emit/io/frames_csv.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int electrode_count = 3 + data[0] % 14;
  const std::string& path = emit::fuzz::input_file(data + 1, size - 1, ".csv");
  emit::fuzz::expect_only_emit_errors([&] {
    for (const emit::Frame& frame : emit::read_frames_csv(path, electrode_count))
      if (frame.rows() != electrode_count || frame.cols() != electrode_count || !frame.allFinite()) std::abort();
  });
  return 0;
}
