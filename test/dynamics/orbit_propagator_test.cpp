// Orbit propagation entry points used by the other modules.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "evade/dynamics/kepler_propagator.hpp"
#include "evade/dynamics/orbit_propagator.hpp"
#include "test_orbits.hpp"

namespace evade {
namespace {

TEST(OrbitPropagator, TwoBodyModelIsTheAnalyticKeplerSolution) {
  const StateEci s0 = test::leo_e01();
  const StateEci a = propagate_orbit(s0, 5000.0, GravityModel::kTwoBody);
  const StateEci b = propagate_kepler(s0, 5000.0, kEarthDefault.mu_m3ps2);
  EXPECT_EQ(a.r_eci_m, b.r_eci_m);
  EXPECT_EQ(a.v_eci_mps, b.v_eci_mps);
}

// The numerical path with J2 = 0 is a two-body integration: default preset < 1 m per day.
TEST(OrbitPropagator, NumericalPathWithZeroJ2MatchesKepler) {
  EarthModel no_j2 = kEarthDefault;
  no_j2.j2 = 0.0;
  const StateEci s0 = test::leo_e01();
  IntegrationStats stats;
  const StateEci s = propagate_orbit(s0, kSecondsPerDay, GravityModel::kTwoBodyJ2, no_j2, {}, &stats);
  EXPECT_LT((s.r_eci_m - propagate_kepler(s0, kSecondsPerDay, no_j2.mu_m3ps2).r_eci_m).norm(), 1.0);
  EXPECT_GT(stats.steps_accepted, 0);
}

// J2 visibly changes the orbit: after one day the J2 and two-body positions differ by far
// more than the integration error (J2 moves the node by ~5e-3 rad/day here: ~ tens of km).
TEST(OrbitPropagator, J2ChangesTheOrbit) {
  const StateEci s0 = test::leo_e01();
  const StateEci a = propagate_orbit(s0, kSecondsPerDay, GravityModel::kTwoBodyJ2);
  const StateEci b = propagate_orbit(s0, kSecondsPerDay, GravityModel::kTwoBody);
  EXPECT_GT((a.r_eci_m - b.r_eci_m).norm(), 10e3);
}

// Samples from one dense-output integration equal separate propagations to each time, in
// any order and either sign. Both use the tight preset (< 1 mm each): allow 2 mm.
TEST(OrbitPropagator, SamplesMatchSeparatePropagations) {
  const StateEci s0 = test::leo_e01();
  const std::vector<double> dt = {3000.0, -1234.5, 10.0, 86400.0, -20000.0, 0.0, 500.25};
  const AdaptiveOptions opt = AdaptiveOptions::tight();
  const std::vector<StateEci> samples =
      propagate_orbit_samples(s0, dt, GravityModel::kTwoBodyJ2, kEarthDefault, opt);
  ASSERT_EQ(samples.size(), dt.size());
  for (std::size_t k = 0; k < dt.size(); ++k) {
    const StateEci single = propagate_orbit(s0, dt[k], GravityModel::kTwoBodyJ2, kEarthDefault, opt);
    EXPECT_LT((samples[k].r_eci_m - single.r_eci_m).norm(), 2e-3) << dt[k];
  }
  EXPECT_EQ(samples[5].r_eci_m, s0.r_eci_m);  // dt = 0 is the initial state
}

TEST(OrbitPropagator, RejectsNonFiniteInput) {
  StateEci bad = test::leo_e01();
  bad.v_eci_mps.x() = NAN;
  EXPECT_THROW(propagate_orbit(bad, 10.0, GravityModel::kTwoBodyJ2), std::invalid_argument);
  EXPECT_THROW(propagate_orbit(test::leo_e01(), NAN, GravityModel::kTwoBody), std::invalid_argument);
  EXPECT_THROW(propagate_orbit_samples(test::leo_e01(), {1.0, INFINITY}, GravityModel::kTwoBodyJ2),
               std::invalid_argument);
}

// An orbit through the Earth's centre makes the integration fail loudly, not return NaN.
TEST(OrbitPropagator, ReportsIntegrationFailure) {
  const StateEci radial{{7000e3, 0.0, 0.0}, {-100.0, 0.0, 0.0}};  // falls straight in
  EXPECT_THROW(propagate_orbit(radial, 5000.0, GravityModel::kTwoBodyJ2), std::runtime_error);
}

}  // namespace
}  // namespace evade
