// Message <-> struct conversion is bit-exact for every double (docs/GUIDANCE_NODE.md NODE-IF-2).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/validate.hpp"

namespace evade::guidance_lcm {
namespace {

TEST(Convert, AnglesAndNavRoundTripBitExact) {
  guidance::AnglesMeasurement m;
  m.utime_us = 123456789;
  m.seq = 5;
  m.elevation_rad = 0.1 + 1e-17;
  m.azimuth_rad = std::nextafter(1.0, 2.0);
  m.sigma_angle_rad = 3e-6;
  m.has_rates = true;
  m.elevation_rate_radps = 1.234567890123e-9;
  m.azimuth_rate_radps = -4e-9;
  m.sigma_rate_radps = 1e-10;
  m.has_range = true;
  m.range_m = 10000.000000001;
  m.range_rate_mps = -6712.4;
  m.valid = true;
  evade_angles_t msg{};
  to_lcm(m, 77, &msg);
  std::uint8_t buf[512];
  const int n = msg.encode(buf, 0, sizeof(buf));
  evade_angles_t back{};
  ASSERT_EQ(back.decode(buf, 0, n), n);
  guidance::AnglesMeasurement m2;
  from_lcm(back, &m2);
  EXPECT_EQ(m2.utime_us, m.utime_us);
  EXPECT_EQ(m2.seq, 77);
  EXPECT_EQ(m2.elevation_rad, m.elevation_rad);
  EXPECT_EQ(m2.azimuth_rad, m.azimuth_rad);
  EXPECT_EQ(m2.elevation_rate_radps, m.elevation_rate_radps);
  EXPECT_EQ(m2.range_m, m.range_m);
  EXPECT_EQ(m2.range_rate_mps, m.range_rate_mps);

  guidance::NavState nav;
  nav.utime_us = 42;
  nav.r_eci_m = Vec3(7.0e6 + 1e-9, -1.0 / 3.0, 2.0);
  nav.v_eci_mps = Vec3(1.0 / 7.0, 7546.123456789, -0.0);
  nav.valid = true;
  evade_nav_state_t nm{};
  to_lcm(nav, 3, &nm);
  guidance::NavState nav2;
  from_lcm(nm, &nav2);
  EXPECT_EQ(nav2.r_eci_m, nav.r_eci_m);
  EXPECT_EQ(nav2.v_eci_mps, nav.v_eci_mps);
  EXPECT_EQ(nav2.utime_us, 42);
}

// The command and the status the node publishes, read back by a subscriber (the simulator,
// the HIL scripts): bit-exact through the encoded bytes. The status carries ZEM and t_go
// only as a pair (has_range), and never a stale value of an invalid one.
TEST(Convert, CommandAndStatusRoundTripBitExact) {
  guidance::ThrustCommand c;
  c.utime_us = 1700000000123456LL;
  c.mode = guidance::GuidanceMode::kEvade;
  c.u_eci = Vec3(1.0 / 3.0, -std::sqrt(5.0 / 9.0), 1.0 / 3.0);
  c.accel_mps2 = 0.1 + 1e-17;
  c.reason = guidance::CommandReason::kLowLosRate;
  evade_thrust_cmd_t cm{};
  to_lcm(c, 41, 1700000000100000LL, &cm);
  std::uint8_t buf[1024];
  int n = cm.encode(buf, 0, sizeof(buf));
  evade_thrust_cmd_t cback{};
  ASSERT_EQ(cback.decode(buf, 0, n), n);
  EXPECT_EQ(cback.seq, 41);
  EXPECT_EQ(cback.input_utime, 1700000000100000LL);
  guidance::ThrustCommand c2;
  from_lcm(cback, &c2);
  EXPECT_EQ(c2.utime_us, c.utime_us);
  EXPECT_EQ(c2.mode, c.mode);
  EXPECT_EQ(c2.u_eci, c.u_eci);
  EXPECT_EQ(c2.accel_mps2, c.accel_mps2);
  EXPECT_EQ(c2.reason, c.reason);

  guidance::GuidanceStatus s;
  s.mode = guidance::GuidanceMode::kTracking;
  s.reason = guidance::CommandReason::kZemAboveTrigger;
  s.track_valid = true;
  s.los_rate_radps = 1.234567890123e-3;
  s.los_rate_var_rad2ps2 = 1e-13;
  s.e_theta_eci = Vec3(0.0, std::nextafter(1.0, 0.0), -0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s.e_theta_cov_eci(i, j) = 1e-6 * (3 * i + j + 1) / 7.0;
  s.zem_valid = s.t_go_valid = true;
  s.zem_m = 123.456789;
  s.t_go_s = 9.87654321;
  s.dv_used_mps = 0.75;
  evade_guidance_status_t sm{};
  to_lcm(s, &sm);
  sm.utime = 99;
  sm.cycles = 1234;
  n = sm.encode(buf, 0, sizeof(buf));
  evade_guidance_status_t sback{};
  ASSERT_EQ(sback.decode(buf, 0, n), n);
  guidance::GuidanceStatus s2;
  from_lcm(sback, &s2);
  EXPECT_EQ(s2.utime_us, 99);
  EXPECT_EQ(s2.cycles, 1234);
  EXPECT_EQ(s2.mode, s.mode);
  EXPECT_EQ(s2.reason, s.reason);
  EXPECT_EQ(s2.track_valid, s.track_valid);
  EXPECT_EQ(s2.los_rate_radps, s.los_rate_radps);
  EXPECT_EQ(s2.los_rate_var_rad2ps2, s.los_rate_var_rad2ps2);
  EXPECT_EQ(s2.e_theta_eci, s.e_theta_eci);
  EXPECT_EQ(s2.e_theta_cov_eci, s.e_theta_cov_eci);
  EXPECT_TRUE(s2.zem_valid && s2.t_go_valid);
  EXPECT_EQ(s2.zem_m, s.zem_m);
  EXPECT_EQ(s2.t_go_s, s.t_go_s);
  EXPECT_EQ(s2.dv_used_mps, s.dv_used_mps);

  // One of the pair invalid: no range, and the invalid one is sent as 0, not its old value.
  s.t_go_valid = false;
  to_lcm(s, &sm);
  EXPECT_FALSE(sm.has_range);
  EXPECT_EQ(sm.zem_m, s.zem_m);
  EXPECT_EQ(sm.t_go_s, 0.0);
  s.zem_valid = false;
  s.t_go_valid = true;
  to_lcm(s, &sm);
  EXPECT_FALSE(sm.has_range);
  EXPECT_EQ(sm.zem_m, 0.0);
  EXPECT_EQ(sm.t_go_s, s.t_go_s);
  from_lcm(sm, &s2);
  EXPECT_FALSE(s2.zem_valid || s2.t_go_valid);
}

}  // namespace
}  // namespace evade::guidance_lcm
