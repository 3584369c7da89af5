// Encounter-plane projection (include/evade/assessment/encounter_plane.hpp gives the source).
#include "evade/assessment/encounter_plane.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace evade::assessment {

EncounterPlane encounter_plane(const StateEci& obj1, const Mat3& cov1_eci_m2,
                               const StateEci& obj2, const Mat3& cov2_eci_m2) {
  const Vec3 r = obj2.r_eci_m - obj1.r_eci_m;
  const Vec3 v = obj2.v_eci_mps - obj1.v_eci_mps;
  EncounterPlane ep;
  ep.rel_speed_mps = v.norm();
  ep.miss_3d_m = r.norm();
  if (!(ep.rel_speed_mps > 0.0)) {
    throw std::invalid_argument("encounter plane: relative speed is zero (no encounter plane)");
  }
  const Vec3 y = v / ep.rel_speed_mps;
  Vec3 x = r - r.dot(y) * y;  // the miss, normal to the relative velocity
  if (x.norm() < 1e-12 * std::max(1.0, r.norm())) {
    x = y.unitOrthogonal();
  } else {
    x.normalize();
  }
  const Vec3 z = x.cross(y);
  ep.axes_eci.row(0) = x.transpose();
  ep.axes_eci.row(1) = y.transpose();
  ep.axes_eci.row(2) = z.transpose();
  ep.tca_offset_check = ep.miss_3d_m > 0.0 ? r.dot(v) / (ep.miss_3d_m * ep.rel_speed_mps) : 0.0;
  ep.miss_m = Vec2(r.dot(x), r.dot(z));
  Eigen::Matrix<double, 2, 3> p;
  p.row(0) = x.transpose();
  p.row(1) = z.transpose();
  ep.cov_m2 = p * (cov1_eci_m2 + cov2_eci_m2) * p.transpose();
  return ep;
}

PrincipalEncounter principal_axes(const EncounterPlane& ep) {
  Eigen::SelfAdjointEigenSolver<Mat2> es(0.5 * (ep.cov_m2 + ep.cov_m2.transpose()));
  const Vec2& l = es.eigenvalues();  // ascending
  if (!(l(0) > 0.0)) {
    throw std::invalid_argument("encounter plane: combined covariance is not positive definite");
  }
  const Vec2 m = es.eigenvectors().transpose() * ep.miss_m;
  return {m(0), m(1), std::sqrt(l(0)), std::sqrt(l(1))};
}

}  // namespace evade::assessment
