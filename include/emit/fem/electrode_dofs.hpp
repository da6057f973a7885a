#pragma once
/// \file electrode_dofs.hpp
/// Degrees of freedom of the electrode model: each electrode is a perfect conductor, so all its
/// nodes share one unknown. Electrode e is dof e (0..N-1); the other nodes follow from N on.
#include <vector>

#include "emit/fem/contact_load.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

struct ElectrodeDofs {
  std::vector<int> dof_of_node;  ///< #V
  int dof_count = 0;
  int electrode_count = 0;
};

/// \throw InvalidInput if a node lies on two electrodes or an electrode has no node.
ElectrodeDofs number_electrode_dofs(const Mesh& mesh);

/// Node-space matrix A (#V×#V) to dof space: Pᵀ A P, where P maps dofs to nodes.
SparseMatrix to_dof_space(const SparseMatrix& node_matrix, const ElectrodeDofs& dofs);

/// The contact matrix C (contact_load.hpp) assembled straight into dof space [S].
SparseMatrix contact_to_dof_space(const Mesh& mesh, const ContactLoad& contact, const ElectrodeDofs& dofs);

}  // namespace emit
