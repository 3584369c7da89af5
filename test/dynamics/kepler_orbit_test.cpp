// KeplerOrbit (f and g with precomputed constants) against an independent reference: the
// element path (core: mean anomaly advanced by n dt, Kepler's equation solved in the
// elements, state_from_elements). The two paths get a (and so n) by different roundings
// (vis-viva from the state vs the given a): a few ulp of n, i.e. a phase error of
// ~k eps n dt rad, which over a week (n dt ~ 620 rad) at 7200 km is ~1e-6 m per ulp. Bound:
// |r| (1 + n |dt|) 8 eps (8 ulp) plus 1e-7 m, and the same for |v|.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "evade/core/elements.hpp"
#include "evade/dynamics/kepler_propagator.hpp"

namespace evade {
namespace {

StateEci reference_state(const OrbitalElements& oe0, double dt_s, double mu) {
  OrbitalElements oe = oe0;
  const double m0 = mean_from_true_anomaly(oe0.true_anomaly_rad, oe0.e);
  oe.true_anomaly_rad = true_from_mean_anomaly(m0 + mean_motion_radps(oe0.a_m, mu) * dt_s, oe0.e);
  return state_from_elements(oe, mu);
}

TEST(KeplerOrbit, MatchesTheElementPathOverAWeek) {
  const double mu = 3.986004418e14;
  for (double e : {0.0, 1e-6, 0.01, 0.3, 0.7}) {
    OrbitalElements oe{7.2e6 / (1.0 - e) * (1.0 - 0.5 * e), e, 1.1, 0.3, 2.0, 0.7};
    const KeplerOrbit orb(state_from_elements(oe, mu), mu);
    for (double dt : {-5000.0, 0.0, 0.02, 1.0, 3333.3, 86400.0, 7 * 86400.0 + 0.123}) {
      const StateEci a = orb.state_at(dt);
      const StateEci b = reference_state(oe, dt, mu);
      const double phase_ulps = 8.0 * 2.2e-16 * (1.0 + orb.mean_motion_radps() * std::fabs(dt));
      EXPECT_LT((a.r_eci_m - b.r_eci_m).norm(), 1e-7 + b.r_eci_m.norm() * phase_ulps)
          << "e " << e << " dt " << dt;
      EXPECT_LT((a.v_eci_mps - b.v_eci_mps).norm(), 1e-10 + b.v_eci_mps.norm() * phase_ulps)
          << "e " << e << " dt " << dt;
    }
  }
}

TEST(KeplerOrbit, DenseSweepNearCircularHasNoOutliers) {
  // A converged first guess once made the bracketed Newton fall back to bisection and stop
  // 1e-8 rad (cm) away at isolated times; a dense sweep of times catches such outliers.
  const double mu = 3.986004418e14;
  const OrbitalElements oe{6.95e6, 0.0016, 0.9, 0.0, 1.0, 0.0};
  const KeplerOrbit orb(state_from_elements(oe, mu), mu);
  double worst_m = 0.0;
  for (double t = 0.0; t < 20000.0; t += 0.37) {
    worst_m = std::max(worst_m, (orb.state_at(t).r_eci_m - reference_state(oe, t, mu).r_eci_m).norm());
  }
  EXPECT_LT(worst_m, 1e-6);
}

TEST(KeplerOrbit, RejectsNonFiniteTime) {
  const KeplerOrbit orb(StateEci{Vec3(7e6, 0, 0), Vec3(0, 7.5e3, 0)}, 3.986004418e14);
  EXPECT_THROW(orb.state_at(NAN), std::invalid_argument);
}

}  // namespace
}  // namespace evade
