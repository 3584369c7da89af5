// The closest approach of a HIL run from its samples (src/hil/conjunction_hil_report.cpp;
// docs/AUTONOMY.md AUT-11): straight-line relative motion within half the samples' spacing.
#include <cmath>

#include <gtest/gtest.h>

#include "evade/hil/conjunction_hil.hpp"

namespace {

using namespace evade;

// Samples every 20 ms of two objects passing in straight lines: the closest approach between
// two samples is found exactly (to rounding), not at the nearer sample.
TEST(HilClosestApproach, FindsTheMinimumBetweenSamples) {
  sim::PlanRunResult r;
  const Vec3 w(7000.0, 1000.0, 0.0);  // relative velocity [m/s]
  const Vec3 miss(0.0, 0.0, 42.0);
  const double t_ca = 10.0073;        // between two samples
  for (int k = 0; k <= 1000; ++k) {
    sim::PlanRunSample s;
    s.t_s = 0.02 * k;
    s.satellite = {Vec3(7e6, 0.0, 0.0), Vec3(0.0, 7500.0, 0.0)};
    s.other = {s.satellite.r_eci_m + miss + (s.t_s - t_ca) * w, s.satellite.v_eci_mps + w};
    r.samples.push_back(s);
  }
  const hil::HilClosest c = hil::hil_closest_approach(r);
  EXPECT_NEAR(c.miss_m, 42.0, 1e-6);
  EXPECT_NEAR(c.t_s, t_ca, 1e-9);
}

TEST(HilClosestApproach, NoSamplesGiveNoApproach) {
  EXPECT_TRUE(std::isinf(hil::hil_closest_approach(sim::PlanRunResult{}).miss_m));
}

}  // namespace
