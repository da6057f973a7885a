#pragma once
/// \file open_source.hpp
/// A live source from its spec, as `emit live --source` takes it: the twin (twin/sim_source.hpp)
/// or a device (acquire/device_source.hpp).
#include <memory>
#include <string>

#include "emit/acquire/frame_source.hpp"

namespace emit {

/// "sim" (a finger moving over the sheet in a figure-eight, lifted now and then), "sim:random"
/// (presses at random places), "sim:fixed" (10 N held at the sheet's middle), "sim:fixed:X,Y[,F]" (one press held at X,
/// Y mm with F N, default 10); "file:PATH" (a recording, acquire/recording.hpp) and "serial:PATH[@BAUD]" (the board).
/// \throw InvalidInput naming the spec.
std::unique_ptr<FrameSource> open_source(const std::string& spec, const Sensor& sensor, const SourceOptions& options);

}  // namespace emit
