#include "emit/fem/supernodal_cholesky.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <cblas.h>
#include <suitesparse/cholmod.h>

#include "emit/core/errors.hpp"
#include "emit/core/large_matrix.hpp"

extern "C" void dpotri_(const char* uplo, const int* n, double* a, const int* lda, int* info);

namespace emit {

struct SupernodalCholesky::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  SparseMatrix lower;  ///< the factorised matrix's lower triangle: CHOLMOD's input, and the
                       ///< pattern selected_inverse returns

  Impl() {
    cholmod_start(&common);
    common.print = 0;  // errors reach the caller as SolverError, not as CHOLMOD's messages on stderr
  }
  ~Impl() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  /// `lower` seen by CHOLMOD as a symmetric matrix (stype −1: lower triangle stored), no copy.
  cholmod_sparse view() {
    cholmod_sparse A{};
    A.nrow = A.ncol = static_cast<std::size_t>(lower.rows());
    A.nzmax = static_cast<std::size_t>(lower.nonZeros());
    A.p = lower.outerIndexPtr();
    A.i = lower.innerIndexPtr();
    A.x = lower.valuePtr();
    A.stype = -1;
    A.itype = CHOLMOD_INT;
    A.xtype = CHOLMOD_REAL;
    A.dtype = CHOLMOD_DOUBLE;
    A.sorted = 1;
    A.packed = 1;
    return A;
  }
};

SupernodalCholesky::SupernodalCholesky() : impl_(std::make_unique<Impl>()) {}
SupernodalCholesky::~SupernodalCholesky() = default;
SupernodalCholesky::SupernodalCholesky(SupernodalCholesky&&) noexcept = default;
SupernodalCholesky& SupernodalCholesky::operator=(SupernodalCholesky&&) noexcept = default;

void SupernodalCholesky::factorize(const SparseMatrix& matrix) {
  Impl& m = *impl_;
  m.lower = matrix.triangularView<Eigen::Lower>();
  m.lower.makeCompressed();
  if (m.factor) cholmod_free_factor(&m.factor, &m.common);
  m.common.supernodal = CHOLMOD_SUPERNODAL;  // dense blocks for selected inversion's BLAS
  // CHOLMOD's default ordering: AMD, and METIS only if AMD's fill is high. On the default
  // sensor AMD won (92k triangles: analysis 0.03 s, factor + selected inversion 0.36 s;
  // METIS 0.22 s and 0.48 s).
  cholmod_sparse A = m.view();
  m.factor = cholmod_analyze(&A, &m.common);
  if (!m.factor) throw SolverError("supernodal Cholesky: CHOLMOD's analysis failed");
  cholmod_factorize(&A, m.factor, &m.common);
  if (m.common.status == CHOLMOD_NOT_POSDEF || m.factor->minor < m.factor->n)
    throw SolverError("supernodal Cholesky: the matrix is not positive definite (is an electrode disconnected?)");
  if (m.common.status != CHOLMOD_OK || !m.factor->is_super)
    throw SolverError("supernodal Cholesky: CHOLMOD's factorisation failed, status " + std::to_string(m.common.status));
}

Matrix SupernodalCholesky::solve(const Matrix& rhs) const {
  Impl& m = *impl_;
  if (!m.factor) throw std::logic_error("SupernodalCholesky::solve before factorize");
  cholmod_dense B{};
  B.nrow = static_cast<std::size_t>(rhs.rows());
  B.ncol = static_cast<std::size_t>(rhs.cols());
  B.nzmax = B.d = B.nrow;
  B.nzmax *= B.ncol;
  B.x = const_cast<double*>(rhs.data());  // read only: cholmod_solve returns a new matrix
  B.xtype = CHOLMOD_REAL;
  B.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* X = cholmod_solve(CHOLMOD_A, m.factor, &B, &m.common);
  if (!X) throw SolverError("supernodal Cholesky: CHOLMOD's solve failed");
  Matrix result = Eigen::Map<const Matrix>(static_cast<const double*>(X->x), rhs.rows(), rhs.cols());
  cholmod_free_dense(&X, &m.common);
  return result;
}

namespace {

/// The supernodal factor's layout (CHOLMOD's L->super, pi, px, s): supernode K holds columns
/// super[K]..super[K+1]−1 as one dense column-major block of rows s[pi[K]..pi[K+1]) (sorted;
/// its own columns first) at x[px[K]].
struct Supernodes {
  const int *super, *pi, *px, *s;
  int count;
  std::vector<int> of_column;  ///< the supernode holding each column

