// formation::make_burn_plan (burn_plan.hpp): seed3's decision (paper 003: raise 18 h before
// the TCA, restore 12 h after) as a two-impulse BurnPlan: the decision's times from the
// scenario epoch, the vis-viva Δv along the velocity at each burn in ECI, the same vector in
// the RSW frame of that state, and the refusal of a decision with nothing to fly.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "evade/core/frames.hpp"
#include "evade/formation/burn_plan.hpp"
#include "evade/formation/burn_propagation.hpp"
#include "evade/commands/formation_scenario.hpp"
#include "evade/formation/limits.hpp"

namespace evade::formation {
namespace {

struct Planned {
  PlanInputs in;
  Decision dec;
};

Planned plan_of(const char* scenario) {
  const config::Scenario sc = config::Scenario::load(scenario);
  Planned p{commands::read_plan_inputs(sc), {}};
  const LimitsResult lim = compute_limits(p.in.spec, p.in.threatened);
  p.dec = decide(p.in.spec, p.in.threatened, lim, p.in.conjunction, p.in.timing,
                 p.in.propagation);
  return p;
}

const Planned& seed3() {
  static const Planned p = plan_of("seed3");
  return p;
}

// The satellite just before burn k: propagated with the earlier burns only (a sample at a
// burn time would get the post-burn state).
StateEci pre_burn_state(const Planned& p, std::size_t k) {
  std::vector<TangentialBurn> earlier = p.dec.burn_plan();
  const double t_b = earlier[k].t_s;
  earlier.resize(k);
  const StateEci s0 = state_from_mean_elements(p.in.spec.sat(p.in.threatened), p.in.spec.earth);
  return propagate_with_burns(s0, {t_b}, earlier, p.in.spec.earth, p.in.propagation.integrator)
      .front();
}

double semi_major_axis_m(const StateEci& s, double mu) {
  return 1.0 / (2.0 / s.r_eci_m.norm() - s.v_eci_mps.squaredNorm() / mu);
}

TEST(FormationBurnPlan, Seed3PlanHasTheDecisionsTwoBurnsAtTheirTimesFromTheEpoch) {
  const Planned& p = seed3();
  ASSERT_TRUE(p.dec.feasible);
  const BurnPlan plan = make_burn_plan(p.in.spec, p.in.threatened, p.dec, p.in.propagation, 7);
  EXPECT_EQ(plan.plan_id, 7);
  EXPECT_EQ(plan.source, static_cast<int>(PlanSource::kFormation));
  EXPECT_FALSE(plan.observability.valid);
  ASSERT_EQ(plan.n_impulses, 2);
  // Plan t = 0 is the scenario epoch: seed3's TCA is 30 h after it, burn 18 h before the TCA
  // and restore 12 h after.
  EXPECT_EQ(plan.impulses[0].t_s, p.dec.burn_time_s);
  EXPECT_EQ(plan.impulses[1].t_s, p.dec.restore_time_s);
  EXPECT_DOUBLE_EQ(plan.impulses[0].t_s, 108000.0 - 64800.0);
  EXPECT_DOUBLE_EQ(plan.impulses[1].t_s, 108000.0 + 43200.0);
}

TEST(FormationBurnPlan, EciDvIsTheVisVivaDvAlongTheVelocityAndReachesTheTargetDeltaA) {
  const Planned& p = seed3();
  const BurnPlan plan = make_burn_plan(p.in.spec, p.in.threatened, p.dec, p.in.propagation, 1);
  const double mu = p.in.spec.earth.mu_m3ps2;
  for (std::size_t k = 0; k < 2; ++k) {
    const ImpulsiveBurn& imp = plan.impulses[k];
    ASSERT_TRUE(imp.dv_eci_valid);
    const StateEci pre = pre_burn_state(p, k);
    // Magnitude and sign: the decision's vis-viva Δv (raise: prograde; restore: retrograde).
    EXPECT_NEAR(imp.dv_eci_mps.dot(pre.v_eci_mps.normalized()), p.dec.burns[k].dv_mps, 1e-12);
    EXPECT_LT(imp.dv_eci_mps.cross(pre.v_eci_mps.normalized()).norm(), 1e-12);
    // Applied to the state before the burn it changes the osculating a by the decision's Δa
    // (to the propagation's 1e-10 relative tolerance on a 7.47e6 m orbit).
    const StateEci post{pre.r_eci_m, pre.v_eci_mps + imp.dv_eci_mps};
    EXPECT_NEAR(semi_major_axis_m(post, mu) - semi_major_axis_m(pre, mu),
                p.dec.burns[k].delta_a_m, 1e-3);
  }
  EXPECT_GT(plan.impulses[0].dv_eci_mps.dot(pre_burn_state(p, 0).v_eci_mps), 0.0);  // raise
  EXPECT_LT(plan.impulses[1].dv_eci_mps.dot(pre_burn_state(p, 1).v_eci_mps), 0.0);  // restore
}

TEST(FormationBurnPlan, RswDvIsTheEciDvInTheFrameOfTheStateAtTheBurn) {
  const Planned& p = seed3();
  const BurnPlan plan = make_burn_plan(p.in.spec, p.in.threatened, p.dec, p.in.propagation, 1);
  for (std::size_t k = 0; k < 2; ++k) {
    const ImpulsiveBurn& imp = plan.impulses[k];
    const Mat3 c = rotation_eci_to_rsw(pre_burn_state(p, k));
    EXPECT_LT((imp.dv_rsw_mps - c * imp.dv_eci_mps).norm(), 1e-15);
    EXPECT_NEAR(imp.dv_rsw_mps.norm(), imp.dv_eci_mps.norm(), 1e-16);
    // Tangential on a near-circular orbit: along track, radial part below e |Δv|, no normal.
    const double e = osculating_angles(pre_burn_state(p, k), p.in.spec.earth.mu_m3ps2).e;
    // (the flight-path angle γ of an osculating orbit is at most asin e).
    EXPECT_LE(std::abs(imp.dv_rsw_mps.x()), (e + 1e-12) * imp.dv_rsw_mps.norm());
    EXPECT_GE(std::abs(imp.dv_rsw_mps.y()), std::sqrt(1.0 - e * e) * imp.dv_rsw_mps.norm());
    EXPECT_LT(std::abs(imp.dv_rsw_mps.z()), 1e-15);
  }
}

TEST(FormationBurnPlan, ADecisionWithNothingToFlyIsRefusedSayingWhy) {
  const Planned inf = plan_of("seed3-infeasible");
  ASSERT_FALSE(inf.dec.feasible);
  try {
    (void)make_burn_plan(inf.in.spec, inf.in.threatened, inf.dec, inf.in.propagation, 1);
    ADD_FAILURE() << "infeasible decision published";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not feasible"), std::string::npos) << e.what();
  }
  Decision none = seed3().dec;
  none.maneuver_needed = false;
  try {
    (void)make_burn_plan(seed3().in.spec, seed3().in.threatened, none, seed3().in.propagation, 1);
    ADD_FAILURE() << "decision without maneuver published";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no maneuver needed"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace evade::formation
