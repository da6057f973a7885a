#pragma once
/// \file green_function.hpp
/// The probing sheet's Green's function with electrode 0 grounded, dense: G0 = A0⁻¹ in the
/// forward model's dofs (each electrode one dof, electrode_dofs.hpp), with row and column 0 (the
/// grounded electrode) zero. The grounded Green's function of any other electrode follows from it
/// (DESIGN §2, step 3), and a contact on a few nodes then costs a small dense solve on those nodes
/// (frame_predictor.hpp), not a factorisation.
///
/// Dense is n² doubles: about 180 MB for the default sheet's graded fit mesh (4.8k dofs),
/// computed by n solves with the sparse factor in about a second. That is the price of a
/// predicted frame in tens of microseconds.
#include <functional>

#include "emit/fem/electrode_dofs.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

struct DenseGreenFunction {
  ElectrodeDofs dofs;
  Matrix G0;  ///< dof_count × dof_count [Ω]
};

/// \param progress  told the fraction done, now and then (may be empty).
DenseGreenFunction dense_green_function(const Mesh& mesh, double sheet_resistance_ohm_per_sq,
                                        const std::function<void(double)>& progress = {});

}  // namespace emit
