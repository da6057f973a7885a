#pragma once
/// \file presses_csv.hpp
/// Ground truth of a simulated run: `frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2`, one
/// row per press (several rows share a frame index for simultaneous presses).
#include <string>

#include "emit/sensor/press.hpp"

namespace emit {

void write_presses_csv(const std::string& path, const PressSequence& sequence);
/// \throw IoError / InvalidInput naming the line.
PressSequence read_presses_csv(const std::string& path);

}  // namespace emit
