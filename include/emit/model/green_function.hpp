#pragma once
/// \file green_function.hpp
/// The probing sheet's Green's function with electrode 0 grounded, dense: G0 = A0⁻¹ in the
/// forward model's dofs (each electrode one dof, electrode_dofs.hpp), with row and column 0 (the
/// grounded electrode) zero. The grounded Green's function of any other electrode follows from it
/// (docs/physics.md, "The Jacobian"), and a contact on a few nodes then costs a small dense solve on those nodes
/// (frame_predictor.hpp), not a factorisation.
///
/// Dense is n² doubles: about 180 MB for the default sheet's graded fit mesh (4.8k dofs),
/// computed by n solves with the sparse factor in about a second. That is the price of a
/// predicted frame in tens of microseconds.
#include <functional>
#include <vector>

#include "emit/fem/electrode_dofs.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

struct DenseGreenFunction {
  ElectrodeDofs dofs;
  Matrix G0;                       ///< (dof_count, or the kept rows) × (dof_count, or the solved columns) [Ω]
  std::vector<int> column_of_dof;  ///< G0's column of each dof (−1: not solved); empty: the dof itself
  std::vector<int> row_of_dof;     ///< G0's row of each dof (−1: not kept); empty: the dof itself

  /// A column over G0's rows: index it with row().
  auto column(int dof) const {
    return G0.col(column_of_dof.empty() ? dof : column_of_dof[static_cast<std::size_t>(dof)]);
  }
  int row(int dof) const { return row_of_dof.empty() ? dof : row_of_dof[static_cast<std::size_t>(dof)]; }
  double at(int row_dof, int column_dof) const { return column(column_dof)[row(row_dof)]; }
};

/// \param progress  told the fraction done, now and then (may be empty).
DenseGreenFunction dense_green_function(const Mesh& mesh, double sheet_resistance_ohm_per_sq,
                                        const std::function<void(double)>& progress = {});

/// The same for a sheet conductance per triangle [S]. If `only_dofs` is not empty, only those
/// columns are solved and kept (column_of_dof says where): enough for frames of contacts whose
/// patches lie in them, since a prediction reads G0 on its patch and the electrodes only
/// (frame_predictor.hpp). Dof 0 (the ground) is always among them.
DenseGreenFunction dense_green_function(const Mesh& mesh, const Vector& element_conductance_S,
                                        const std::vector<int>& only_dofs = {},
                                        const std::function<void(double)>& progress = {});

/// G0 only where one block of dofs meets itself: for each block (the electrodes added to it),
/// G0 on block × block, by sparse forward solves along the elimination tree
/// (SparseCholesky::inverse_block) instead of a solve per column. Rows and columns are the union
/// of the blocks, electrodes first (so `column(l).head(N)` holds electrode l's column on the
/// electrodes); entries between two blocks are not computed (left 0) and must not be read. For
/// fits whose contacts stay on known patches (a labelled calibration: one block per press): on the
/// default sheet about a tenth of the solves' time.
DenseGreenFunction blockwise_green_function(const Mesh& mesh, const Vector& element_conductance_S,
                                            const std::vector<std::vector<int>>& blocks);

}  // namespace emit
