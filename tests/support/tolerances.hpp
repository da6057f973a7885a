#pragma once
// Every tolerance the tests use, with the reason for it, in one place.
#include <limits>

namespace emit::test {

constexpr double machine_epsilon = std::numeric_limits<double>::epsilon();
/// Identities of assembled operators (K·1 = 0, symmetry): sums of O(10) terms of size ~1 per row,
/// so a few hundred ulps.
constexpr double operator_identity = 1e3 * machine_epsilon;
/// Solutions through a sparse Cholesky factorisation of a well-conditioned (grounded, cond ~1e5)
/// system: cond × eps with margin.
constexpr double solve_roundoff = 1e-9;
/// P1 elements converge at O(h²) in nodal values for smooth solutions; observed rates on
/// unstructured or structured meshes stray a little from 2 (pre-asymptotic terms).
constexpr double min_convergence_rate = 1.8;
/// The conformance README: a correct twin on a reasonable mesh agrees with the independent
/// implementation to about 1 % of the largest potential.
constexpr double conformance_fraction_of_max = 0.01;

}  // namespace emit::test
