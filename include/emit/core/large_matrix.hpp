#pragma once
/// \file large_matrix.hpp
/// Dense matrices of tens to hundreds of MiB (the Jacobian, the operator's factors) whose
/// memory the kernel may back with 2 MiB transparent huge pages.
///
/// Why: the first touch of each 4 KiB page is a page fault, and on our (virtualised) 2-core
/// machine one costs about 24 µs: zeroing 45 MiB, the Jacobian at 24k triangles, took 0.28 s in
/// 4 KiB pages and 0.02–0.05 s once advised (0.15 s when the kernel first compacts memory);
/// 800 MiB (100k triangles, 32 electrodes) 3.6–5.4 s against 0.23 s. Debian's default
/// transparent-huge-page mode is "madvise", so a region gets huge pages only when asked.
#include <cstddef>

#include "emit/core/types.hpp"

namespace emit {

/// Asks the kernel for huge pages on the whole 2 MiB pages inside [data, data + bytes), before
/// they are touched. Only advice: ignored where unsupported, and the memory stays the caller's.
void advise_huge_pages(void* data, std::size_t bytes);

/// An uninitialised rows × cols dense Eigen matrix (Matrix, Eigen::MatrixXf), advised as above.
template <class DenseMatrix = Matrix>
DenseMatrix large_matrix(Index rows, Index cols) {
  DenseMatrix matrix(rows, cols);
  advise_huge_pages(matrix.data(), sizeof(typename DenseMatrix::Scalar) * static_cast<std::size_t>(matrix.size()));
  return matrix;
}

}  // namespace emit
