#pragma once
/// \file types.hpp
/// The numeric types used across emit, in one place (Eigen-based).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>

namespace emit {

using Index = Eigen::Index;
using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;
using Vector2 = Eigen::Vector2d;
using Vector3 = Eigen::Vector3d;
/// Column-major sparse matrix with int indices, the layout sparse direct solvers expect.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
/// One frame: N×N volts, row l = grounded electrode, column m = sensed electrode. Row-major, so
/// data() is the ground-major order l·N + m of the frame files (README, "Files").
using Frame = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
/// A frame held elsewhere (a numpy array, a block of frames), read in place: N×N ground-major
/// values, contiguous.
using FrameView = Eigen::Map<const Frame>;
inline FrameView frame_view(const Frame& frame) { return {frame.data(), frame.rows(), frame.cols()}; }

}  // namespace emit
