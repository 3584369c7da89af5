// Covariance checks and frame changes for conjunction assessment.
//
// Positive definiteness: a symmetric covariance is tested by its eigenvalues (Eigen's
// SelfAdjointEigenSolver). A matrix with an eigenvalue <= 0 (non-positive-definite, NPD, as
// produced by rounding or by interpolated ephemerides) is repaired by eigenvalue clipping
// (Higham 1988, "Computing a nearest symmetric positive semidefinite matrix", the nearest
// PSD matrix in the Frobenius norm, then lifted to a floor): every eigenvalue below
// floor = max(1e-10 * largest eigenvalue, 1e-12) is set to the floor, C' = V max(L, floor) V^T.
// The repair is flagged (npd = true) with the smallest eigenvalue found. An asymmetric
// matrix (|C - C^T| > 1e-9 |C|) or a non-finite one is an error, not repaired.
// RTN -> ECI: C_eci = R^T C_rtn R with R the rows R, T (= S), N (= W) of the object's own
// state (core/frames.hpp, RSW = RTN), applied to both 3x3 blocks of a 6x6 covariance.
#pragma once

#include <string>

#include "evade/core/state.hpp"

namespace evade::assessment {

struct CovarianceRepair {
  Mat3 cov_m2 = Mat3::Zero();  ///< the matrix used (repaired when npd)
  bool npd = false;            ///< the input had an eigenvalue <= 0 and was clipped
  double min_eigenvalue_m2 = 0.0;  ///< smallest eigenvalue of the input
};

/// Checks symmetry and finiteness (std::invalid_argument naming `what` otherwise) and clips
/// non-positive eigenvalues as described above.
CovarianceRepair repair_covariance(const Mat3& cov_m2, const std::string& what);
/// Same for a 6x6 position-velocity covariance (m^2, m^2/s, m^2/s^2).
Mat6 repair_covariance6(const Mat6& cov, const std::string& what, bool* npd,
                        double* min_eigenvalue);

/// RTN (of `object`) -> ECI for a 6x6 position-velocity covariance.
Mat6 cov_eci_from_rtn(const Mat6& cov_rtn, const StateEci& object);
/// ECI -> RTN (of `object`).
Mat6 cov_rtn_from_eci(const Mat6& cov_eci, const StateEci& object);

}  // namespace evade::assessment
