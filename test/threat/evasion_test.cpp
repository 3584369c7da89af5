// Tests of the evasion optimizer and the eliminating burn (paper 001 sec. 3, Table 3, Fig. 8).
#include <cmath>

#include <gtest/gtest.h>

#include "evade/threat/evasion.hpp"
#include "seed1_geometry.hpp"

namespace evade::threat {
namespace {

using testing::seed1_geometry;
using testing::seed1_options;

TEST(EvasionDirection, PitchAndYawFollowTheVvlhDefinition) {
  // α = θ = 0: prograde (RSW +S).
  EXPECT_LT((evasion_dv_rsw(2.0, 0.0, 0.0) - Vec3(0.0, 2.0, 0.0)).norm(), 1e-12);
  // α = +π/2: toward the zenith (RSW +R).
  EXPECT_LT((evasion_dv_rsw(1.0, 0.5 * M_PI, 0.0) - Vec3(1.0, 0.0, 0.0)).norm(), 1e-12);
  // θ = +π/2: VVLH +y = −orbit normal (RSW −W).
  EXPECT_LT((evasion_dv_rsw(1.0, 0.0, 0.5 * M_PI) - Vec3(0.0, 0.0, -1.0)).norm(), 1e-12);
  EXPECT_NEAR(evasion_dv_vvlh(3.0, 0.4, -2.0).norm(), 3.0, 1e-12);
}

// A reduced but meaningful setting for the unit-test budget: 20 s step, 0.5 s edges,
// 200 ISRES evaluations (the CLI and the benchmark use the paper's 5 s and 1 200).
ThreatOptions test_options() {
  ThreatOptions o = seed1_options();
  o.step_s = 20.0;
  o.edge_tol_s = 0.5;
  return o;
}

EvasionOptions test_evasion() {
  EvasionOptions e;
  e.max_evaluations = 200;
  e.seed = 3;
  return e;
}

TEST(Evasion, ThreatArcDecreasesMonotonicallyWithTheBurn) {
  const ThreatAreaSolver s(seed1_geometry(), test_options());
  double previous = 1e300;
  for (double v : {0.0, 20.0, 40.0, 80.0, 160.0, 240.0}) {
    const EvasionResult r = optimize_evasion(s, v, test_evasion());
    EXPECT_LE(r.area.arc_s, previous) << "V_E = " << v;
    if (v > 0.0) {
      EXPECT_LT(r.area.arc_s, previous) << "strictly, V_E = " << v;
    }
    EXPECT_NEAR(r.dv_vvlh_mps.norm(), v, 1e-9);
    previous = r.area.arc_s;
  }
}

TEST(Evasion, EliminatingBurnRespectsTheT0BoundAndIsWithinOnePercentOfIt) {
  const ThreatAreaSolver s(seed1_geometry(), test_options());
  // Tolerance 1 m/s (< the 1 % = 2.4 m/s being tested) and 200 evaluations per V_E keep the
  // bisection within the unit-test budget; the CLI run with the paper's budget is in
  // docs/VALIDATION.md.
  const EliminationResult e = find_eliminating_dv(s, test_evasion(), 1.0);
  // README §001: J(t0) ≈ 83.5 m/s, bound ≈ 324 − 83.5 = 240.5 m/s.
  EXPECT_NEAR(e.j_t0_mps, 83.5, 0.05);
  EXPECT_GT(e.eliminating_dv_mps, e.bound_mps);
  EXPECT_LT(e.eliminating_dv_mps, 1.01 * e.bound_mps);
  EXPECT_TRUE(e.best.area.intervals.empty());
  // Independent check at t0 with the eliminating burn: the chaser's best plan exceeds ΔV_max.
  EXPECT_GT(s.min_cost_plan(0.0, e.best.dv_rsw_mps).cost_mps, s.options().dv_max_mps);
}

TEST(Evasion, RejectsBadBurns) {
  const ThreatAreaSolver s(seed1_geometry(), test_options());
  EXPECT_THROW(optimize_evasion(s, -1.0, test_evasion()), std::invalid_argument);
  EXPECT_THROW(optimize_evasion(s, std::nan(""), test_evasion()), std::invalid_argument);
  EvasionOptions bad = test_evasion();
  bad.max_evaluations = 0;
  EXPECT_THROW(optimize_evasion(s, 10.0, bad), std::invalid_argument);
}

}  // namespace
}  // namespace evade::threat
