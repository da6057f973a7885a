#pragma once
/// \file electrode_health.hpp
/// Dead and swapped electrodes, told from the frames. A disconnected electrode m reads ~0 V as the sensed
/// electrode whatever is pressed (its ADC input is pulled down); as the grounded one it grounds
/// nothing, so the pressed sheet rises to the drive and its whole row reads full scale. Either,
/// in every frame that has signal, marks the electrode dead: the reconstruction then leaves out
/// all its measurements (as ground and as sense) and keeps the rest. Frames with a value that is
/// not finite are not counted. Two electrodes wired in each other's places show in the frames'
/// shape along the border (electrode_swap.hpp).
#include <cstddef>
#include <string>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct DeadElectrode {
  int electrode = -1;
  std::string reason;  ///< e.g. "reads 0 V as the sensed electrode in all 25 frames with signal"
};

/// Two electrodes wired in each other's places (electrode_swap.hpp).
struct SwappedElectrodes {
  int a = -1, b = -1;  ///< a < b
  std::string
      reason;  ///< e.g. "their readings fit each other's places along the border in 24 of 25 frames with signal"
};

/// find_dead_electrodes one frame at a time, for frames read as a stream.
class ElectrodeHealthTally {
 public:
  ElectrodeHealthTally(int electrode_count, const AdcSpec& adc);
  void add(const Frame& frame);
  std::vector<DeadElectrode> dead() const;
  /// Pairs that best_swap (electrode_swap.hpp) named, below swap_roughness_ratio, in a
  /// swap_vote_fraction of the frames with signal at least (min_swap_frames at least); none while
  /// an electrode is dead (its zeros are no border's shape). With 4 electrodes or fewer: none.
  std::vector<SwappedElectrodes> swapped() const;
  /// The frames with signal added since construction or the last reset().
  int frames_with_signal() const { return with_signal_; }
  /// Forget what was added (a window of frames: the live viewer's health). Allocates nothing.
  void reset();

 private:
  AdcSpec adc_;
  double tolerance_V_;
  int with_signal_ = 0;
  std::vector<int> zero_columns_, full_rows_;
  std::vector<int> swap_votes_;  ///< N × N: frames whose best exchange was (a, b), at a·N + b
};

/// Electrodes dead in every frame with signal. "At a rail" allows max(2 ADC steps, 5 σ of the
/// ADC noise); a frame has signal when some reading exceeds 20 times that. Needs at least one
/// such frame to say anything.
std::vector<DeadElectrode> find_dead_electrodes(const std::vector<Frame>& frames, const AdcSpec& adc);

/// The first reading an ADC of this spec cannot give: below 0 V or above its reference, by more
/// than the rail tolerance (volts in another unit, another board's frames): "ground l, sense
/// m reads v V, outside the ADC's 0 to vref V (sensor "adc")"; empty when there is none. The one
/// check of a frame's range, for files (check_readings_in_range) and arrays (the Python module). A
/// value that is not finite is no range error: the reconstructor masks it (frame/masked_readings.hpp).
/// (A grounding that fails in one frame, its row at full scale, is masked there too: clipped.)
std::string reading_out_of_range(const Eigen::Ref<const Frame>& frame, const AdcSpec& adc);

/// \throw InvalidInput "<where>: " + reading_out_of_range(frame, adc) when that is not empty.
void check_readings_in_range(const Eigen::Ref<const Frame>& frame, const AdcSpec& adc, const std::string& where);

/// A no-contact frame reads ~0 V everywhere; true if this one has a reading well above the noise
/// (the "signal" of find_dead_electrodes): a reference that was pressed.
bool looks_pressed(const Frame& frame, const AdcSpec& adc);

}  // namespace emit
