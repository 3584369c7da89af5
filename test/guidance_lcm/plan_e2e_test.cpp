// End to end (docs/GUIDANCE_NODE.md PLAN-E2E-1): the seed4 observability plan (paper 004) is
// published as evade_burn_plan_t on memq://, executed by the guidance node (GuidanceNode, the
// node's cycle) inside the simulator (sim::run_plan_simulation: two-body truth, actuator
// model, one exchange per 50 Hz cycle in lockstep), and checked against the plan:
//  - delivered Δv (∫ a dt of the actuator) within 1 % in magnitude and 0.5° in direction of
//    the planned Δv (RSW turned into ECI with the truth at the planned time);
//  - burn centre within one cycle of the planned time;
//  - the post-burn state: the evader's deviation from its unburnt trajectory, 1000 s after
//    the burn (the paper's observation window), against (a) the same truth with an ideal
//    impulse, within the finite-burn bound of PLAN-FB-1 + PLAN-FB-3, and (b) the planner's HCW
//    prediction Φ(t) [0; Δv], within that bound plus HCW's own linearisation error, which is
//    measured here by the ideal-impulse run and bounded by PLAN-FB-2.
#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include "evade/core/frames.hpp"
#include "evade/dynamics/hcw.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/lcm_link/burn_plan_publisher.hpp"
#include "evade/observability/burn_plan.hpp"
#include "evade/observability/planner.hpp"
#include "evade/sim/plan_run.hpp"
#include "plan_e2e_support.hpp"
#include "seed4_problem.hpp"

