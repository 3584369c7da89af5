// Coppola's encounter window of a conjunction (pc_3d_nc.hpp, coppola_window; Coppola 2012,
// AAS 12-248 eqs. 4-6 and 12-16): the span holding all but gamma of a linear encounter's Pc.
#include <algorithm>
#include <cmath>
#include <limits>

#include "evade/assessment/pc_3d_nc.hpp"
#include "evade/core/erfc_inverse.hpp"

namespace evade::assessment {

EncounterWindow coppola_window(const StateEci& obj1, const Mat6& cov1_eci,
                               const StateEci& obj2, const Mat6& cov2_eci, double hbr_m,
                               double gamma) {
  const Vec3 r = obj2.r_eci_m - obj1.r_eci_m;
  const Vec3 v = obj2.v_eci_mps - obj1.v_eci_mps;
  const double v0 = v.norm();
  EncounterWindow w;
  if (!(v0 >= 100.0 * std::numeric_limits<double>::epsilon())) {
    w.tau0_s = -std::numeric_limits<double>::infinity();
    w.tau1_s = std::numeric_limits<double>::infinity();
    return w;
  }
  // Encounter frame: x along the relative velocity, y towards the miss (AAS 12-248 eqs. 4-6).
  const Vec3 xh = v / v0;
  Vec3 yh = r - xh * xh.dot(r);
  if (!(yh.norm() > 0.0)) yh = xh.unitOrthogonal();
  yh.normalize();
  Mat3 rot;
  rot.row(0) = xh;
  rot.row(1) = yh;
  rot.row(2) = xh.cross(yh);
  const Mat3 a = rot * (cov1_eci + cov2_eci).block<3, 3>(0, 0) * rot.transpose();
  const Vec3 re = rot * r;
  const Eigen::Matrix2d pc = a.block<2, 2>(1, 1);
  const Eigen::Vector2d wv = a.block<2, 1>(1, 0);
  const Eigen::Vector2d b = pc.completeOrthogonalDecomposition().solve(wv);
  const double sv2 = std::sqrt(std::max(0.0, 2.0 * (a(0, 0) - b.dot(wv))));
  const double q0 = b.dot(re.tail<2>());
  const double dmin = -hbr_m * b.norm();
  const double dmax = hbr_m * std::sqrt(1.0 + b.squaredNorm());
  const double t = erfc_inverse(gamma) * sv2;  // AAS 12-248 eqs. 12-16
  w.tau0_s = (-t + q0 - dmax) / v0;
  w.tau1_s = (t + q0 - dmin) / v0;
  return w;
}

}  // namespace evade::assessment
