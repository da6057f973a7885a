#pragma once
/// \file slide_electrodes.hpp
/// Electrodes moved along the border without remeshing: the mesh's nodes slide with them (a
/// painted electrode sits up to ±0.5 mm from its nominal place, and the calibration fits where). Remeshing for each
/// trial position would change the mesh's topology, and the discretisation error with it, by far more than a finite
/// difference's step; sliding keeps the topology, so a frame is a smooth function of the shifts.
///
/// Electrode e moves by shift_mm[e] along the border (counter-clockwise positive). Its nodes and
/// every node within `rigid_mm` of it (along the border and into the sheet) move by the full shift;
/// the displacement then falls linearly to 0 over `reach_mm` further; border nodes stay on the
/// border (placed at their arc length plus the displacement), interior ones move along the
/// border's tangent. The zones are shrunk so that no two electrodes' zones overlap and none
/// reaches a corner of the border (where the tangent turns).
#include <vector>

#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct SlideOptions {
  double rigid_mm = 0.6;  ///< moved by the full shift beyond the electrode's ends and depth
  double reach_mm = 3.0;  ///< then down to 0 over this much more
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// \param sensor  the sheet's border and its electrodes as `mesh` has them (an analytic border)
/// \throw InvalidInput for a mesh-file sensor (no analytic border), a wrong count of shifts, a
///        shift larger than its zone allows, an electrode over a corner of the border with a
///        non-zero shift, or a slide that would fold a triangle.
Mesh slide_electrodes(const Mesh& mesh, const Sensor& sensor, const std::vector<double>& shift_mm,
                      const SlideOptions& options = {});

/// The sensor with each electrode moved along the border by shift_mm[e]: what the slid mesh
/// represents, for pictures and for remeshing. \throw InvalidInput as above.
Sensor with_electrodes_slid(const Sensor& sensor, const std::vector<double>& shift_mm);

}  // namespace emit
