// Covariance checks, eigenvalue-clipping repair and RTN <-> ECI rotation
// (include/evade/assessment/covariance.hpp gives the method and its source).
#include "evade/assessment/covariance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "evade/core/frames.hpp"

namespace evade::assessment {
namespace {

template <class M>
M repair(const M& c, const std::string& what, bool* npd, double* min_eig) {
  if (!c.allFinite()) throw std::invalid_argument(what + ": covariance has a non-finite entry");
  const double scale = std::max(c.cwiseAbs().maxCoeff(), 1e-300);
  if ((c - c.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    throw std::invalid_argument(what + ": covariance is not symmetric");
  }
  M s = 0.5 * (c + c.transpose());
  Eigen::SelfAdjointEigenSolver<M> es(s);
  const auto& l = es.eigenvalues();
  *min_eig = l.minCoeff();
  const double floor = std::max(1e-10 * l.maxCoeff(), 1e-12);
  *npd = *min_eig <= 0.0;
  if (!*npd) return s;
  if (l.maxCoeff() <= 0.0) {
    throw std::invalid_argument(what + ": covariance has no positive eigenvalue");
  }
  auto clipped = l;
  for (int i = 0; i < clipped.size(); ++i) clipped(i) = std::max(clipped(i), floor);
  return es.eigenvectors() * clipped.asDiagonal() * es.eigenvectors().transpose();
}

Mat6 block_rotation(const StateEci& object) {
  const Mat3 r = rotation_eci_to_rsw(object);
  Mat6 b = Mat6::Zero();
  b.block<3, 3>(0, 0) = r;
  b.block<3, 3>(3, 3) = r;
  return b;
}

}  // namespace

CovarianceRepair repair_covariance(const Mat3& cov_m2, const std::string& what) {
  CovarianceRepair out;
  out.cov_m2 = repair(cov_m2, what, &out.npd, &out.min_eigenvalue_m2);
  return out;
}

Mat6 repair_covariance6(const Mat6& cov, const std::string& what, bool* npd,
                        double* min_eigenvalue) {
  return repair(cov, what, npd, min_eigenvalue);
}

Mat6 cov_eci_from_rtn(const Mat6& cov_rtn, const StateEci& object) {
  const Mat6 b = block_rotation(object);
  return b.transpose() * cov_rtn * b;
}

Mat6 cov_rtn_from_eci(const Mat6& cov_eci, const StateEci& object) {
  const Mat6 b = block_rotation(object);
  return b * cov_eci * b.transpose();
}

}  // namespace evade::assessment
