#pragma once
/// \file excitation.hpp
/// A current-injection protocol (the EIT skins of the paper's Table 1): which pairs of
/// electrodes a current is driven between, in order, and which pairs are read, in the order a
/// frame from the hardware lists them. The named patterns are the classic ones (pyEIT, EIDORS's
/// mk_stim_patterns): a drive `skip-s` sources at electrode k and sinks at k + s + 1, k = 0 … N−1;
/// `adjacent` is skip-0 and `opposite` skip-(N/2 − 1). Readings are adjacent differential pairs
/// (m + 1, m), m = 0 … N−1, per drive, optionally without the pairs that share an electrode with
/// the drive (most boards cannot read a driving electrode). Electrodes are numbered modulo N.
#include <string>
#include <vector>

#include "emit/core/types.hpp"

namespace emit {

struct EitDrive {
  int source = 0, sink = 0;  ///< the current enters at source and leaves at sink
};

/// One value of a frame: drive `drive` (an index into the drives), read as U_plus − U_minus.
struct EitReading {
  int drive = 0;
  int plus = 0, minus = 0;
};

struct Excitation {
  double current_A = 1e-3;  ///< the drive's amplitude
  double frequency_Hz = 0;  ///< documentation only: the model is resistive
  std::vector<EitDrive> drives;
  std::vector<EitReading> readings;  ///< in the frame's order
  /// Each electrode's contact impedance per length of its edge [Ω·mm] (complete electrode model;
  /// a contact of Ω·mm² on a sheet t mm thick is that over t); empty or 0: the shunt model.
  std::vector<double> contact_impedance_ohm_mm;
  /// The range a contact impedance other than 0 must be in, as z / R□: the length of sheet whose
  /// resistance (per mm of width) equals the contact's. Below a micrometre the contact is perfect
  /// to any reading at a mm's resolution (the shunt model, 0, says so exactly); beyond a kilometre
  /// the electrode is as good as cut off the sheet. Outside, the model's system loses the digits
  /// a double holds (1e-15 or 1e20 Ω·mm at 5000 Ω/sq: "not positive definite"); inside, it
  /// factorises (CompleteElectrodeModel.TheSensorsContactImpedanceRangeIsSolvable). The sensor's JSON
  /// holds the key to it.
  static constexpr double min_contact_length_mm = 1e-6, max_contact_length_mm = 1e6;

  /// The drives as currents [A], electrode_count × #drives: +current_A at the source, − at the sink.
  Matrix drive_currents_A(int electrode_count) const;
};

/// "adjacent", "opposite" (N even) or "skip-s" (0 ≤ s ≤ N − 2), for N electrodes.
/// \throw InvalidInput naming the pattern and the choices.
std::vector<EitDrive> drive_pattern(const std::string& name, int electrode_count);

/// The adjacent pairs (m + 1, m) of every drive, drive by drive; with skip_driving, without the
/// pairs that share an electrode with their drive.
std::vector<EitReading> adjacent_readings(const std::vector<EitDrive>& drives, int electrode_count, bool skip_driving);

}  // namespace emit
