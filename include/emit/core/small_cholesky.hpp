#pragma once
/// \file small_cholesky.hpp
/// A small symmetric positive definite system A·x = b solved in scratch sized once, for the
/// per-frame path: Eigen's LLT allocates on every factorisation, and the k×k blocks here (a frame's
/// few masked readings) are too small for a library's call to pay.
///
///   small_cholesky(k, entry, L);   // A = L·Lᵀ, A(i, j) = entry(i, j), L's top-left k×k
///   small_cholesky_solve(L, x);    // x ← A⁻¹x, x of size k
///
/// A pivot that is not positive (A only semi-definite, round-off) is held at a tiny positive value
/// rather than failing: the callers' blocks are principal blocks of a positive definite matrix.
#include <algorithm>
#include <cmath>

#include "emit/core/types.hpp"

namespace emit {

/// L's lower k×k triangle ← the Cholesky factor of A(i, j) = entry(i, j), i, j < k. L at least k×k;
/// only A's lower triangle (j ≤ i) is read.
template <class Entry, class Scratch>
void small_cholesky(Index k, const Entry& entry, Scratch& L) {
  for (Index i = 0; i < k; ++i)
    for (Index j = 0; j <= i; ++j) {
      double s = entry(i, j);
      for (Index l = 0; l < j; ++l) s -= L(i, l) * L(j, l);
      L(i, j) = i == j ? std::sqrt(std::max(s, 1e-300)) : s / L(j, j);
    }
}

/// x ← (L·Lᵀ)⁻¹x, k = x.size(), L from small_cholesky.
template <class Factor, class Values>
void small_cholesky_solve(const Factor& L, Values& x) {
  const Index k = x.size();
  for (Index i = 0; i < k; ++i) {
    double s = x(i);
    for (Index l = 0; l < i; ++l) s -= L(i, l) * x(l);
    x(i) = s / L(i, i);
  }
  for (Index i = k; i-- > 0;) {
    double s = x(i);
    for (Index l = i + 1; l < k; ++l) s -= L(l, i) * x(l);
    x(i) = s / L(i, i);
  }
}

}  // namespace emit
