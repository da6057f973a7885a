// libFuzzer target for recordings (acquire/recording.hpp, acquire/file_source.hpp): any bytes as a
// .emitrec file, opened by FileSource for the built-in default sensor (16 electrodes) and read to
// its end as fast as possible. Opening and each frame must succeed or throw an emit::Error
// (fuzz_support.hpp); a file of k whole packets yields at most k frames of N×N finite volts.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "core/frame_packet.hpp"
#include "emit/acquire/file_source.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const emit::Sensor sensor = emit::default_sensor();
  const int n = sensor.electrode_count();
  const std::string& path = emit::fuzz::input_file(data, size, ".emitrec");
  emit::fuzz::expect_only_emit_errors([&] {
    emit::FileSource source(path, sensor, /*as_fast_as_possible=*/true);
    const std::size_t most = size / emit::firmware::packet_size(n);
    emit::SourceFrame frame;
    for (std::size_t frames = 1; !source.finished(); ++frames) {
      // At the end, next() throws IoError "end of recording" (file_source.hpp).
      if (!source.next(frame, std::chrono::milliseconds(0)) || frames > most) std::abort();
      if (frame.volts.rows() != n || frame.volts.cols() != n || !frame.volts.allFinite()) std::abort();
    }
  });
  return 0;
}
