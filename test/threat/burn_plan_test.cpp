// threat::make_burn_plan (burn_plan.hpp): paper 001's evasive burn as a one-impulse BurnPlan
// at plan t = 0 (the burn at t0), the optimizer's RSW Δv with the pitch/yaw of the result,
// no ECI Δv (HCW knows no inertial state), and refusals of a Δv that is not a burn.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "evade/threat/burn_plan.hpp"
#include "seed1_geometry.hpp"

namespace evade::threat {
namespace {

// Seed1 with a reduced sweep (20 s step) and 200 ISRES evaluations: the conversion, not the
// optimizer, is under test.
EvasionResult seed1_evasion() {
  ThreatOptions o = testing::seed1_options();
  o.step_s = 20.0;
  o.edge_tol_s = 0.5;
  const ThreatAreaSolver s(testing::seed1_geometry(), o);
  EvasionOptions e;
  e.max_evaluations = 200;
  e.seed = 3;
  e.use_isres = true;
  return optimize_evasion(s, 20.0, e);
}

void expect_refused(const EvasionResult& r, const std::string& what) {
  try {
    (void)make_burn_plan(r, 1);
    ADD_FAILURE() << "accepted: " << what;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(ThreatBurnPlan, Seed1EvasionIsOneRswImpulseAtT0WithTheOptimizersDirection) {
  const EvasionResult r = seed1_evasion();
  const BurnPlan p = make_burn_plan(r, 5);
  EXPECT_EQ(p.plan_id, 5);
  EXPECT_EQ(p.source, static_cast<int>(PlanSource::kThreatArea));
  EXPECT_FALSE(p.observability.valid);
  ASSERT_EQ(p.n_impulses, 1);
  EXPECT_EQ(p.impulses[0].t_s, 0.0);  // plan epoch = t0, the start of the threat window
  EXPECT_EQ(p.impulses[0].dv_rsw_mps, r.dv_rsw_mps);
  EXPECT_NEAR(p.impulses[0].dv_rsw_mps.norm(), 20.0, 1e-12);
  // The direction is the result's pitch α and yaw θ (VVLH definition of evasion.hpp).
  EXPECT_LT((p.impulses[0].dv_rsw_mps - evasion_dv_rsw(20.0, r.alpha_rad, r.theta_rad)).norm(),
            1e-12);
  EXPECT_FALSE(p.impulses[0].dv_eci_valid);
  EXPECT_EQ(p.impulses[0].dv_eci_mps, Vec3::Zero());
}

TEST(ThreatBurnPlan, ADvThatIsNotABurnIsRefusedNamingTheField) {
  EvasionResult r;
  r.dv_mps = 20.0;
  r.dv_rsw_mps = Vec3(0.0, 20.0, std::numeric_limits<double>::quiet_NaN());
  expect_refused(r, "dv_rsw_mps is not finite");
  r.dv_mps = 0.0;
  r.dv_rsw_mps = Vec3::Zero();
  expect_refused(r, "V_E = 0");
  r.dv_mps = 20.0;
  r.dv_rsw_mps = Vec3(0.0, 19.0, 0.0);
  expect_refused(r, "differs from dv_mps");
}

}  // namespace
}  // namespace evade::threat
