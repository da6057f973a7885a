#include "emit/frame/masked_readings.hpp"

#include <algorithm>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/core/small_cholesky.hpp"

namespace emit {

MaskedReadingFill::MaskedReadingFill(Index readings, Index max_masked)
    : factor_(std::min(max_masked, readings), std::min(max_masked, readings)), rhs_(std::min(max_masked, readings)) {}

void MaskedReadingFill::fill(const Eigen::MatrixXf& precision, const std::vector<Index>& masked, Vector& dV) {
  const auto k = static_cast<Index>(masked.size());
  if (k == 0) return;
  if (precision.rows() != dV.size() || precision.cols() != dV.size())
    throw InvalidInput("masked readings: a precision of " + std::to_string(precision.rows()) + " by " +
                       std::to_string(precision.cols()) + " for " + std::to_string(dV.size()) + " readings");
  if (k > max_masked())
    throw InvalidInput("masked readings: " + std::to_string(k) + " masked, at most " + std::to_string(max_masked()));
  for (const Index m : masked) dV(m) = 0;
  // rhs = −P_𝓜𝓤 δV_𝓤 (δV is 0 on 𝓜), then P_𝓜𝓜 δV̂_𝓜 = rhs. P is symmetric: its columns are its
  // rows, contiguous in column-major storage.
  auto rhs = rhs_.head(k);
  for (Index i = 0; i < k; ++i) rhs(i) = -precision.col(masked[static_cast<std::size_t>(i)]).cast<double>().dot(dV);
  auto L = factor_.topLeftCorner(k, k);
  small_cholesky(
      k,
      [&](Index i, Index j) {
        return static_cast<double>(precision(masked[static_cast<std::size_t>(i)], masked[static_cast<std::size_t>(j)]));
      },
      L);
  small_cholesky_solve(L, rhs);
  for (Index i = 0; i < k; ++i) dV(masked[static_cast<std::size_t>(i)]) = rhs(i);
}

}  // namespace emit
