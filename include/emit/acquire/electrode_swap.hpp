#pragma once
/// \file electrode_swap.hpp
/// Two electrodes wired in each other's places, told from a pressed frame without a model.
///
/// Grounding electrode l, the other electrodes read the probing layer's potential where they are:
/// a smooth function of the place along the border (it falls to 0 at l and rises towards the
/// press). Electrodes numbered in order along the border (as every sensor of examples/sensors is),
/// each row of a frame is then smooth from one electrode to the next. Two electrodes swapped in the
/// wiring exchange two rows and the same two columns: each row gets two readings out of place, and
/// its second differences grow. The frame's roughness is the sum over rows l of the squared
/// second differences V[l][m] − (V[l][m−1] + V[l][m+1]) / 2 along the border (cyclic), leaving out
/// those that touch l (the dip to its 0 V). A swap shows as the one exchange (a, b) that makes a
/// frame much smoother: below swap_roughness_ratio of its roughness as read.
///
/// Measured (emit simulate --script random, 20 pressed frames a sheet, seeds 3–5): on unswapped
/// frames of the square, circle, hexagon, cylinder patch and fingertip no exchange brings the
/// roughness below 0.978 of itself; a swapped pair not adjacent along the border is the best
/// exchange in every frame, at 0.04–0.54; an adjacent one in most: 15–20 of 20 frames on the
/// square (a press on the diagonal of a corner reads alike from the two electrodes either side
/// of it), 20 of 20 on the circle. On the independent implementation's frames (../shared/
/// conformance: square, circle, dome), the same. The sleeve (two rings of electrodes) has single
/// frames where an exchange across its rings scores 0.63–0.9, never the same pair in more than 4
/// of 20 frames: a verdict takes the same pair in most frames with signal (swap_vote_fraction).
#include "emit/core/types.hpp"

namespace emit {

/// An exchange that smooths a frame below this fraction of its roughness names a swap candidate.
inline constexpr double swap_roughness_ratio = 0.9;
/// A swap is named (electrode_health.hpp) when the same pair was the frame's candidate in this
/// share of the frames with signal, and this many frames at least.
inline constexpr double swap_vote_fraction = 0.6;
inline constexpr int min_swap_frames = 5;

/// The frame's roughness along the border with electrodes `a` and `b` exchanged (a = b: as read).
/// \pre frame is N × N, N ≥ 4, all finite.
double border_roughness(const Frame& frame, int a = 0, int b = 0);

struct SwapCandidate {
  int a = -1, b = -1;          ///< the exchange that smooths the frame most (a < b); −1: none helps
  double roughness_ratio = 1;  ///< its roughness over the frame's as read
};

/// The best exchange of two electrodes (N(N − 1)/2 tried: O(N⁴), 30 µs for N = 16). Allocates
/// nothing. A frame with no roughness (unpressed, or all alike) has none.
SwapCandidate best_swap(const Frame& frame);

}  // namespace emit
