#pragma once
/// \file forward_model.hpp
/// The forward model (docs/physics.md, "Forward model"; paper eqs. 1–2): -div(σ ∇u) + g u = g E on the sheet, one
/// electrode grounded, every other electrode one floating unknown with zero net current, insulating elsewhere.
///
/// Per contact it factorises once (electrode 0 grounded) and gets all N groundings from N solves:
/// for ground l ≠ 0 the solution is u = c·1 + v, with v the electrode-0-grounded solution of a
/// drive (E − c) plus a current I drained at electrode l; u(e_l) = 0 and zero net current at
/// electrode 0 fix (c, I) by a 2×2 solve. This works because K·1 = 0, so shifting u by c is the
/// same as lowering the drive by c.
///
/// Optionally each electrode reaches ground through a series resistance R_l (its contact and the
/// multiplexer's switch): a sensing electrode draws no current, so it reads its potential as
/// before; the grounded one sits at u(e_l) = I_out·R_l, I_out the current it drains.
#include <memory>
#include <optional>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/fem/contact_load.hpp"
#include "emit/fem/driving_layer.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

class ForwardModel {
 public:
  /// Assembles the stiffness once and analyses its pattern (assemble once, solve many).
  /// \throw InvalidInput for a mesh whose electrodes are not usable.
  ForwardModel(Mesh mesh, double sheet_resistance_ohm_per_sq);
  /// A sheet whose conductance varies: one value per triangle [S] (1 / its sheet resistance),
  /// and optionally a driving layer with its own resistance (driving_layer.hpp) instead of an
  /// equipotential one; with it, every contact costs a symbolic analysis as well.
  ForwardModel(Mesh mesh, const Vector& element_conductance_S, const std::optional<DrivingLayer>& driving = {});
  ~ForwardModel();
  ForwardModel(ForwardModel&&) noexcept;
  ForwardModel& operator=(ForwardModel&&) noexcept;
  ForwardModel(const ForwardModel&) = delete;  // move-only: it owns its factor
  ForwardModel& operator=(const ForwardModel&) = delete;

  const Mesh& mesh() const;
  int electrode_count() const;

  /// Each electrode's series resistance to ground when grounded [Ω], one per electrode (empty:
  /// none, an ideal ground). The frame's diagonal (the board's reading of its grounded line)
  /// stays 0. \throw InvalidInput for a wrong count or a negative or non-finite value.
  void set_series_resistance(std::vector<double> ohm);

  /// From now on solve_frame condenses each contact onto a skeleton of the mesh
  /// (condensed_contact_solver.hpp) instead of factorising the sheet: the same frame to rounding,
  /// several times faster on a fine mesh, for a setup of one factorisation and m solves and m²
  /// doubles, m the skeleton's dofs (~15 % of them). `cell_size_mm`: the cells' edge; 0: 12 mean
  /// edge lengths. solve_potentials still factorises. \throw InvalidInput with a resistive
  /// driving layer (its coupling's pattern follows the contact) or a negative cell size.
  void condense_contacts(double cell_size_mm = 0);
  bool condensed() const;
  /// The skeleton's dofs (m above; 0 before condense_contacts).
  int condensed_skeleton_size() const;

  /// Electrode potentials for every grounding. An empty contact gives the zero frame. A solve
  /// factorises into the model's own workspace (the stiffness and its analysis stay as they
  /// are), so it is not const: one ForwardModel solves on one thread at a time.
  Frame solve_frame(const ContactLoad& contact, double drive_voltage_V);
  /// Node potentials [V], #V by N: column l is the field with electrode l grounded.
  Matrix solve_potentials(const ContactLoad& contact, double drive_voltage_V);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace emit
