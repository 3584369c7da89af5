// DOP853 on the two-body problem against the analytic Kepler propagator.
#include <gtest/gtest.h>

#include <cstdio>

#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/dynamics/kepler_propagator.hpp"
#include "test_orbits.hpp"

namespace evade {
namespace {

const double kMu = kEarthDefault.mu_m3ps2;

Vec6 two_body(double, const Vec6& x) {
  return orbit_derivative(x, GravityModel::kTwoBody, kEarthDefault);
}

double one_day_position_error_m(const AdaptiveOptions& opt, IntegrationStats* stats) {
  const StateEci s0 = test::leo_e01();
  const Vec6 x1 = propagate_adaptive(two_body, 0.0, s0.stacked(), kSecondsPerDay, opt, stats);
  const StateEci truth = propagate_kepler(s0, kSecondsPerDay, kMu);
  return (x1.head<3>() - truth.r_eci_m).norm();
}

// Requirement of the default preset (adaptive_options.hpp): < 1 m after one day, e = 0.1 LEO.
TEST(AdaptiveVsKepler, DefaultToleranceKeepsOneDayPositionErrorBelowOneMetre) {
  IntegrationStats stats;
  const double err_m = one_day_position_error_m(AdaptiveOptions{}, &stats);
  std::printf("default: 1-day position error %.3e m, %ld steps, %ld rejected, %ld f-evals\n",
              err_m, stats.steps_accepted, stats.steps_rejected, stats.rhs_evaluations);
  EXPECT_LT(err_m, 1.0);
}

// Requirement of the tight preset: < 1 mm after one day.
TEST(AdaptiveVsKepler, TightToleranceKeepsOneDayPositionErrorBelowOneMillimetre) {
  IntegrationStats stats;
  const double err_m = one_day_position_error_m(AdaptiveOptions::tight(), &stats);
  std::printf("tight: 1-day position error %.3e m, %ld steps, %ld rejected, %ld f-evals\n",
              err_m, stats.steps_accepted, stats.steps_rejected, stats.rhs_evaluations);
  EXPECT_LT(err_m, 1e-3);
}

// A tighter tolerance must buy accuracy: the error shrinks by at least 100x from default to
// tight (tolerance ratio 1000, error ~ tol^(8/9) for an 8th-order method).
TEST(AdaptiveVsKepler, ErrorFallsWithTolerance) {
  const double e_default = one_day_position_error_m(AdaptiveOptions{}, nullptr);
  const double e_tight = one_day_position_error_m(AdaptiveOptions::tight(), nullptr);
  EXPECT_LT(e_tight * 100.0, e_default);
}

// Energy and angular momentum are integrals of the two-body problem. With the tight preset
// the one-day position error is < 1 mm; an energy error dE/E = da/a would produce an
// along-track drift 1.5 n t da ~ 120 a (dE/E) over 13 orbits, so < 1 mm implies
// |dE/E| < ~1e-12; we require 1e-12 for energy and likewise for |h| (dh/h ~ da/(2a)).
TEST(AdaptiveVsKepler, TightToleranceConservesEnergyAndAngularMomentum) {
  const StateEci s0 = test::leo_e01();
  Dop853<Vec6> integ(two_body, AdaptiveOptions::tight());
  integ.reset(0.0, s0.stacked());
  const double e0 = test::specific_energy(s0, kMu);
  const Vec3 h0 = s0.r_eci_m.cross(s0.v_eci_mps);
  double worst_de = 0.0;
  double worst_dh = 0.0;
  while (integ.t_s() < kSecondsPerDay) {
    ASSERT_TRUE(integ.step(kSecondsPerDay)) << integ.failure_reason();
    const StateEci s = StateEci::from_stacked(integ.x());
    worst_de = std::max(worst_de, std::abs(test::specific_energy(s, kMu) / e0 - 1.0));
    worst_dh = std::max(worst_dh, (s.r_eci_m.cross(s.v_eci_mps) - h0).norm() / h0.norm());
  }
  std::printf("tight: max |dE/E| = %.3e, max |dh|/|h| = %.3e\n", worst_de, worst_dh);
  EXPECT_LT(worst_de, 1e-12);
  EXPECT_LT(worst_dh, 1e-12);
}

// Backward integration (t1 < t0) must retrace the orbit: forward one day then back, tight.
// Each leg errs < 1 mm (test above), so the round trip errs < 2 mm.
TEST(AdaptiveVsKepler, BackwardIntegrationRetracesTheOrbit) {
  const StateEci s0 = test::leo_e01();
  const AdaptiveOptions opt = AdaptiveOptions::tight();
  const Vec6 x1 = propagate_adaptive(two_body, 0.0, s0.stacked(), kSecondsPerDay, opt);
  const Vec6 back = propagate_adaptive(two_body, kSecondsPerDay, x1, 0.0, opt);
  EXPECT_LT((back.head<3>() - s0.r_eci_m).norm(), 2e-3);
  // Backward alone against Kepler.
  const Vec6 xm = propagate_adaptive(two_body, 0.0, s0.stacked(), -kSecondsPerDay, opt);
  EXPECT_LT((xm.head<3>() - propagate_kepler(s0, -kSecondsPerDay, kMu).r_eci_m).norm(), 1e-3);
}

// The 7th-order dense output between steps must be as good as the step ends: sampled on
// a fine grid over one orbit with the tight preset, error < 1 mm at every sample.
TEST(AdaptiveVsKepler, DenseOutputMatchesKeplerInsideSteps) {
  const StateEci s0 = test::leo_e01();
  Dop853<Vec6> integ(two_body, AdaptiveOptions::tight());
  integ.reset(0.0, s0.stacked());
  const double t_end = 6500.0;
  double worst = 0.0;
  int samples = 0;
  while (integ.t_s() < t_end) {
    ASSERT_TRUE(integ.step(t_end));
    for (int j = 1; j < 10; ++j) {
      const double t = integ.t_prev_s() + 0.1 * j * (integ.t_s() - integ.t_prev_s());
      const Vec6 xd = integ.dense(t);
      worst = std::max(worst, (xd.head<3>() - propagate_kepler(s0, t, kMu).r_eci_m).norm());
      ++samples;
    }
    // Continuity: dense output reproduces both ends of the step.
    EXPECT_LT((integ.dense(integ.t_s()) - integ.x()).head<3>().norm(), 1e-6);
    EXPECT_LT((integ.dense(integ.t_prev_s()) - integ.x_prev()).head<3>().norm(), 1e-9);
  }
  std::printf("dense output: worst position error %.3e m over %d samples\n", worst, samples);
  EXPECT_GT(samples, 50);
  EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace evade
