// KeplerOrbit (precomputed f and g) against the foundation's propagate_kepler: same
// formulation, so they agree to rounding (1e-6 m over a week at 7000 km: ~1e-13 relative).
#include <gtest/gtest.h>

#include "evade/conjunction/kepler_orbit.hpp"
#include "evade/core/elements.hpp"
#include "evade/dynamics/kepler_propagator.hpp"

namespace evade::conjunction {
namespace {

TEST(KeplerOrbit, MatchesFoundationPropagator) {
  const double mu = 3.986004418e14;
  for (double e : {0.0, 1e-6, 0.01, 0.3, 0.7}) {
    OrbitalElements oe;
    oe.a_m = 7.2e6 / (1.0 - e) * (1.0 - 0.5 * e);
    oe.e = e;
    oe.i_rad = 1.1;
    oe.raan_rad = 0.3;
    oe.argp_rad = 2.0;
    oe.true_anomaly_rad = 0.7;
    const StateEci s0 = state_from_elements(oe, mu);
    const KeplerOrbit orb(s0, mu);
    for (double dt : {-5000.0, 0.0, 1.0, 3333.3, 86400.0, 7 * 86400.0 + 0.123}) {
      const StateEci a = orb.state_at(dt);
      const StateEci b = propagate_kepler(s0, dt, mu);
      EXPECT_LT((a.r_eci_m - b.r_eci_m).norm(), 1e-5) << "e " << e << " dt " << dt;
      EXPECT_LT((a.v_eci_mps - b.v_eci_mps).norm(), 1e-8) << "e " << e << " dt " << dt;
    }
  }
}

}  // namespace
}  // namespace evade::conjunction
