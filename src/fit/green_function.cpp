#include "emit/fit/green_function.hpp"

#include <algorithm>

#include "emit/errors.hpp"
#include "emit/fem/sparse_cholesky.hpp"
#include "emit/fem/stiffness.hpp"

namespace emit {

DenseGreenFunction dense_green_function(const Mesh& mesh, double sheet_resistance_ohm_per_sq,
                                        const std::function<void(double)>& progress) {
  if (!(sheet_resistance_ohm_per_sq > 0)) throw InvalidInput("sheet resistance must be positive");
  DenseGreenFunction green{number_electrode_dofs(mesh), {}};
  const int n = green.dofs.dof_count;
  const SparseMatrix K = to_dof_space(assemble_stiffness(mesh, 1.0 / sheet_resistance_ohm_per_sq), green.dofs);
  const SparseMatrix A0 = K.bottomRightCorner(n - 1, n - 1);  // electrode 0 grounded
  SparseCholesky cholesky;
  cholesky.analyze(A0);
  cholesky.factorize(A0);
  green.G0 = Matrix::Zero(n, n);
  constexpr int block = 256;  // columns of the identity solved at once: bounded extra memory
  for (int first = 0; first < n - 1; first += block) {
    const int count = std::min(block, n - 1 - first);
    Matrix unit = Matrix::Zero(n - 1, count);
    for (int k = 0; k < count; ++k) unit(first + k, k) = 1.0;
    green.G0.block(1, 1 + first, n - 1, count) = cholesky.solve(unit);
    if (progress) progress(static_cast<double>(first + count) / (n - 1));
  }
  return green;
}

}  // namespace emit
