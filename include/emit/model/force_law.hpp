#pragma once
/// \file force_law.hpp
/// A linear method's force from its image, emit's calibration (not the paper's; docs/physics.md,
/// "Force from a linear image"): F = (b1/I + b2)^b3, eq. 8's form applied to the image's integral
/// I = Σ A_k δφ_k over the contact's part of the sheet [V·mm²] instead of to one element's δφ.
///
/// Why: a frame pins a contact's total conductance G = g·A, and a linear image spreads it over a
/// region 2–20× the contact's (its 50 % region is the image's blur, not the press), so eq. 8's
/// per-element pressure summed over that region (Σ P_k A_k) is the image's force, ×6–20 the
/// press's. The integral of δφ, a linear functional of the frame, follows G whatever the blur
/// (on the 60 mm sheet it is the same for the paper, NOSER and Laplacian priors to 0.1 %), and
/// G gives the force almost whatever the contact's size (eq. 2: G = A^(1+γ) F^(−γ)/α, F ∝ A^(1/6)
/// at fixed G). The linear response saturates as G grows (the contact pulls the sheet toward the
/// drive), which is eq. 8's own form: I ≈ k·G/(1 + G/G_s), so F = (b1/I + b2)^b3 with b3 ≈ 1/γ.
/// What the frame does not pin is the area: a contact is reported with the calibration presses'
/// indenter area, its pressure F/A, and σs that say how little the area is known.
namespace emit {

/// log A's σ for an indenter of unknown size, radii 2–10 mm log-uniform about the calibration's:
/// 2·ln(5)/√12 (as contact fitting's force σ, frame/reconstructor.cpp).
inline constexpr double unknown_indenter_log_area_std = 0.93;

struct ImageForceLaw {
  double b1_V_mm2 = 1, b2 = 0, b3 = -1;  ///< F [N] = (b1/I + b2)^b3, I in V·mm²
  double log_std = 0;                    ///< rms of ln(F̂/F) over the calibration presses
  double indenter_radius_mm = 5;         ///< the calibration presses' indenter (their mean radius)

  /// F [N] for an integral I [V·mm²]; 0 for I ≤ 0. The base b1/I + b2 is kept positive (an I
  /// beyond the calibration's range reads as the largest force the law can express).
  double force_N(double integral_V_mm2) const;
  /// π r² of the calibration's indenter: the area a contact is reported with.
  double indenter_area_mm2() const;
  /// The force's relative 1σ: the calibration's scatter and the indenter's unknown size, ln F
  /// moving by (1 + γ)/γ = 1 + b3 per unit of ln A (γ = 1/b3).
  double force_relative_std() const;
  /// The pressure's (F/A): ln P moves by 1/γ = b3 per unit of ln A, so the area dominates.
  double pressure_relative_std() const;
  /// \throw InvalidInput naming the field (core/option_check.hpp): b1 ≥ 0, b3 < 0, log_std ≥ 0,
  /// indenter_radius_mm > 0, all finite.
  void validate() const;
};

}  // namespace emit
