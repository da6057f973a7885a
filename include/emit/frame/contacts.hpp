#pragma once
/// \file contacts.hpp
/// Contacts from a reconstructed image (paper §2.4): the connected regions of selected (above
/// threshold) elements, two elements being connected when they share an edge. Each contact gets
/// its centroid, area, mean and peak pressure and force = Σ P_k·A_k, the ellipse of its second
/// moments and its outline (contact_outline.hpp).
///
/// Offline/online split: the constructor precomputes the mesh's element adjacency, areas and
/// centroids; find() runs per frame and allocates nothing (all scratch and the output buffer are
/// sized for the worst case at construction).
#include <cstdint>
#include <limits>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/frame/contact_outline.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Where a tracked touch is in its life (frame/contact_tracker.hpp), as touch screens report it.
enum class TouchPhase : std::uint8_t {
  none,  ///< not tracked (a single frame's contacts)
  down,  ///< the touch's first frame
  move,  ///< a later frame of the same touch (moved or not)
  up,    ///< the touch has ended: its last state, reported once, in the frame after its last
};

/// "none", "down", "move", "up": as JSON Lines and CSV tracks write a phase.
const char* touch_phase_name(TouchPhase phase);

struct Contact {
  /// The contact's point of the sheet and the sheet's unit outward normal there
  /// (sensor/surface.hpp): the point the centroid (weighted by area × weight, see find()) names.
  /// On a flat sheet z = 0 and the normal is +z; on a curved one the point is on the surface.
  double x_mm = 0, y_mm = 0, z_mm = 0, nx = 0, ny = 0, nz = 1;
  double area_mm2 = 0;                 ///< Σ A_k over the contact's elements
  double pressure_N_per_mm2 = 0;       ///< area-weighted mean pressure
  double peak_pressure_N_per_mm2 = 0;  ///< largest element pressure
  double force_N = 0;                  ///< Σ P_k A_k
  /// 1σ uncertainties: contact fitting's from its covariance, a calibrated linear method's force and
  /// pressure from its force law (frame/image_forces.hpp); 0 where not estimated.
  /// The position's are along the chart's two axes (sensor/surface.hpp): x and y on a flat sheet
  /// and a cap, along the axis and around it on a cylinder.
  double x_std_mm = 0, y_std_mm = 0, pressure_std_N_per_mm2 = 0;
  /// The force's 1σ: the fit's, and the indenter's unknown size (contact fitting reports the
  /// calibration indenter's area; frame/reconstructor.hpp says how much that leaves open).
  double force_std_N = 0;
  /// The outline as the ellipse of its second moments: semi-axes [mm] and the major axis's angle
  /// from the chart's first axis (x on a flat sheet) [deg, in (−90, 90]]. A linear method's from
  /// its region's elements (seen from +z), contact fitting's from the refitted ellipse
  /// (shape_refiner.hpp); a round contact's angle means nothing (see orientation_std_deg).
  double semi_major_mm = 0, semi_minor_mm = 0, orientation_deg = 0;
  /// 1σ of the area and the angle (contact fitting); 0 where not estimated.
  double area_std_mm2 = 0, orientation_std_deg = 0;
  int element_count = 0;
  /// The outline as a polygon in the sheet's chart [mm], counter-clockwise (contact_outline.hpp):
  /// a linear method's region's level line at its threshold, contact fitting's disc's circle,
  /// the `shapes` method's ellipse. Empty where there is none (a contact read from a file
  /// without it).
  Outline outline;
  /// Tracking (frame/contact_tracker.hpp): the touch's id, the same while it lasts and never reused
  /// in a run; −1 untracked. Its phase, and its velocity along the chart's axes [mm/s].
  std::int64_t id = -1;
  TouchPhase phase = TouchPhase::none;
  double vx_mm_per_s = 0, vy_mm_per_s = 0;
};

/// Sets the contact's semi-axes and orientation to the uniform ellipse's of this covariance of
/// position over its area [mm²] (a uniform ellipse's variances along its axes are a²/4, b²/4).
void set_outline_ellipse(const Eigen::Matrix2d& covariance_mm2, Contact& contact);

/// Puts the contact at the sheet's point named by chart point c, with the sheet's normal there
/// (sensor/surface.hpp).
void place_on_surface(const Shape& surface, const Vector2& chart_mm, Contact& contact);

/// The chart point of the contact's position (sensor/surface.hpp): its (x, y) unless on a cylinder.
Vector2 chart_of(const Shape& surface, const Contact& contact);

class ContactFinder {
 public:
  /// \param surface  the sheet's shape: each contact's centroid (in 3D) is placed on it, at the
  ///                 point whose chart point is the centroid's (surface_chart_mm).
  explicit ContactFinder(const Mesh& mesh, Shape surface = {});

  /// \param selected  #F flags, nonzero where the element is above threshold
  /// \param pressure  #F element pressures [N/mm²] (read only where selected)
  /// \param weight    #F non-negative weights for the centroid (e.g. the reconstructed
  ///                  potential); the centroid is Σ w_k A_k c_k / Σ w_k A_k, or the area-weighted
  ///                  centroid when all weights of a contact are 0
  /// \param floor   null, or #F values: a contact is kept only if the weight of one of its
  ///                 elements exceeds the floor there (the image's significance: reconstructor.hpp)
  /// \param level  the weight's value that selected the elements (a linear method's threshold on
  ///                δφ): each contact's outline is the weight's level line there around its region
  ///                (RegionOutliner); NaN: the line half-way between its elements and the others.
  ///                A region too small for a line gets the polygon of its ellipse.
  /// \return the contacts, largest force first; valid until the next call. Contacts smaller than
  ///         min_area_mm2 are dropped.
  const std::vector<Contact>& find(const std::vector<std::uint8_t>& selected, const Vector& pressure,
                                   const Vector& weight, double min_area_mm2 = 0.0, const Vector* floor = nullptr,
                                   double level = std::numeric_limits<double>::quiet_NaN());

  /// The image's peaks: elements whose value is at least min_value and no smaller than any edge
  /// neighbour's, strongest first, each at least min_separation_mm from every stronger one kept.
  /// Where a 50 % threshold merges two presses into one region, the image still has two peaks.
  /// \return the peaks' centroids' chart points, valid until the next call.
  const std::vector<Vector2>& peaks(const Vector& image, double min_value, double min_separation_mm);

  Index element_count() const { return static_cast<Index>(areas_mm2_.size()); }
  /// The chart point (sensor/surface.hpp) of an element's centroid.
  const Vector2& centroid_chart_mm(Index element) const { return charts_mm_[static_cast<std::size_t>(element)]; }
  /// An element's centroid in 3D.
  const Vector3& centroid_mm(Index element) const { return centroids_mm_[static_cast<std::size_t>(element)]; }

 private:
  Shape surface_;
  std::vector<int> neighbour_offsets_, neighbours_;  ///< CSR edge adjacency of triangles
  std::vector<double> areas_mm2_;
  Vector no_floor_;  ///< −∞ everywhere: the floor when none is given
  std::vector<Vector3> centroids_mm_;
  std::vector<Vector2> charts_mm_;     ///< the centroids' chart points
  std::vector<std::uint8_t> pending_;  ///< scratch: selected elements not yet in a contact
  std::vector<int> stack_;             ///< scratch
  std::vector<int> members_;           ///< scratch: the elements of the contact grown last
  RegionOutliner outliner_;
  std::vector<Contact> contacts_;  ///< output, capacity #F
  std::vector<int> peak_elements_;
  std::vector<Vector2> peaks_;
};

}  // namespace emit