namespace {

using namespace evade;

constexpr double kLeadS = 10.0;     // the burn's planned time after the run starts [s]
constexpr double kAfterS = 1000.0;  // post-burn check: paper 004's observation window [s]

using test::angle_deg;
using test::NodeEndpoint;

TEST(PlanEndToEnd, Seed4ObservabilityPlanFlownByTheNodeInTheSimulator) {
  // The plan (paper 004 seed4: 3 m/s, ISRES as in the publisher test).
  observability::IsresOptions io;
  io.seed = 3;
  const observability::PlanResult res = observability::plan_isres(
      observability::sample(observability::test::seed4()), observability::ObjectiveKind::kPaper,
      observability::EstimationConfig{}, io);
  const BurnPlan plan = observability::make_burn_plan(res, 1);
  ASSERT_EQ(plan.n_impulses, 1);
  const Vec3 dv_rsw = plan.impulses[0].dv_rsw_mps;

  // Truth: evader on the 400 km circular orbit, chaser at seed4's X_P0 (frame P: x = −R,
  // y = −S, z = W), two-body (the planner's HCW is about a Keplerian circular orbit).
  sim::PlanRunConfig cfg;
  const double r0 = kEarthDefault.re_m + 400e3;
  const double n = std::sqrt(kEarthDefault.mu_m3ps2 / (r0 * r0 * r0));
  cfg.satellite0 = {Vec3(r0, 0.0, 0.0), Vec3(0.0, n * r0, 0.0)};
  Vec6 rel;
  rel << -79933.5, 57232.0, 0.0, 11.135, -2.38, 0.0;
  cfg.other0 = eci_from_relative_rsw(cfg.satellite0, rel);
  cfg.duration_s = kLeadS + kAfterS;

  guidance_lcm::NodeConfig ncfg;  // defaults: 50 Hz, max_accel 1 m/s^2, budget 100 m/s
  NodeEndpoint ep(ncfg);
  const double cycle_s = ncfg.guidance.cycle_s();
  const std::int64_t epoch_us = sim::kPlanRunUtime0 + static_cast<std::int64_t>(kLeadS * 1e6);
  const auto uplink = [&](long k, std::int64_t utime) {
    if (k != 0) return;
    lcm_link::PlanStamp stamp = test::signed_stamp();
    stamp.utime = utime;
    stamp.epoch_utime = epoch_us;  // plan t = 0 (paper 004 burns at t0) is 10 s after start
    lcm_link::publish_burn_plan(ep.lcm(), guidance_lcm::kChanPlan, plan, 1, stamp);
  };
  const sim::PlanRunResult run = sim::run_plan_simulation(cfg, ep, uplink);

  // Node status: accepted, completed, one impulse.
  const evade_guidance_status_t& st = ep.node().last_status();
  EXPECT_EQ(st.plan_id, 1);
  EXPECT_EQ(st.plan_end, evade_guidance_status_t::PLAN_END_COMPLETED);
  EXPECT_EQ(st.plan_impulses_done, 1);
  EXPECT_EQ(ep.node().counts().received, ep.node().counts().accounted());

  // Delivered vs planned Δv (PLAN-E2E-1).
  ASSERT_EQ(run.burns.size(), 1u);
  const sim::DeliveredBurn& b = run.burns[0];
  StateEci sat_tb, oth_tb;
  sim::propagate_unforced(cfg, kLeadS, &sat_tb, &oth_tb);
  const Vec3 dv_plan_eci = rotation_eci_to_rsw(sat_tb).transpose() * dv_rsw;
  const double mag_err = b.dv_eci_mps.norm() / dv_plan_eci.norm() - 1.0;
  const double dir_err_deg = angle_deg(b.dv_eci_mps, dv_plan_eci);
  const double centre_err_s = 0.5 * (b.t_start_s + b.t_end_s) - kLeadS;
  std::printf("seed4: planned |dv| %.9f m/s, delivered %.9f m/s (%.3e), direction error %.4f deg,"
              " burn [%.3f, %.3f] s, centre offset %+.4f s, node-reported %.9f m/s\n",
              dv_plan_eci.norm(), b.dv_eci_mps.norm(), mag_err, dir_err_deg, b.t_start_s,
              b.t_end_s, centre_err_s, st.plan_dv_delivered_mps[0]);
  EXPECT_LT(std::abs(mag_err), 0.01);
  EXPECT_LT(dir_err_deg, 0.5);
  EXPECT_LE(std::abs(centre_err_s), cycle_s + 1e-9);
  // The node counts Σ|a| dt; the vector sum is shorter by the RSW frame's turn over the
  // burn: 1 − |Σ a dt| / Σ|a| dt ≈ (n τ)² / 24 (4.8e-7 here).
  const double tau_s = b.t_end_s - b.t_start_s;
  EXPECT_NEAR(st.plan_dv_delivered_mps[0], b.dv_eci_mps.norm(),
              1.01 * dv_plan_eci.norm() * (n * tau_s) * (n * tau_s) / 24.0 + 1e-12);

  // Post-burn state. References: the unburnt truth, and the truth with an ideal impulse.
  const double t_end = kLeadS + kAfterS;
  StateEci sat_nb, oth_nb;
  sim::propagate_unforced(cfg, t_end, &sat_nb, &oth_nb);
  sim::PlanRunConfig after = cfg;
  after.satellite0 = {sat_tb.r_eci_m, sat_tb.v_eci_mps + dv_plan_eci};
  after.other0 = oth_tb;
  StateEci sat_imp, oth_imp;
  sim::propagate_unforced(after, kAfterS, &sat_imp, &oth_imp);
  const Vec6 d_sim = relative_rsw_from_eci(sat_nb, run.satellite_end);
  const Vec6 d_imp = relative_rsw_from_eci(sat_nb, sat_imp);
  const Vec6 d_hcw = hcw_impulse_response(n, kAfterS, dv_rsw);

  // PLAN-FB-1 + PLAN-FB-3: |x_finite − x_impulse| ≤ ‖Φ A²B‖ |Δv| τ²/24 + ‖Φ A B‖ |Δv| δc
  // + ‖Φ B‖ |Δv| n T/2, δc ≤ T/2.
  const test::Bound fb = test::finite_burn_bound(n, kAfterS, dv_rsw.norm(), tau_s, cycle_s);
  const double e_r = (d_sim.head<3>() - d_imp.head<3>()).norm();
  const double e_v = (d_sim.tail<3>() - d_imp.tail<3>()).norm();
  const double lin_r = (d_imp.head<3>() - d_hcw.head<3>()).norm();
  const double lin_v = (d_imp.tail<3>() - d_hcw.tail<3>()).norm();
  const double h_r = (d_sim.head<3>() - d_hcw.head<3>()).norm();
  const double h_v = (d_sim.tail<3>() - d_hcw.tail<3>()).norm();
  // PLAN-FB-2: HCW's linearisation error for a deviation ρ about a circular orbit of radius
  // r is second order, ≲ 3 (|ρ|/r) |ρ| in position (and n times that in velocity).
  const double rho = d_hcw.head<3>().norm();
  const double lin_bound_r = 3.0 * rho * rho / r0;
  std::printf("seed4 +%.0f s: |deviation| %.3f m; finite vs impulse: %.4f m (bound %.4f m), "
              "%.3e m/s (bound %.3e m/s); impulse vs HCW %.4f m, %.3e m/s (bound %.3f m); node "
              "vs HCW %.4f m, %.3e m/s\n",
              kAfterS, rho, e_r, fb.r_m, e_v, fb.v_mps, lin_r, lin_v, lin_bound_r, h_r, h_v);
  EXPECT_LE(e_r, fb.r_m);
  EXPECT_LE(e_v, fb.v_mps);
  EXPECT_LE(lin_r, lin_bound_r);
  EXPECT_LE(lin_v, n * lin_bound_r * 3.0);
  EXPECT_LE(h_r, fb.r_m + lin_r);
}

}  // namespace
