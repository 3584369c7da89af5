// Covariance checks, eigenvalue-clipping repair and RTN <-> ECI rotation
// (include/evade/assessment/covariance.hpp gives the method and its source).
#include "evade/assessment/covariance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "evade/assessment/encounter_2d.hpp"
#include "evade/core/frames.hpp"

namespace evade::assessment {
namespace {

// The flight form's repair (encounter_2d.hpp), its refusals thrown with the ground's text.
template <class M>
M repair(const M& c, const std::string& what, bool* npd, double* min_eig) {
  M out = M::Zero();
  switch (repair_covariance_into(c, &out, npd, min_eig)) {
    case CovarianceStatus::kNotFinite:
      throw std::invalid_argument(what + ": covariance has a non-finite entry");
    case CovarianceStatus::kAsymmetric:
      throw std::invalid_argument(what + ": covariance is not symmetric");
    case CovarianceStatus::kNoPositiveEigenvalue:
      throw std::invalid_argument(what + ": covariance has no positive eigenvalue");
    case CovarianceStatus::kNotConverged:
      throw std::invalid_argument(what + ": covariance's eigen-decomposition did not converge");
    case CovarianceStatus::kOk: break;
  }
  return out;
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
