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

DenseGreenFunction dense_green_function(const Mesh& mesh, const Vector& element_conductance_S,
                                        const std::vector<int>& only_dofs,
                                        const std::function<void(double)>& progress) {
  if (element_conductance_S.size() != mesh.triangle_count() || !(element_conductance_S.array() > 0).all())
    throw InvalidInput("Green's function: one positive sheet conductance per triangle is needed");
  DenseGreenFunction green{number_electrode_dofs(mesh), {}, {}};
  const int n = green.dofs.dof_count;
  const SparseMatrix K = to_dof_space(assemble_stiffness(mesh, element_conductance_S), green.dofs);
  const SparseMatrix A0 = K.bottomRightCorner(n - 1, n - 1);  // electrode 0 grounded
  SparseCholesky cholesky;
  cholesky.analyze(A0);
  cholesky.factorize(A0);
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

}  // namespace emit
