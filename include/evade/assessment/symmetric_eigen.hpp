// Eigen-decompositions of small symmetric matrices for flight code (docs/AUTONOMY.md, the
// planning worker's stack bound): fixed size, bounded loops, no allocation, no alloca (Eigen's
// SelfAdjointEigenSolver reaches Householder products on dynamic blocks whose stack GCC cannot
// bound). The 2x2 is one symmetric Schur rotation (G. H. Golub and C. F. Van Loan, "Matrix
// Computations", 4th ed., 2013, Algorithm 8.5.1: the smaller eigenvalue as a - t b, within a
// few ulps of a(0,0), test SymmetricEigen.*); the NxN is the cyclic-by-row Jacobi method of the same
// book (Algorithm 8.5.3) with that rotation, at most kMaxJacobiSweeps sweeps. Eigenvalues in
// ascending order, eigenvectors as the orthonormal columns of the same order (as Eigen's).
#pragma once

#include <Eigen/Core>

#include "evade/assessment/encounter_plane.hpp"
#include "evade/core/state.hpp"

namespace evade::assessment {

inline constexpr int kMaxJacobiSweeps = 30;

/// The symmetric part of a (its off-diagonal as the mean of a(0,1) and a(1,0)).
void symmetric_eigen_2x2(const Mat2& a, Vec2* values, Mat2* vectors) noexcept;

/// Cyclic Jacobi on the symmetric part of a (instantiated for N = 6, the covariance repair's). Returns false when the off-diagonal has not
/// fallen below 1e-14 of the Frobenius norm within kMaxJacobiSweeps sweeps (finite symmetric
/// input converges quadratically, in under 10 sweeps for N = 6) or a is not finite; the
/// outputs then hold the last sweep's.
template <int N>
bool symmetric_eigen_jacobi(const Eigen::Matrix<double, N, N>& a, Eigen::Matrix<double, N, 1>* values,
                            Eigen::Matrix<double, N, N>* vectors) noexcept;

extern template bool symmetric_eigen_jacobi<6>(const Mat6&, Vec6*, Mat6*) noexcept;

}  // namespace evade::assessment
