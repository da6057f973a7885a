#pragma once
/// \file complete_electrode_model.hpp
/// Current-injection EIT on the sheet (docs/physics.md, "Current-injection skins"): currents I_l
/// are driven into the electrodes and their potentials U_l read, through the complete electrode
/// model (Somersalo, Cheney & Isaacson 1992):
///   −∇·(σ∇u) = 0 on the sheet,   σ ∂u/∂n = 0 on the border off the electrodes,
///   u + z_l σ ∂u/∂n = U_l  and  ∫_{e_l} σ ∂u/∂n ds = I_l  on electrode l,
/// σ the sheet conductance [S] per triangle, z_l the contact impedance per length of the
/// electrode's edge [Ω·mm] (a contact of Ω·mm² over a sheet t mm thick is z/t). With P1 elements
/// (Vauhkonen et al. 1999) the unknowns are the nodes' u and the electrodes' U, and the matrix is
///   [ K + Σ_l M_l / z_l    −b_l / z_l  ]
///   [ −b_lᵀ / z_l           |e_l| / z_l ],
/// M_l = ∫_{e_l} φ_i φ_j ds, b_l = ∫_{e_l} φ_i ds, |e_l| the electrode's length. z_l = 0 is the
/// shunt model (the electrode one perfect conductor): its nodes are then merged into U_l. The
/// matrix is symmetric and positive semidefinite, its kernel the constants: electrode 0 is held
/// at 0 V, then the potentials are shifted to Σ_l U_l = 0.
///
/// Assembled and factorised once per σ and z (offline); each set of injections is one solve.
#include <memory>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

class CompleteElectrodeModel {
 public:
  /// contact_impedance_ohm_mm: one per electrode, each ≥ 0 (0: the shunt model).
  /// \throw InvalidInput for a wrong count of conductances or impedances, a negative or non-finite
  /// one, or a mesh whose electrodes share a node or have no border edge.
  CompleteElectrodeModel(const Mesh& mesh, const Vector& element_conductance_S,
                         const std::vector<double>& contact_impedance_ohm_mm);
  ~CompleteElectrodeModel();
  CompleteElectrodeModel(CompleteElectrodeModel&&) noexcept;
  CompleteElectrodeModel& operator=(CompleteElectrodeModel&&) noexcept;
  CompleteElectrodeModel(const CompleteElectrodeModel&) = delete;  // move-only: it owns its factor
  CompleteElectrodeModel& operator=(const CompleteElectrodeModel&) = delete;

  int electrode_count() const;

  /// The electrodes' potentials [V], N × P, for the injected currents [A], N × P: column p is one
  /// drive, its currents summing to 0 (\throw InvalidInput otherwise); each result column sums to 0.
  Matrix electrode_potentials_V(const Matrix& currents_A) const;
  /// The nodes' potentials [V], #V × P, for the same drives and with the same reference.
  Matrix node_potentials_V(const Matrix& currents_A) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace emit
