// The uplinked own state against the node's navigation (include/evade/autonomy/nav_check.hpp).
#include "evade/autonomy/nav_check.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "evade/autonomy/orbit_stm.hpp"

namespace evade::autonomy {

double mahalanobis(const Vec3& d, const Mat3& c, double floor_m2) noexcept {
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (c + c.transpose()));
  const Vec3 along = eig.eigenvectors().transpose() * d;
  double s2 = 0.0;
  for (int i = 0; i < 3; ++i) s2 += along[i] * along[i] / std::max(eig.eigenvalues()[i], floor_m2);
  return std::sqrt(s2);
}

NavCheck check_own_state(const ConjunctionEvent& e, const Vec6& x_nav_eci, std::int64_t now_us,
                         double h_max_s, const EarthModel& earth) noexcept {
  NavCheck out;
  Vec6 x = x_nav_eci;
  const double dt_s = 1e-6 * static_cast<double>(e.tca_us - now_us);
  if (!propagate(&x, dt_s, h_max_s, earth)) return out;
  const Vec3 d = x.head<3>() - e.x1_eci.head<3>();
  out.ok = true;
  out.x_nav_tca = x;
  out.distance_m = d.norm();
  out.sigma = mahalanobis(d, e.cov1_eci.topLeftCorner<3, 3>(), 1.0);
  return out;
}

}  // namespace evade::autonomy
