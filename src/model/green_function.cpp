#include "emit/model/green_function.hpp"

#include <algorithm>

#include "emit/core/errors.hpp"
#include "emit/fem/sparse_cholesky.hpp"
#include "emit/fem/stiffness.hpp"

namespace emit {

DenseGreenFunction dense_green_function(const Mesh& mesh, double sheet_resistance_ohm_per_sq,
                                        const std::function<void(double)>& progress) {
  if (!(sheet_resistance_ohm_per_sq > 0)) throw InvalidInput("sheet resistance must be positive");
  return dense_green_function(mesh, Vector::Constant(mesh.triangle_count(), 1.0 / sheet_resistance_ohm_per_sq), {},
                              progress);
}

namespace {

/// A0, the dof-space stiffness with electrode 0 grounded, factorised.
SparseCholesky grounded_factor(const Mesh& mesh, const Vector& element_conductance_S, const ElectrodeDofs& dofs) {
  if (element_conductance_S.size() != mesh.triangle_count() || !(element_conductance_S.array() > 0).all())
    throw InvalidInput("Green's function: one positive sheet conductance per triangle is needed");
  const int n = dofs.dof_count;
  const SparseMatrix K = to_dof_space(assemble_stiffness(mesh, element_conductance_S), dofs);
  const SparseMatrix A0 = K.bottomRightCorner(n - 1, n - 1);  // electrode 0 grounded
  SparseCholesky cholesky;
  cholesky.analyze(A0);
  cholesky.factorize(A0);
  return cholesky;
}

}  // namespace

DenseGreenFunction dense_green_function(const Mesh& mesh, const Vector& element_conductance_S,
                                        const std::vector<int>& only_dofs,
                                        const std::function<void(double)>& progress) {
  DenseGreenFunction green{number_electrode_dofs(mesh), {}, {}, {}};
  const int n = green.dofs.dof_count;
  const SparseCholesky cholesky = grounded_factor(mesh, element_conductance_S, green.dofs);
  std::vector<int> columns;  // every dof, or the asked ones and the ground
  if (only_dofs.empty()) {
    for (int dof = 0; dof < n; ++dof) columns.push_back(dof);
  } else {
    columns = only_dofs;
    columns.push_back(0);
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    if (columns.front() < 0 || columns.back() >= n) throw InvalidInput("Green's function: a dof out of range");
    green.column_of_dof.assign(static_cast<std::size_t>(n), -1);
    for (std::size_t c = 0; c < columns.size(); ++c)
      green.column_of_dof[static_cast<std::size_t>(columns[c])] = static_cast<int>(c);
  }
  const int solved = static_cast<int>(columns.size()) - 1;  // column 0 (the ground) stays 0
  green.G0 = Matrix::Zero(n, solved + 1);
  constexpr int block = 256;  // columns of the identity solved at once: bounded extra memory
  for (int first = 0; first < solved; first += block) {
    const int count = std::min(block, solved - first);
    Matrix unit = Matrix::Zero(n - 1, count);
    for (int k = 0; k < count; ++k)
      unit(columns[1 + static_cast<std::size_t>(first) + static_cast<std::size_t>(k)] - 1, k) = 1.0;
    green.G0.block(1, 1 + first, n - 1, count) = cholesky.solve(unit);
    if (progress) progress(static_cast<double>(first + count) / solved);
  }
  return green;
}

DenseGreenFunction blockwise_green_function(const Mesh& mesh, const Vector& element_conductance_S,
                                            const std::vector<std::vector<int>>& blocks) {
  DenseGreenFunction green{number_electrode_dofs(mesh), {}, {}, {}};
  const int n = green.dofs.dof_count, N = green.dofs.electrode_count;
  const SparseCholesky cholesky = grounded_factor(mesh, element_conductance_S, green.dofs);
  green.row_of_dof.assign(static_cast<std::size_t>(n), -1);
  int kept = 0;
  for (int e = 0; e < N; ++e) green.row_of_dof[static_cast<std::size_t>(e)] = kept++;  // electrode e is dof e
  for (const std::vector<int>& block : blocks)
    for (const int dof : block) {
      if (dof < 0 || dof >= n) throw InvalidInput("Green's function: a dof out of range");
      if (green.row_of_dof[static_cast<std::size_t>(dof)] < 0) green.row_of_dof[static_cast<std::size_t>(dof)] = kept++;
    }
  green.column_of_dof = green.row_of_dof;
  green.G0 = Matrix::Zero(kept, kept);
  std::vector<int> block_dofs, index;  // the block's dofs but the ground, and their rows of A0
  for (const std::vector<int>& block : blocks) {
    block_dofs.clear();
    for (int e = 1; e < N; ++e) block_dofs.push_back(e);
    for (const int dof : block)
      if (dof >= N) block_dofs.push_back(dof);
    std::sort(block_dofs.begin(), block_dofs.end());
    block_dofs.erase(std::unique(block_dofs.begin(), block_dofs.end()), block_dofs.end());
    index.resize(block_dofs.size());
    std::transform(block_dofs.begin(), block_dofs.end(), index.begin(), [](int dof) { return dof - 1; });
    const Matrix inverse = cholesky.inverse_block(index);
    for (std::size_t b = 0; b < block_dofs.size(); ++b)
      for (std::size_t a = 0; a < block_dofs.size(); ++a)
        green.G0(green.row(block_dofs[a]), green.row(block_dofs[b])) =
            inverse(static_cast<Index>(a), static_cast<Index>(b));
  }
  return green;
}

}  // namespace emit
