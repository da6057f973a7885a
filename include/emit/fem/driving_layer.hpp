#pragma once
/// \file driving_layer.hpp
/// A driving layer with a resistance of its own. docs/physics.md (and the paper, and the reconstruction)
/// take the driving layer as an equipotential at E. A real one (conductive fabric) is a sheet with
/// its own small sheet resistance, held at E only where it is fed (a bus bar), so a contact far
/// from the feed draws its current through it and sees less than E:
///
///     -div(σ_d ∇v) + g (v − u) = 0  on the sheet,  v = E on the feed;
///     -div(σ ∇u)   + g (u − v) = 0  (the probing sheet, with its electrodes as before).
///
/// The two layers share one mesh; the contact couples them node by node. The twin uses this to
/// simulate a sensor that departs from the model the reconstruction assumes.
#include <vector>

#include "emit/fem/contact_load.hpp"
#include "emit/fem/electrode_dofs.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

struct DrivingLayer {
  Vector element_conductance_S;  ///< 1 / its sheet resistance, per triangle [S]
  std::vector<int> feed_nodes;   ///< nodes held at the drive voltage
};

/// A uniform driving layer fed along a bus bar on the sheet's bottom: the border nodes within
/// `fraction` of the sheet's height of its lowest point (for a rectangle, the bottom side and
/// the lowest bit of the two others). \throw InvalidInput for a non-positive resistance.
DrivingLayer bottom_fed_driving_layer(const Mesh& mesh, double sheet_resistance_ohm_per_sq, double fraction = 0.05);

/// The probing sheet's dofs (first `dofs.dof_count`) and the driving layer's free nodes (after
/// them) as one linear system F·x = E·drive, for one contact.
struct CoupledSystem {
  SparseMatrix F;  ///< symmetric; singular until an electrode is grounded
  Vector drive;    ///< right-hand side per volt of drive (the feed's pull, moved to the right)
};

/// Assembles the driving layer's part once; `system` then adds a contact in O(contact).
class CoupledAssembler {
 public:
  CoupledAssembler(const Mesh& mesh, const ElectrodeDofs& dofs, const SparseMatrix& probing_stiffness_dof,
                   const DrivingLayer& layer);
  CoupledSystem system(const ContactLoad& contact) const;

 private:
  const Mesh* mesh_;
  const ElectrodeDofs* dofs_;
  std::vector<int> free_index_;  ///< per node: its index among the driving layer's unknowns, or −1 (fed)
  SparseMatrix F_without_contact_;
  Vector drive_without_contact_;
};

}  // namespace emit
