#pragma once
/// \file stiffness.hpp
/// P1 stiffness of the probing sheet: K_ij = ∫ σ ∇φ_i·∇φ_j dA.
#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

/// Local stiffness of one triangle with vertices p0, p1, p2 (in 3D or in the plane) and sheet
/// conductance σ [S]: K_ij = σ (e_i·e_j) / (4A), e_i the edge opposite vertex i. Using edge
/// vectors rather than planar gradients makes it valid for a triangle anywhere in 3D.
Eigen::Matrix3d local_stiffness(const Vector3& p0, const Vector3& p1, const Vector3& p2, double conductance_S);

/// #V by #V stiffness [S] of the whole mesh; symmetric, K·1 = 0, positive semi-definite.
SparseMatrix assemble_stiffness(const Mesh& mesh, double conductance_S);
/// The same with a sheet conductance per triangle (#F values [S]), for sheets that are not uniform.
SparseMatrix assemble_stiffness(const Mesh& mesh, const Vector& element_conductance_S);

}  // namespace emit
