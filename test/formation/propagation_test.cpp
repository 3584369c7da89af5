// Paper 003 by propagation (two-body + J2, DOP853): the analytic Table 1 against limits
// found by bisection on propagated constraint margins; the decision on seed3 clears the
// debris and keeps every constraint; the infeasible case is reported as infeasible; the
// burn model (vis-viva Δv) realizes the requested Δa.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "evade/dynamics/orbit_propagator.hpp"
#include "evade/commands/formation_scenario.hpp"
#include "evade/formation/verification.hpp"

namespace evade::formation {
namespace {

PlanInputs load(const std::string& name) {
  const config::Scenario sc = config::Scenario::load(name);
  return commands::read_plan_inputs(sc);
}

TEST(FormationPropagation, TangentialBurnRealizesDeltaAByVisViva) {
  const PlanInputs in = load("seed3");
  const StateEci s0 = state_from_mean_elements(in.spec.groups[1].sats[0], in.spec.earth);
  std::vector<AppliedBurn> applied;
  const double t_b = 1000.0;
  const auto st = propagate_with_burns(s0, {t_b - 1e-9, t_b}, {{t_b, 12.5}}, in.spec.earth,
                                       in.propagation.integrator, &applied);
  ASSERT_EQ(applied.size(), 1u);
  const double mu = in.spec.earth.mu_m3ps2;
  auto a_of = [&](const StateEci& s) { return 1.0 / (2.0 / s.r_eci_m.norm() - s.v_eci_mps.squaredNorm() / mu); };
  // Vis-viva is exact: the osculating a jumps by 12.5 m to rounding (a ~ 7.5e6 m, 1e-9 rel).
  EXPECT_NEAR(a_of(st[1]) - a_of(st[0]), 12.5, 1e-4);
  // Δv ≈ n Δa / 2 on a near-circular orbit; the difference is O(e) + O(Δa/a) (~1e-3 here).
  EXPECT_NEAR(applied[0].dv_mps / applied[0].dv_approx_mps - 1.0, 0.0, 2e-3);
  EXPECT_GT(applied[0].dv_mps, 0.0);
  // Without burns, the sampler agrees with the foundation's propagate_orbit (same DOP853).
  const auto plain = propagate_with_burns(s0, {5000.0}, {}, in.spec.earth, in.propagation.integrator);
  const StateEci ref = propagate_orbit(s0, 5000.0, GravityModel::kTwoBodyJ2, in.spec.earth,
                                       in.propagation.integrator);
  EXPECT_LT((plain[0].r_eci_m - ref.r_eci_m).norm(), 1e-3);
}

TEST(FormationPropagation, AnalyticLimitsAgreeWithPropagatedBisection) {
  const PlanInputs in = load("seed3");
  const LimitsResult lim = compute_limits(in.spec, in.threatened);
  const double t_b = in.conjunction.tca_s - in.timing.burn_before_tca_s;
  const std::vector<NumericalLimitRow> num =
      numerical_limits(in.spec, in.threatened, lim, t_b, in.propagation, 1e-3);
  ASSERT_EQ(num.size(), lim.rows.size());
  int compared = 0;
  for (std::size_t r = 0; r < num.size(); ++r) {
    for (int d = 0; d < 2; ++d) {
      const double a = d == 0 ? lim.rows[r].raise_max_m : lim.rows[r].lower_max_m;
      const double n = d == 0 ? num[r].raise_max_m : num[r].lower_max_m;
      // Brief: within 5 %. Only "small" Δa (<= 5 km, Δa/a <= 7e-4) — the paper's linear
      // drift model: rows whose limit is ~100 km (out-of-plane with 18+ km of margin) are
      // outside it (K_Ω ∝ a^-4.5 changes 6 % over Δa = 100 km) and are tabulated in
      // docs/VALIDATION.md instead.
      if (!std::isfinite(a) || a > 5000.0) continue;
      ++compared;
      EXPECT_NEAR(n / a - 1.0, 0.0, 0.05) << num[r].name << (d == 0 ? " raise" : " lower")
                                           << " analytic " << a << " numerical " << n;
    }
  }
  EXPECT_GE(compared, 9);  // every binding candidate: RAAN, phase, in-plane (both), out-of-plane lower
}

TEST(FormationPropagation, Seed3DecisionClearsAndKeepsEveryConstraint) {
  const PlanInputs in = load("seed3");
  const LimitsResult lim = compute_limits(in.spec, in.threatened);
  const Decision dec = decide(in.spec, in.threatened, lim, in.conjunction, in.timing, in.propagation);
  ASSERT_TRUE(dec.feasible) << dec.summary;
  EXPECT_TRUE(dec.maneuver_needed);
  EXPECT_EQ(dec.direction, "raise");  // the paper's case was a raise, too
  EXPECT_GT(dec.delta_a_m, 0.0);
  EXPECT_LE(dec.delta_a_m, lim.raise_max_m);
  EXPECT_NEAR(dec.nominal_miss_m, in.conjunction.miss_rsw_m.norm(), 0.5);  // miss given ⊥ v_rel
  ASSERT_EQ(dec.burns.size(), 2u);
  EXPECT_NEAR(dec.burns[0].t_s, in.conjunction.tca_s - 18 * 3600.0, 1e-9);
  EXPECT_NEAR(dec.burns[1].t_s, in.conjunction.tca_s + 12 * 3600.0, 1e-9);
  EXPECT_LT(dec.burns[1].dv_mps, 0.0);  // restore: lowering
  const Verification v = verify(in.spec, in.threatened, in.conjunction, dec, in.propagation);
  EXPECT_TRUE(v.clears);
  EXPECT_GE(v.miss_at_tca_m, in.conjunction.required_miss_m);
  // The decision aims at the smallest Δa: the miss is not far above the requirement.
  EXPECT_LT(v.miss_at_tca_m, 1.01 * in.conjunction.required_miss_m);
  EXPECT_TRUE(v.all_kept);
  for (const ConstraintCheck& c : v.rows) EXPECT_GE(c.min_margin, 0.0) << c.name;
  // Lower would have needed more than its limit (10.5 m): the reason raise was chosen.
  EXPECT_FALSE(dec.lower.feasible);
}

TEST(FormationPropagation, RestoredDriftMatchesTheDriftCoefficients) {
  // With the restore burn the Δa acts for burn_before + restore_after = 30 h: the in-plane
  // deviation of each deputy moves by K_am Δa · 1.25 day (the rest of T the drift stops).
  const PlanInputs in = load("seed3");
  const LimitsResult lim = compute_limits(in.spec, in.threatened);
  const Decision dec = decide(in.spec, in.threatened, lim, in.conjunction, in.timing, in.propagation);
  const Verification v = verify(in.spec, in.threatened, in.conjunction, dec, in.propagation);
  const double hold_days = (dec.restore_time_s - dec.burn_time_s) / kSecondsPerDay;
  for (std::size_t r = 0; r < v.rows.size(); ++r) {
    if (lim.rows[r].def.kind != ConstraintKind::kInPlane) continue;
    const double predicted = predicted_deviation(lim.rows[r], dec.delta_a_m, hold_days);
    const double moved = predicted - lim.rows[r].deviation;  // ~1.9 km
    // 2 % of the motion: the along-track oscillation 2Δa sin(nt) and K_Ω cos i term are
    // < 0.1 %; the window averaging around the burns smears up to half a period (~1 %).
    EXPECT_NEAR(v.rows[r].final_deviation, predicted, 0.02 * std::abs(moved)) << v.rows[r].name;
  }
}

TEST(FormationPropagation, InfeasibleScenarioIsReportedWithTheBestTradeOff) {
  const PlanInputs in = load("seed3-infeasible");
  const LimitsResult lim = compute_limits(in.spec, in.threatened);
  const Decision dec = decide(in.spec, in.threatened, lim, in.conjunction, in.timing, in.propagation);
  EXPECT_FALSE(dec.feasible);
  EXPECT_NE(dec.summary.find("INFEASIBLE"), std::string::npos);
  EXPECT_GT(dec.raise.required_delta_a_m, lim.raise_max_m);
  EXPECT_GT(dec.lower.required_delta_a_m, lim.lower_max_m);
  EXPECT_FALSE(dec.raise.violated.empty());
  EXPECT_FALSE(dec.lower.violated.empty());
  // Best trade-off: at a limit, the direction with the larger miss; every constraint kept.
  const double lim_abs = dec.delta_a_m > 0 ? lim.raise_max_m : lim.lower_max_m;
  EXPECT_DOUBLE_EQ(std::abs(dec.delta_a_m), lim_abs);
  const Verification v = verify(in.spec, in.threatened, in.conjunction, dec, in.propagation);
  EXPECT_FALSE(v.clears);
  EXPECT_TRUE(v.all_kept);
  EXPECT_LT(v.miss_at_tca_m, in.conjunction.required_miss_m);
}

TEST(FormationPropagation, NoManeuverWhenTheNominalMissSuffices) {
  PlanInputs in = load("seed3");
  in.conjunction.required_miss_m = 50.0;  // nominal miss is 68 m
  const LimitsResult lim = compute_limits(in.spec, in.threatened);
  const Decision dec = decide(in.spec, in.threatened, lim, in.conjunction, in.timing, in.propagation);
  EXPECT_FALSE(dec.maneuver_needed);
  EXPECT_EQ(dec.direction, "none");
  EXPECT_TRUE(dec.burn_plan().empty());
}

}  // namespace
}  // namespace evade::formation
