#pragma once
/// \file press_contact.hpp
/// Presses → contact conductance, resolved inside elements: the twin integrates g(P(x)) φ_i φ_j
/// exactly on triangles wholly inside or outside every disc, and on the triangles a disc's edge
/// cuts it subdivides adaptively (4 children per level) and integrates each child with the
/// edge-midpoint rule, exact for the quadratic φ_i φ_j, with the pressure taken at the child's
/// centroid. The contact edge is then resolved to h / 2^levels, not to the mesh size.
///
/// Spherical presses, or any press under a cover that blurs (press_pressure.hpp), have a smooth
/// pressure field: triangles within its support are cut into pieces small against the blur (a
/// quarter of it) or the profile (an eighth of the radius), refined `levels` more where the
/// contact's edge crosses them, and integrated by the edge-midpoint rule with g at the midpoints.
///
/// Flat punches of any outline (sensor/press_outline.hpp), on flat sheets: the same rule as the
/// discs', a piece being cut where one of the outline's polygon edges meets it, else wholly inside
/// or outside as its centroid is. Frames with no outline take the discs' path unchanged.
#include <vector>

#include "emit/fem/contact_load.hpp"
#include "emit/sensor/press.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// A press loads the sheet where it is within its radius (3D distance) of its centre (x, y, z),
/// a point on the sheet: a disc on a flat sheet. `levels` is the subdivision depth on cut
/// triangles (6: children 64× smaller in edge length); `blur_mm`, the cover's Gaussian (0: none).
/// \throw InvalidInput for a negative blur; for an outline press under a blur, beside a spherical
/// press, on a curved mesh, or with an invalid outline.
ContactLoad press_contact_load(const Mesh& mesh, const std::vector<Press>& presses, const ContactLaw& law,
                               int levels = 6, double blur_mm = 0);

}  // namespace emit
