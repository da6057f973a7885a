#include "emit/fem/condensed_contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/fem/supernodal_cholesky.hpp"

namespace emit {

namespace {

/// Grows `m` to at least rows × cols (its contents are then undefined).
void reserve(Matrix& m, Index rows, Index cols) {
  if (m.rows() < rows || m.cols() < cols) m.resize(std::max(m.rows(), rows), std::max(m.cols(), cols));
}

constexpr int solve_block = 128;  // right-hand sides per solve while computing M

}  // namespace

CondensedContactSolver::CondensedContactSolver(const SparseMatrix& A0, const std::vector<Vector3>& position_mm,
                                               std::vector<int> kept, std::vector<int> unit_rhs, double cell_size_mm)
    : A0_(A0), kept_(std::move(kept)), unit_rhs_(std::move(unit_rhs)) {
  A0_.makeCompressed();
  const auto n = static_cast<int>(A0.rows());
  if (A0.cols() != n || static_cast<int>(position_mm.size()) != n)
    throw InvalidInput("condensed contact solver: A0 must be square with one position per dof");
  if (!(cell_size_mm > 0) || !std::isfinite(cell_size_mm))
    throw InvalidInput("condensed contact solver: the cell size must be positive");
  std::vector<char> on_skeleton(static_cast<std::size_t>(n), 0);
  for (const int d : kept_) {
    if (d < 0 || d >= n)
      throw InvalidInput("condensed contact solver: kept dof " + std::to_string(d) + " out of range");
    on_skeleton[static_cast<std::size_t>(d)] = 1;
  }
  for (const int k : unit_rhs_)
    if (k < 0 || k >= static_cast<int>(kept_.size()))
      throw InvalidInput("condensed contact solver: unit right-hand side " + std::to_string(k) + " out of range");

  // Cells: cubes of the grid over the dofs' positions; the kept dofs belong to none.
  Vector3 lowest = Vector3::Constant(std::numeric_limits<double>::infinity());
  for (const Vector3& p : position_mm) lowest = lowest.cwiseMin(p);
  constexpr std::int64_t span = std::int64_t{1} << 20;
  std::vector<std::int64_t> key(static_cast<std::size_t>(n), -1);
  for (int d = 0; d < n; ++d) {
    if (on_skeleton[static_cast<std::size_t>(d)]) continue;
    const Eigen::Array3d cell = ((position_mm[static_cast<std::size_t>(d)] - lowest) / cell_size_mm).array().floor();
    if (!(cell.maxCoeff() < static_cast<double>(span)))
      throw InvalidInput("condensed contact solver: the cell size is too small for the sheet");
    key[static_cast<std::size_t>(d)] =
        static_cast<std::int64_t>(cell.x()) +
        span * (static_cast<std::int64_t>(cell.y()) + span * static_cast<std::int64_t>(cell.z()));
  }
  // The skeleton: of every coupled pair in two cells, the one in the later cell, so no two cells'
  // interiors are coupled.
  for (int c = 0; c < n; ++c)
    for (SparseMatrix::InnerIterator it(A0, c); it; ++it) {
      const std::int64_t kr = key[static_cast<std::size_t>(it.row())], kc = key[static_cast<std::size_t>(c)];
      if (kr >= 0 && kc >= 0 && kr != kc) on_skeleton[static_cast<std::size_t>(kr > kc ? it.row() : c)] = 1;
    }

  // Number the skeleton and the cells' interiors.
  cell_of_.assign(static_cast<std::size_t>(n), -1);
  local_of_.assign(static_cast<std::size_t>(n), -1);
  std::vector<std::int64_t> keys;
  for (int d = 0; d < n; ++d)
    if (!on_skeleton[static_cast<std::size_t>(d)]) keys.push_back(key[static_cast<std::size_t>(d)]);
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  cells_.resize(keys.size());
  for (int d = 0; d < n; ++d) {
    if (on_skeleton[static_cast<std::size_t>(d)]) {
      local_of_[static_cast<std::size_t>(d)] = static_cast<int>(skeleton_.size());
      skeleton_.push_back(d);
      continue;
    }
    const auto j =
        static_cast<int>(std::lower_bound(keys.begin(), keys.end(), key[static_cast<std::size_t>(d)]) - keys.begin());
    Cell& cell = cells_[static_cast<std::size_t>(j)];
    cell_of_[static_cast<std::size_t>(d)] = j;
    local_of_[static_cast<std::size_t>(d)] = static_cast<int>(cell.interior.size());
    cell.interior.push_back(d);
  }
  for (Cell& cell : cells_) {
    for (const int d : cell.interior)
      for (SparseMatrix::InnerIterator it(A0, d); it; ++it)
        if (cell_of_[static_cast<std::size_t>(it.row())] < 0) cell.boundary.push_back(static_cast<int>(it.row()));
    std::sort(cell.boundary.begin(), cell.boundary.end());
    cell.boundary.erase(std::unique(cell.boundary.begin(), cell.boundary.end()), cell.boundary.end());
  }

  // M = A0⁻¹ on the skeleton, by solves in blocks.
  const auto m = static_cast<int>(skeleton_.size());
  SupernodalCholesky cholesky;
  cholesky.factorize(A0);
  M_.resize(m, m);
  Matrix units;
  for (int first = 0; first < m; first += solve_block) {
    const int count = std::min(solve_block, m - first);
    units.setZero(n, count);
    for (int k = 0; k < count; ++k)
      units(skeleton_[static_cast<std::size_t>(first) + static_cast<std::size_t>(k)], k) = 1;
    const Matrix solved = cholesky.solve(units);
    for (int k = 0; k < count; ++k)
      for (int s = 0; s < m; ++s) M_(s, first + k) = solved(skeleton_[static_cast<std::size_t>(s)], k);
  }

  // Each cell's contact-free condensation.
  boundary_pos_.assign(static_cast<std::size_t>(n), -1);
  for (Cell& cell : cells_) {
    const auto p = static_cast<Index>(cell.interior.size()), nb = static_cast<Index>(cell.boundary.size());
    for (Index a = 0; a < nb; ++a)
      boundary_pos_[static_cast<std::size_t>(cell.boundary[static_cast<std::size_t>(a)])] = static_cast<int>(a);
    assemble_cell(cell, nullptr, nullptr);
    Eigen::Ref<Matrix> II = work_II_.topLeftCorner(p, p);
    const Eigen::LLT<Eigen::Ref<Matrix>> llt(II);  // in place
    if (llt.info() != Eigen::Success) throw SolverError("condensed contact solver: A0 is not positive definite");
    reserve(work_Z_, p, nb);
    work_Z_.topLeftCorner(p, nb) = work_IB_.topLeftCorner(p, nb);
    llt.solveInPlace(work_Z_.topLeftCorner(p, nb));
    cell.H0.noalias() = work_IB_.topLeftCorner(p, nb).transpose() * work_Z_.topLeftCorner(p, nb);
    for (const int d : cell.boundary) boundary_pos_[static_cast<std::size_t>(d)] = -1;
  }

  q_pos_.assign(static_cast<std::size_t>(m), -1);
  entries_of_cell_.resize(cells_.size());
  rhs_.assign(static_cast<std::size_t>(n), 0.0);
  rhs_listed_.assign(static_cast<std::size_t>(n), 0);
}

void CondensedContactSolver::assemble_cell(const Cell& cell, const std::vector<Entry>* C,
                                           const std::vector<int>* entries) {
  const auto p = static_cast<Index>(cell.interior.size()), nb = static_cast<Index>(cell.boundary.size());
  reserve(work_II_, p, p);
  reserve(work_IB_, p, nb);
  auto II = work_II_.topLeftCorner(p, p);
  auto IB = work_IB_.topLeftCorner(p, nb);
  II.setZero();
  IB.setZero();
  const int j = cell_of_[static_cast<std::size_t>(cell.interior.front())];
  for (Index li = 0; li < p; ++li)
    for (SparseMatrix::InnerIterator it(A0_, cell.interior[static_cast<std::size_t>(li)]); it; ++it) {
      const auto r = static_cast<std::size_t>(it.row());
      if (cell_of_[r] == j) II(local_of_[r], li) = it.value();
      else IB(li, boundary_pos_[r]) = it.value();  // A0 is symmetric
    }
  if (!C) return;
  for (const int e : *entries) {
    const Entry& entry = (*C)[static_cast<std::size_t>(e)];
    const auto r = static_cast<std::size_t>(entry.row()), c = static_cast<std::size_t>(entry.col());
    if (cell_of_[r] != j) continue;  // (skeleton, interior): its mirror (interior, skeleton) is there too
    if (cell_of_[c] == j) II(local_of_[r], local_of_[c]) += entry.value();
    else if (boundary_pos_[c] >= 0) IB(local_of_[r], boundary_pos_[c]) += entry.value();
    else throw InvalidInput("condensed contact solver: a contact entry outside A0's pattern");
  }
}

void CondensedContactSolver::solve(const std::vector<Entry>& C, const std::vector<std::pair<int, double>>& b,
                                   Matrix& X) {
  const auto n = static_cast<int>(A0_.rows());
  const auto cols = static_cast<Index>(1 + unit_rhs_.size());
  // The scratch is left as found, whether this returns or throws.
  struct Reset {
    CondensedContactSolver& solver;
    explicit Reset(CondensedContactSolver& s) : solver(s) {}
    Reset(const Reset&) = delete;
    Reset& operator=(const Reset&) = delete;
    Reset(Reset&&) = delete;
    Reset& operator=(Reset&&) = delete;
    ~Reset() { solver.reset_scratch(); }
  } reset(*this);
  // The first right-hand side, summed per dof.
  for (const auto& [d, value] : b) {
    if (d < 0 || d >= n) throw InvalidInput("condensed contact solver: right-hand side dof out of range");
    if (!rhs_listed_[static_cast<std::size_t>(d)]) {
      rhs_listed_[static_cast<std::size_t>(d)] = 1;
      rhs_dofs_.push_back(d);
    }
    rhs_[static_cast<std::size_t>(d)] += value;
  }
  // The contact's entries, per cell they reach (or between skeleton dofs).
  for (std::size_t e = 0; e < C.size(); ++e) {
    const int r = C[e].row(), c = C[e].col();
    if (r < 0 || r >= n || c < 0 || c >= n) throw InvalidInput("condensed contact solver: contact dof out of range");
    const int cell = cell_of_[static_cast<std::size_t>(r)] >= 0 ? cell_of_[static_cast<std::size_t>(r)]
                                                                : cell_of_[static_cast<std::size_t>(c)];
    if (cell < 0) {
      const int* first = A0_.innerIndexPtr() + A0_.outerIndexPtr()[c];
      const int* last = A0_.innerIndexPtr() + A0_.outerIndexPtr()[c + 1];
      if (!std::binary_search(first, last, r))
        throw InvalidInput("condensed contact solver: a contact entry outside A0's pattern");
      skeleton_entries_.push_back(static_cast<int>(e));
      continue;
    }
    auto& list = entries_of_cell_[static_cast<std::size_t>(cell)];
    if (list.empty()) touched_cells_.push_back(cell);
    list.push_back(static_cast<int>(e));
  }
  for (const int d : rhs_dofs_)
    if (const int cell = cell_of_[static_cast<std::size_t>(d)];
        cell >= 0 && entries_of_cell_[static_cast<std::size_t>(cell)].empty())
      throw InvalidInput("condensed contact solver: a right-hand side off the contact and the kept dofs");

  // Q: the skeleton dofs round the reached cells and the contact's skeleton dofs (T, first), then
  // the kept ones.
  const auto add_q = [&](int dof) {
    const auto s = static_cast<std::size_t>(local_of_[static_cast<std::size_t>(dof)]);
    if (q_pos_[s] < 0) {
      q_pos_[s] = static_cast<int>(q_dofs_.size());
      q_dofs_.push_back(dof);
    }
  };
  for (const int cell : touched_cells_)
    for (const int d : cells_[static_cast<std::size_t>(cell)].boundary) add_q(d);
  for (const int e : skeleton_entries_)
    add_q(C[static_cast<std::size_t>(e)].row()), add_q(C[static_cast<std::size_t>(e)].col());
  for (const int d : rhs_dofs_)
    if (cell_of_[static_cast<std::size_t>(d)] < 0) add_q(d);
  const auto t = static_cast<Index>(q_dofs_.size());
  for (const int d : kept_) add_q(d);
  const auto q = static_cast<Index>(q_dofs_.size());
  const auto qpos = [&](int dof) { return q_pos_[static_cast<std::size_t>(local_of_[static_cast<std::size_t>(dof)])]; };

  reserve(delta_, t, t);
  reserve(Rq_, q, cols);
  auto delta = delta_.topLeftCorner(t, t);
  auto Rq = Rq_.topLeftCorner(q, cols);
  delta.setZero();
  Rq.setZero();
  // Eliminate each reached cell's interior: Δ += H0 − H, r −= A_BI A_II⁻¹ b_I.
  for (const int j : touched_cells_) {
    const Cell& cell = cells_[static_cast<std::size_t>(j)];
    const auto p = static_cast<Index>(cell.interior.size()), nb = static_cast<Index>(cell.boundary.size());
    for (Index a = 0; a < nb; ++a)
      boundary_pos_[static_cast<std::size_t>(cell.boundary[static_cast<std::size_t>(a)])] = static_cast<int>(a);
    assemble_cell(cell, &C, &entries_of_cell_[static_cast<std::size_t>(j)]);
    Eigen::Ref<Matrix> II = work_II_.topLeftCorner(p, p);
    const Eigen::LLT<Eigen::Ref<Matrix>> llt(II);  // in place
    if (llt.info() != Eigen::Success) throw SolverError("condensed contact solver: A0 + C is not positive definite");
    reserve(work_Z_, p, nb + 1);
    auto Z = work_Z_.topLeftCorner(p, nb + 1);
    Z.leftCols(nb) = work_IB_.topLeftCorner(p, nb);
    for (Index li = 0; li < p; ++li)
      Z(li, nb) = rhs_[static_cast<std::size_t>(cell.interior[static_cast<std::size_t>(li)])];
    llt.solveInPlace(Z);
    reserve(work_H_, nb, nb + 1);
    auto H = work_H_.topLeftCorner(nb, nb + 1);
    H.noalias() = work_IB_.topLeftCorner(p, nb).transpose() * Z;
    for (Index a = 0; a < nb; ++a) {
      const int qa = qpos(cell.boundary[static_cast<std::size_t>(a)]);
      for (Index c = 0; c < nb; ++c)
        delta(qa, qpos(cell.boundary[static_cast<std::size_t>(c)])) += cell.H0(a, c) - H(a, c);
      Rq(qa, 0) -= H(a, nb);
    }
    for (const int d : cell.boundary) boundary_pos_[static_cast<std::size_t>(d)] = -1;
  }
  for (const int e : skeleton_entries_) {
    const Entry& entry = C[static_cast<std::size_t>(e)];
    delta(qpos(entry.row()), qpos(entry.col())) += entry.value();
  }
  for (const int d : rhs_dofs_)
    if (cell_of_[static_cast<std::size_t>(d)] < 0) Rq(qpos(d), 0) += rhs_[static_cast<std::size_t>(d)];
  for (Index k = 1; k < cols; ++k)
    Rq(qpos(kept_[static_cast<std::size_t>(unit_rhs_[static_cast<std::size_t>(k - 1)])]), k) = 1;

  // Woodbury on Σ0⁻¹ = A0⁻¹ restricted to Q.
  reserve(Mq_, q, q);
  auto Mq = Mq_.topLeftCorner(q, q);
  for (Index k = 0; k < q; ++k) {
    const auto sk = local_of_[static_cast<std::size_t>(q_dofs_[static_cast<std::size_t>(k)])];
    for (Index i = 0; i < q; ++i)
      Mq(i, k) = M_(local_of_[static_cast<std::size_t>(q_dofs_[static_cast<std::size_t>(i)])], sk);
  }
  reserve(z_, q, cols);
  auto z = z_.topLeftCorner(q, cols);
  z.noalias() = Mq * Rq;
  if (t > 0) {
    reserve(K_, t, t);
    auto K = K_.topLeftCorner(t, t);
    K.noalias() = Mq.topLeftCorner(t, t) * delta;
    K.diagonal().array() += 1.0;
    Eigen::Ref<Matrix> K_ref = K;
    const Eigen::PartialPivLU<Eigen::Ref<Matrix>> lu(K_ref);  // in place: its pivots are all it allocates
    reserve(W_, t, cols);
    reserve(V_, t, cols);
    W_.topLeftCorner(t, cols) = lu.solve(z.topRows(t));
    V_.topLeftCorner(t, cols).noalias() = delta * W_.topLeftCorner(t, cols);
    z.noalias() -= Mq.leftCols(t) * V_.topLeftCorner(t, cols);
  }
  X.resize(static_cast<Index>(kept_.size()), cols);
  for (std::size_t i = 0; i < kept_.size(); ++i) X.row(static_cast<Index>(i)) = z.row(qpos(kept_[i]));
}

void CondensedContactSolver::reset_scratch() {
  for (const int dof : q_dofs_) q_pos_[static_cast<std::size_t>(local_of_[static_cast<std::size_t>(dof)])] = -1;
  q_dofs_.clear();
  for (const int d : rhs_dofs_) rhs_[static_cast<std::size_t>(d)] = 0, rhs_listed_[static_cast<std::size_t>(d)] = 0;
  rhs_dofs_.clear();
  for (const int j : touched_cells_) {
    entries_of_cell_[static_cast<std::size_t>(j)].clear();
    for (const int d : cells_[static_cast<std::size_t>(j)].boundary) boundary_pos_[static_cast<std::size_t>(d)] = -1;
  }
  touched_cells_.clear();
  skeleton_entries_.clear();
}

}  // namespace emit
