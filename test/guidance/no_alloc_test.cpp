// GuidanceLaw::step must not allocate (real-time code allocates nothing after
// initialization): count operator new calls across 10 000 steps of a tracked, evading
// encounter with noisy angles.
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>

#include <gtest/gtest.h>

#include "evade/guidance/guidance_law.hpp"
#include "evade/guidance/los_geometry.hpp"

#include "support/counting_new.hpp"

namespace {

using evade::Vec3;
using namespace evade::guidance;

TEST(GuidanceNoAlloc, StepDoesNotAllocateOverTenThousandCycles) {
  GuidanceConfig cfg;
  cfg.dv_budget_mps = 1e4;
  cfg.max_burn_s = 1e5;
  GuidanceLaw law(cfg);
  std::mt19937_64 rng(1);
  std::normal_distribution<double> n(0.0, 1.0);
  GuidanceInput in;
  in.armed = true;
  in.nav.valid = true;
  in.nav.r_eci_m = Vec3(6.8e6, 0, 0);
  in.nav.v_eci_mps = Vec3(0, 7500, 0);
  const long before = g_news.load();
  for (int k = 0; k < 10000; ++k) {
    const std::int64_t now = 1'000'000 + 20'000LL * k;
    const double t = 0.02 * k;
    const Vec3 u = Vec3(std::cos(1e-3 * t), std::sin(1e-3 * t), 0.1).normalized();
    const LosAngles a = los_angles_from_unit(u);
    in.nav.utime_us = now;
    in.has_measurement = (k % 3 != 2);  // some cycles without a measurement
    in.meas.utime_us = now;
    in.meas.valid = true;
    in.meas.elevation_rad = a.elevation_rad + 50e-6 * n(rng);
    in.meas.azimuth_rad = a.azimuth_rad + 50e-6 * n(rng);
    in.meas.sigma_angle_rad = 50e-6;
    in.meas.has_rates = (k % 2 == 0);
    in.meas.elevation_rate_radps = 0.0;
    in.meas.azimuth_rate_radps = 1e-3;
    in.meas.sigma_rate_radps = 1e-5;
    const ThrustCommand c = law.step(in, now);
    ASSERT_TRUE(c.u_eci.allFinite());
  }
  EXPECT_EQ(g_news.load() - before, 0);
  EXPECT_GT(law.status().cycles, 9999);
}

}  // namespace