  explicit Supernodes(const cholmod_factor& L)
      : super(static_cast<const int*>(L.super)),
        pi(static_cast<const int*>(L.pi)),
        px(static_cast<const int*>(L.px)),
        s(static_cast<const int*>(L.s)),
        count(static_cast<int>(L.nsuper)),
        of_column(L.n) {
    for (int K = 0; K < count; ++K) std::fill(of_column.begin() + super[K], of_column.begin() + super[K + 1], K);
  }
  int columns(int K) const { return super[K + 1] - super[K]; }
  int rows(int K) const { return pi[K + 1] - pi[K]; }
  /// Position of row r in supernode K's rows (r must be one of them).
  int position(int K, int r) const {
    if (r < super[K + 1]) return r - super[K];
    const int* first = s + pi[K] + columns(K);
    return static_cast<int>(std::lower_bound(first, s + pi[K + 1], r) - (s + pi[K]));
  }
};

/// Z(R, R) for the rows R below a supernode, lower triangle, gathered from the blocks of
/// Z = (LLᵀ)⁻¹ already swept: each column j ∈ R lies in a later supernode J whose rows hold
/// every later row of R (the structure of a column contains that of its descendants).
void gather_below(const Supernodes& sn, const double* z, const int* R, int nr, std::vector<int>& position,
                  double* Zrr) {
  int filled = -1;  // the supernode whose rows `position` currently maps
  for (int b = 0; b < nr; ++b) {
    const int j = R[b], J = sn.of_column[j];
    if (J != filled) {
      for (int p = 0; p < sn.rows(J); ++p) position[sn.s[sn.pi[J] + p]] = p;
      filled = J;
    }
    const double* column = z + sn.px[J] + static_cast<std::ptrdiff_t>(j - sn.super[J]) * sn.rows(J);
    for (int a = b; a < nr; ++a) Zrr[a + static_cast<std::ptrdiff_t>(b) * nr] = column[position[R[a]]];
  }
}

}  // namespace

SparseMatrix SupernodalCholesky::selected_inverse() const {
  const Impl& m = *impl_;
  if (!m.factor) throw std::logic_error("SupernodalCholesky::selected_inverse before factorize");
  const cholmod_factor& L = *m.factor;
  const Supernodes sn(L);
  const auto* l = static_cast<const double*>(L.x);
  // Z on the factor's blocks, same layout as L (26 MB at 93k triangles: huge pages, as J's).
  auto z = large_matrix<Vector>(static_cast<Index>(L.xsize), 1);
  std::vector<double> Y, Zrr;  // scratch: L_RC L_CC⁻¹ and Z(R, R)
  std::vector<int> position(L.n);
  // Block Takahashi, supernodes from the last: for columns C and the rows R below them,
  // with Y = L_RC L_CC⁻¹:  Z_RC = −Z_RR Y,  Z_CC = (L_CC L_CCᵀ)⁻¹ − Z_RCᵀ Y.
  for (int K = sn.count - 1; K >= 0; --K) {
    const int nc = sn.columns(K), ns = sn.rows(K), nr = ns - nc;
    const double* LK = l + sn.px[K];
    double* ZK = z.data() + sn.px[K];
    if (nr > 0) {
      Y.resize(static_cast<std::size_t>(nr) * nc);
      for (int c = 0; c < nc; ++c)
        std::copy_n(LK + nc + static_cast<std::ptrdiff_t>(c) * ns, nr, Y.data() + static_cast<std::ptrdiff_t>(c) * nr);
      cblas_dtrsm(CblasColMajor, CblasRight, CblasLower, CblasNoTrans, CblasNonUnit, nr, nc, 1.0, LK, ns, Y.data(), nr);
      Zrr.resize(static_cast<std::size_t>(nr) * nr);
      gather_below(sn, z.data(), sn.s + sn.pi[K] + nc, nr, position, Zrr.data());
      cblas_dsymm(CblasColMajor, CblasLeft, CblasLower, nr, nc, -1.0, Zrr.data(), nr, Y.data(), nr, 0.0, ZK + nc, ns);
    }
    for (int c = 0; c < nc; ++c)
      std::copy_n(LK + static_cast<std::ptrdiff_t>(c) * ns, nc, ZK + static_cast<std::ptrdiff_t>(c) * ns);
    int info = 0;
    dpotri_("L", &nc, ZK, &ns, &info);
    if (info != 0) throw SolverError("selected inversion: LAPACK dpotri failed, info " + std::to_string(info));
    if (nr > 0)
      cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, nc, nc, nr, -1.0, ZK + nc, ns, Y.data(), nr, 1.0, ZK, ns);
  }
  // Back to A's ordering on A's pattern: A⁻¹(Perm[i], Perm[j]) = Z(i, j).
  const auto* perm = static_cast<const int*>(L.Perm);
  std::vector<int> inverse(L.n);
  for (int i = 0; i < static_cast<int>(L.n); ++i) inverse[perm[i]] = i;
  SparseMatrix result = m.lower;
  for (int col = 0; col < result.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(result, col); it; ++it) {
      const int a = inverse[it.row()], b = inverse[col];
      const int r = std::max(a, b), c = std::min(a, b), J = sn.of_column[c];
      it.valueRef() = z[sn.px[J] + sn.position(J, r) + (c - sn.super[J]) * sn.rows(J)];
    }
  return result;
}

}  // namespace emit
