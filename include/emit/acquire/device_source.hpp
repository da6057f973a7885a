#pragma once
/// \file device_source.hpp
/// The sources that read a device or a file: "serial:PATH[@BAUD]" (serial_source.hpp; default
/// 921600 baud; a port that goes away is retried for SourceOptions::reconnect_s) and "file:PATH"
/// (a recording, file_source.hpp). open_source (frame_source.hpp) hands these specs here.
#include <memory>
#include <string>

#include "emit/acquire/frame_source.hpp"

namespace emit {

/// The source for a "serial:…" or "file:…" spec; nullptr for any other spec.
/// \throw InvalidInput naming the spec if it is malformed (empty path, a baud that is not a
/// positive number) or if options.loop asks a serial port to loop; IoError (one line, naming the path) if the port or
/// file cannot be opened.
std::unique_ptr<FrameSource> open_device_source(const std::string& spec, const Sensor& sensor,
                                                const SourceOptions& options);

}  // namespace emit
