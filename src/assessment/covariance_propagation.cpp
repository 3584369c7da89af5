// Two-body + J2 state and covariance propagation
// (include/evade/assessment/covariance_propagation.hpp gives the method).
#include "evade/assessment/covariance_propagation.hpp"

#include "evade/dynamics/orbit_propagator.hpp"

namespace evade::assessment {

StateEci propagate_j2(const StateEci& s, double dt_s, const EarthModel& earth) {
  if (dt_s == 0.0) return s;
  return propagate_orbit(s, dt_s, GravityModel::kTwoBodyJ2, earth, AdaptiveOptions::tight());
}

Mat6 state_transition_j2(const StateEci& s, double dt_s, const EarthModel& earth) {
  if (dt_s == 0.0) return Mat6::Identity();
  Mat6 phi;
  const Vec6 x0 = s.stacked();
  for (int j = 0; j < 6; ++j) {
    const double h = j < 3 ? 1.0 : 1e-3;
    Vec6 xp = x0, xm = x0;
    xp(j) += h;
    xm(j) -= h;
    phi.col(j) = (propagate_j2(StateEci::from_stacked(xp), dt_s, earth).stacked() -
                  propagate_j2(StateEci::from_stacked(xm), dt_s, earth).stacked()) /
                 (2.0 * h);
  }
  return phi;
}

Mat6 propagate_covariance_j2(const StateEci& s, const Mat6& cov, double dt_s,
                             const EarthModel& earth) {
  const Mat6 phi = state_transition_j2(s, dt_s, earth);
  const Mat6 p = phi * cov * phi.transpose();
  return 0.5 * (p + p.transpose());  // symmetric to rounding (long arcs amplify it)
}

}  // namespace evade::assessment
