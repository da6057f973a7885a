#include "emit/model/symmetric_eigen.hpp"

#include <string>
#include <vector>

#include "emit/core/errors.hpp"

extern "C" void dsyevd_(const char* jobz, const char* uplo, const int* n, double* a, const int* lda, double* w,
                        double* work, const int* lwork, int* iwork, const int* liwork, int* info);

namespace emit {

SymmetricEigen symmetric_eigen(Matrix A) {
  const int n = static_cast<int>(A.rows());
  if (A.cols() != A.rows()) throw InvalidInput("symmetric_eigen: the matrix is not square");
  SymmetricEigen result;
  result.values.resize(n);
  if (n == 0) return result;
  int info = 0, lwork = -1, liwork = -1, iwork_size = 0;
  double work_size = 0;
  dsyevd_("V", "L", &n, A.data(), &n, result.values.data(), &work_size, &lwork, &iwork_size, &liwork, &info);
  lwork = static_cast<int>(work_size);
  liwork = iwork_size;
  std::vector<double> work(static_cast<std::size_t>(lwork));
  std::vector<int> iwork(static_cast<std::size_t>(liwork));
  dsyevd_("V", "L", &n, A.data(), &n, result.values.data(), work.data(), &lwork, iwork.data(), &liwork, &info);
  if (info != 0) throw SolverError("symmetric eigenproblem (LAPACK dsyevd) failed, info " + std::to_string(info));
  result.vectors = std::move(A);
  return result;
}

}  // namespace emit
