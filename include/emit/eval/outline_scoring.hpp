#pragma once
/// \file outline_scoring.hpp
/// A reconstructed pressed region scored against the outlines that were pressed (issue 31): on
/// the reconstruction mesh's own triangles, the region is the elements where the reconstructor's
/// pressure() is positive (every method fills it: the linear ones their thresholded eq. 8 image,
/// contact fitting its contacts drawn at their pressure), the truth the fraction of each triangle
/// inside an outline (sensor/press_outline.hpp). Scored by
///
/// - Dice, 2|A∩B| / (|A| + |B|), area-weighted: |A∩B| = Σ_k A_k [P_k > 0] f_k, |B| = Σ_k A_k f_k;
/// - force: Σ of the frame's contacts' forces against Σ of the presses';
/// - centroid: the region's area-weighted centroid against the outlines' (exact, polygons');
/// - orientation: the principal axis of the region's second moments against the outlines', for
///   outlines elongated enough to have one (eigenvalue ratio ≥ `elongated_ratio`);
/// - the number of regions (contacts) reported, against the number of presses;
/// - the contacts' total area and force against the outlines', with their reported 1σ (summed in
///   quadrature over the contacts), for coverage: whether the truth lies within 1σ and 2σ.
///
/// Flat sheets only (a region's moments are in the sheet's x, y).
#include <vector>

#include "emit/core/types.hpp"
#include "emit/frame/contacts.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/sensor/press.hpp"

namespace emit {

/// Second-moment eigenvalue ratio from which an outline has an orientation to score: a 20 × 6 bar
/// has 11, an ellipse 24 × 12 4, an L of two 20 × 4 bars 3.6, two parallel 20 × 3 bars with centre
/// lines 10 mm apart (33.3 + 0 along, 0.75 + 25 across) 1.29; a disc and a ring 1.
inline constexpr double elongated_ratio = 1.25;

/// #F fractions of each triangle of a flat `mesh` inside some press's outline (a disc's too),
/// each triangle cut into 4^levels equal pieces whose centroids are tested: exact for triangles
/// wholly inside or outside, within the pieces' area along an outline's edge.
Vector outline_coverage(const Mesh& mesh, const std::vector<Press>& presses, int levels = 4);

/// 2 Σ A_k r_k t_k / (Σ A_k r_k + Σ A_k t_k), r_k and t_k in [0, 1] (the reconstructed and the
/// true fractions of triangle k); 1 when both are empty, 0 when one is. \pre equal sizes.
double area_dice(const Vector& areas_mm2, const Vector& reconstructed, const Vector& truth);

/// The principal axis' angle of second moments [deg, in (−90, 90]]: the direction of the larger
/// eigenvalue, from the x axis.
double principal_angle_deg(const Eigen::Matrix2d& second_moments);

/// The angle between two axes [deg, 0…90] (an axis is a direction up to 180°).
double axis_difference_deg(double a_deg, double b_deg);

/// What the pressed outlines are: their total area, force, centroid and second moments (of the
/// union; presses of a frame are taken not to overlap).
struct OutlineTruth {
  double area_mm2 = 0, force_N = 0;
  Vector2 centroid_mm = Vector2::Zero();
  Eigen::Matrix2d second_moments_mm2 = Eigen::Matrix2d::Zero();
  bool elongated = false;  ///< eigenvalue ratio ≥ elongated_ratio
  double angle_deg = 0;    ///< the principal axis (when elongated)
};
OutlineTruth outline_truth(const std::vector<Press>& presses);

/// One frame's score.
struct OutlineScore {
  double dice = 0;
  double force_N = 0, true_force_N = 0;  ///< Σ of the contacts' forces; of the presses'
  double region_area_mm2 = 0;            ///< the reconstructed pressed region's
  /// The region's centroid's distance to the outlines' [mm]; NaN without a region.
  double centroid_error_mm = 0;
  /// Between the principal axes [deg, 0…90]; NaN unless the truth is elongated; 90 (the worst)
  /// when it is and no region was reported.
  double orientation_error_deg = 0;
  int regions = 0, presses = 0;  ///< contacts reported; presses made
  /// Σ of the contacts' areas and their 1σ (in quadrature); the outlines' area [mm²].
  double area_mm2 = 0, area_std_mm2 = 0, true_area_mm2 = 0;
  double force_std_N = 0;  ///< of force_N, in quadrature over the contacts
};

/// Whether `truth` lies within `k` reported σ of `value`, read as a σ of the logarithm
/// (σ/value): |ln(value/truth)| ≤ k σ/value. Every σ the contact fits report is one of log A or
/// log F times the value (frame/reconstructor.hpp), and a σ of 0.9 on log A is a factor 2.5, not
/// ±90 %. False for a value or truth that is not positive.
bool within_sigmas(double value, double std, double truth, double k);

/// Scores a frame: `coverage`, outline_coverage(mesh, presses) (computed once for every method
/// on one mesh); `pressure`, #F per triangle of the flat `mesh` (the reconstructor's pressure());
/// `contacts`, what it reported; `presses`, the truth. The region's second moments are its
/// triangles' centroids' (each triangle's own, ~h²/18, is small against an outline's).
/// \throw InvalidInput when `coverage` or `pressure` is not #F long.
OutlineScore score_outline_frame(const Mesh& mesh, const Vector& coverage, const Vector& pressure,
                                 const std::vector<Contact>& contacts, const std::vector<Press>& presses);

}  // namespace emit
