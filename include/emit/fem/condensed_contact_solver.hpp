#pragma once
/// \file condensed_contact_solver.hpp
/// Solves (A0 + C) X = B for a fixed sparse SPD A0 and a contact C that changes every call, on a
/// few hundred of A0's n dofs, without factorising A0 + C: the twin's frames as fast as a live
/// source needs them (docs/physics.md, "The digital twin", "Frames at a board's pace").
///
/// The dofs are cut into cells (a grid of cubes over their positions) by a skeleton: the dofs with
/// a neighbour in another cell (one side of every cut edge), and the kept dofs (those whose
/// solution is wanted, and any that must not be eliminated). No two cells' interiors touch, so
/// eliminating the interiors of the cells C reaches leaves the rest (R: the skeleton and the other
/// cells) with the Schur complement Σ = A_RR − A_RI A_II⁻¹ A_IR, which differs from the contact-free
/// one Σ0 only on the skeleton dofs T around those cells: Σ = Σ0 + E_T Δ E_Tᵀ, with
/// Δ = C_TT − H + H0 (H, H0: each reached cell's A_TI A_II⁻¹ A_IT with and without the contact,
/// dense on the cell, O(p³) for p of its dofs). Σ0⁻¹ is A0⁻¹ on R (the block inverse), so with
/// M = A0⁻¹ on the skeleton, computed once, Woodbury gives
///
///     X_Q = z − M_QT Δ (I + M_TT Δ)⁻¹ z_T,   z = M_Q· r,   r = B_R − A_RI A_II⁻¹ B_I,
///
/// on Q = T ∪ kept: O(t³ + q²·k) for t skeleton dofs round the contact and k right-hand sides,
/// where a factorisation of A0 + C costs the whole sheet. Exact up to rounding (the same system,
/// eliminated in another order).
///
/// Setup: one factorisation of A0 and m solves, m the skeleton's dofs (~15 % of n at 150 dofs a
/// cell); M takes m² doubles: measured 2,031 for 13.6k nodes, 33 MB, 1.1 s on the default twin; 3,058
/// for 20.1k, 75 MB, 1.9 s on the sleeve's (bench/twin_bench.cpp, BM_TwinCondense).
#include <vector>

#include <Eigen/Dense>

#include "emit/core/types.hpp"

namespace emit {

class CondensedContactSolver {
 public:
  using Entry = Eigen::Triplet<double, int>;

  /// \param A0           n×n, symmetric positive definite, both triangles stored.
  /// \param position_mm  where each dof is (n points), for cutting them into cells.
  /// \param kept         dofs always on the skeleton, whose solution solve() returns, in this order.
  /// \param unit_rhs     positions in `kept` whose unit vectors are right-hand sides 1… of solve().
  /// \param cell_size_mm the cells' edge; ~12 mean edge lengths gives ~150 dofs a cell.
  /// \throw InvalidInput for mismatched sizes or a non-positive cell size; SolverError if A0 is
  /// not positive definite.
  CondensedContactSolver(const SparseMatrix& A0, const std::vector<Vector3>& position_mm, std::vector<int> kept,
                         std::vector<int> unit_rhs, double cell_size_mm);

  int skeleton_size() const { return static_cast<int>(skeleton_.size()); }
  int cell_count() const { return static_cast<int>(cells_.size()); }

  /// X (kept.size() × (1 + unit_rhs.size()), resized) = the solution of (A0 + C) X = B on the kept
  /// dofs. C: entries (row, col, value) in any order, repeats summed, symmetric (both (r, c) and
  /// (c, r) given), positive semi-definite. B's column 0: `b` as (dof, value), repeats summed,
  /// non-zero only on C's rows and the kept dofs; column j ≥ 1: the unit vector at kept[unit_rhs[j − 1]].
  /// Not thread-safe: it works in scratch of its own, kept between calls (grown when a contact
  /// reaches more than any before; the LU's pivots are the only allocation a call makes).
  void solve(const std::vector<Entry>& C, const std::vector<std::pair<int, double>>& b, Matrix& X);

 private:
  struct Cell {
    std::vector<int> interior;  ///< dofs, ascending
    std::vector<int> boundary;  ///< skeleton dofs adjacent to the interior, ascending
    Matrix H0;                  ///< A_BI A_II⁻¹ A_IB without contact (boundary × boundary)
  };
  /// The cell's A_II and A_IB (+ the contact's entries in `entries`) into work_II_, work_IB_;
  /// boundary_pos_ must hold this cell's boundary positions.
  void assemble_cell(const Cell& cell, const std::vector<Entry>* C, const std::vector<int>* entries);
  void reset_scratch();

  SparseMatrix A0_;
  std::vector<int> kept_, unit_rhs_;
  std::vector<int> cell_of_;   ///< per dof: its cell, −1 on the skeleton
  std::vector<int> local_of_;  ///< per dof: its index in its cell's interior, or on the skeleton
  std::vector<int> skeleton_;  ///< skeleton dofs, ascending; M's order
  std::vector<Cell> cells_;
  Matrix M_;  ///< A0⁻¹ on the skeleton, m × m

  // Scratch, per solve.
  std::vector<int> boundary_pos_;  ///< per dof: its index in the current cell's boundary, −1 otherwise
  std::vector<int> q_pos_;         ///< per skeleton index: its position in Q, −1 otherwise
  std::vector<int> touched_cells_, q_dofs_;
  std::vector<std::vector<int>> entries_of_cell_;  ///< per cell: indices into C
  std::vector<int> skeleton_entries_;              ///< C's entries with both dofs on the skeleton
  std::vector<double> rhs_;                        ///< per dof: b, summed
  std::vector<char> rhs_listed_;                   ///< per dof: in rhs_dofs_
  std::vector<int> rhs_dofs_;
  Matrix work_II_, work_IB_, work_Z_, work_H_, delta_, Mq_, Rq_, z_, K_, W_, V_;
};

}  // namespace emit
