#pragma once
/// \file jacobian.hpp
/// The Jacobian of the paper's reconstruction model (eqs. 3–6): with electrode l grounded and
/// the nodes of element k held at 1 V (a Dirichlet patch, eq. 4) in an otherwise insulated sheet
/// with floating electrodes, J[(l,m), k] = ∂V[l][m]/∂φ_k is the potential of electrode m.
///
/// Element touching the grounded electrode: its nodes on electrode l cannot be at 1 V and 0 V at
/// once; we hold only its other nodes at 1 V (the column is the response of the part of the
/// element that can rise). An element with every node on electrode l has a zero column.
#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/model/measurements.hpp"

namespace emit {

/// Fast and exact: one factorisation (electrode 0 grounded), N − 1 solves, and selected
/// inversion of the factor for the Green's function on each element's nodes. For ground l,
/// G_l(x, y) = G0(x, y) − w_l(x) − w_l(y) + w_l(e_l) with w_l = G0(·, e_l), and
/// V[l][m] = G_l(m, S) · G_l(S, S)⁻¹ · 1 for the element's nodes S (docs/physics.md, "The Jacobian").
/// \return #measurements by #F, rows in the order of `measurements`. J is dimensionless and does
/// not depend on the sheet resistance.
Matrix compute_jacobian(const Mesh& mesh, const MeasurementSet& measurements);

/// The same by brute force, one Dirichlet solve per element and grounding: for tests on small
/// meshes only.
Matrix compute_jacobian_brute_force(const Mesh& mesh, const MeasurementSet& measurements);

}  // namespace emit
