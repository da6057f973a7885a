#pragma once
/// \file greit_merit.hpp
/// GREIT's figures of merit for the image of a small target (Adler et al. 2009, "GREIT: a unified
/// approach to 2D linear EIT reconstruction of lung images", Physiol. Meas. 30 S35, §2.3, as
/// EIDORS's eval_GREIT_fig_merit and pyEIT's pyeit.quality.merit compute them), on emit's own
/// triangles instead of a pixel grid: each element's value weighs by its area.
///
/// The quarter-amplitude set q: the elements whose value is at least ¼ of the image's largest
/// value in the target's direction (GREIT's threshold, measured from 0). C: the circle of q's
/// area centred on q's centre of gravity (an unweighted, area-weighted mean of q's elements).
///   AR  = Σ_k x̂_k A_k / target_amount (paper eq. 2: the image's integral over the target's);
///   PE  = r_t − r_q, the target's distance from the sheet's centre of gravity less q's (paper
///         eq. 3; signed: > 0 when the image is drawn towards the centre) [mm];
///   RES = √(A_q / A_sheet) (eq. 4: a radius ratio);
///   SD  = the fraction of q's area outside C (eq. 5);
///   RNG = the integral of the image of the opposite sign outside C over the image's integral
///         inside C (eq. 6), as a magnitude (≥ 0).
/// The paper's images are of a positive contrast; an image whose largest magnitude is negative
/// is taken negated. Flat sheets: positions are seen from +z.
#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

struct GreitMerit {
  double amplitude_response = 0;  ///< AR, in the image's unit × mm² per target_amount's unit
  double position_error_mm = 0;   ///< PE
  double resolution = 0;          ///< RES, dimensionless
  double shape_deformation = 0;   ///< SD, in [0, 1]
  double ringing = 0;             ///< RNG, ≥ 0
  Vector2 quarter_set_centre_mm{0, 0};
  double quarter_set_area_mm2 = 0;
};

/// \param image  per triangle of `mesh` (#F values), e.g. δφ [V] or pressure [N/mm²]
/// \param target_centre_mm  where the target is
/// \param target_amount  what AR divides by: the target's force [N] or area [mm²] (> 0)
/// \throw InvalidInput if the image's size is not #F, it is not finite, it is all 0, or
/// target_amount is not positive.
GreitMerit greit_figures_of_merit(const Mesh& mesh, const Vector& image, const Vector2& target_centre_mm,
                                  double target_amount);

/// The sheet's centre of gravity seen from +z (what PE measures radii from).
Vector2 sheet_centre_mm(const Mesh& mesh);

}  // namespace emit
