// The node's watchdog and its outputs (docs/GUIDANCE_NODE.md NODE-WD-1, NODE-OUT-1): silence, or angles
// flagged invalid, go SAFE one stale limit after the last valid measurement and recover; one command
// per cycle with increasing seq; disarm stops thrust and arm resumes it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fault_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

TEST(NodeFaults, SilenceGoesSafeWithinOneCycleOfStaleLimitThenRecovers) {
  Rig rig;  // stale limit 0.5 s, 50 Hz
  std::int64_t t = 1000000;
  std::int64_t seq = 1;
  for (int k = 0; k < 50; ++k, t += kPeriodUs) rig.good_cycle(t, seq++);
  ASSERT_GT(rig.node.last_command().accel_mps2, 0.0) << "evading before the silence";
  const std::int64_t last_meas = t - kPeriodUs;
  // Silence on the angles channel (nav keeps coming, as from an independent navigator).
  std::int64_t first_safe = -1;
  for (int k = 0; k < 60; ++k, t += kPeriodUs) {
    evade_nav_state_t n{};
    rig.enc.nav_at(t, &n);
    n.seq = seq++;
    rig.pub.send(kChanNav, n);
    const evade_thrust_cmd_t c = rig.cycle(t);
    if (c.mode == evade_thrust_cmd_t::MODE_SAFE && first_safe < 0) first_safe = t;
    if (first_safe >= 0) {
      EXPECT_EQ(c.mode, evade_thrust_cmd_t::MODE_SAFE);
      EXPECT_EQ(c.accel_mps2, 0.0);
      EXPECT_EQ(c.reason, evade_thrust_cmd_t::REASON_MEASUREMENT_STALE);
    }
  }
  ASSERT_GE(first_safe, 0) << "never went SAFE";
  const std::int64_t age_at_safe = first_safe - last_meas;
  EXPECT_GT(age_at_safe, 500000);
  EXPECT_LE(age_at_safe, 500000 + kPeriodUs) << "SAFE within one cycle of the stale limit";
  EXPECT_GT(rig.node.watchdog_cycles(), 0) << "the node's own watchdog fired";
  // Data again: leaves SAFE and evades again. The law's filter, having predicted 1.7 s at
  // a constant LOS rate, gates out the first measurements and re-initialises after
  // max_consecutive_rejects (25): recovery within 25 + min_track_updates + a few cycles.
  bool recovered = false;
  for (int k = 0; k < 40; ++k, t += kPeriodUs) {
    const evade_thrust_cmd_t c = rig.good_cycle(t, seq++);
    recovered = recovered || (c.mode == evade_thrust_cmd_t::MODE_EVADE && c.accel_mps2 > 0.0);
  }
  EXPECT_TRUE(recovered);
  expect_accounted(rig.node, rig.pub.published());
}

// NODE-WD-1: angles messages flagged invalid are consumed (the sensor is alive and says it
// has no measurement) but are not measurements: they do not keep the watchdog alive, so the
// node goes SAFE one stale limit after the last valid one, as under silence.
TEST(NodeFaults, AnglesFlaggedInvalidDoNotKeepTheWatchdogAlive) {
  Rig rig;  // stale limit 0.5 s, 50 Hz
  std::int64_t t = 1000000;
  std::int64_t seq = 1;
  for (int k = 0; k < 50; ++k, t += kPeriodUs) rig.good_cycle(t, seq++);
  ASSERT_GT(rig.node.last_command().accel_mps2, 0.0) << "evading before the invalid angles";
  const std::int64_t last_valid = t - kPeriodUs;
  const std::int64_t consumed_before = rig.node.counts().consumed;
  std::int64_t first_safe = -1;
  for (int k = 0; k < 40; ++k, t += kPeriodUs) {
    evade_nav_state_t n{};
    rig.enc.nav_at(t, &n);
    n.seq = seq;
    rig.pub.send(kChanNav, n);
    evade_angles_t a{};
    rig.enc.angles_at(t, &a);
    a.seq = seq++;
    a.valid = false;
    rig.pub.send(kChanAngles, a);
    const evade_thrust_cmd_t c = rig.cycle(t);
    if (c.mode == evade_thrust_cmd_t::MODE_SAFE && first_safe < 0) first_safe = t;
    if (first_safe >= 0) {
      EXPECT_EQ(c.accel_mps2, 0.0);
    }
  }
  ASSERT_GE(first_safe, 0) << "never went SAFE on invalid-only angles";
  EXPECT_GT(first_safe - last_valid, 500000);
  EXPECT_LE(first_safe - last_valid, 500000 + kPeriodUs);
  EXPECT_GT(rig.node.watchdog_cycles(), 0) << "the node's own watchdog fired";
  EXPECT_EQ(rig.node.counts().consumed - consumed_before, 80) << "40 nav + 40 invalid angles";
  EXPECT_EQ(rig.node.counts().rejected, 0);
  expect_accounted(rig.node, rig.pub.published());
}

TEST(NodeFaults, OneCommandPerCycleWithIncreasingSeq) {
  Rig rig;
  std::int64_t t = 1000000;
  for (int k = 0; k < 100; ++k, t += kPeriodUs) {
    if (k % 7 != 3) rig.send_good(t, k + 1);  // some cycles without input
    rig.cycle(t);
  }
  rig.flush();
  const auto& cmds = rig.rec.commands();
  ASSERT_EQ(cmds.size(), 100u);
  for (std::size_t i = 0; i < cmds.size(); ++i) {
    EXPECT_EQ(cmds[i].seq, static_cast<std::int64_t>(i + 1));
    EXPECT_EQ(cmds[i].utime, 1000000 + static_cast<std::int64_t>(i) * kPeriodUs);
    const double n = std::sqrt(cmds[i].u_eci[0] * cmds[i].u_eci[0] +
                               cmds[i].u_eci[1] * cmds[i].u_eci[1] +
                               cmds[i].u_eci[2] * cmds[i].u_eci[2]);
    if (cmds[i].accel_mps2 > 0.0) {
      EXPECT_NEAR(n, 1.0, 1e-12);
    }
    EXPECT_EQ(validate(cmds[i]), Reason::kOk);
  }
}

TEST(NodeFaults, DisarmStopsThrustAndArmResumes) {
  Rig rig;
  std::int64_t t = 1000000;
  std::int64_t seq = 1;
  for (int k = 0; k < 30; ++k, t += kPeriodUs) rig.good_cycle(t, seq++);
  ASSERT_GT(rig.node.last_command().accel_mps2, 0.0);
  evade_arm_t arm{};
  arm.utime = t;
  arm.seq = 1;
  arm.armed = false;
  rig.pub.send(kChanArm, arm);
  EXPECT_EQ(rig.good_cycle(t, seq++).accel_mps2, 0.0);
  t += kPeriodUs;
  arm.utime = t;
  arm.seq = 2;
  arm.armed = true;
  rig.pub.send(kChanArm, arm);
  bool thrust = false;
  for (int k = 0; k < 10; ++k, t += kPeriodUs) thrust = thrust || rig.good_cycle(t, seq++).accel_mps2 > 0.0;
  EXPECT_TRUE(thrust);
  expect_accounted(rig.node, rig.pub.published());
}

}  // namespace
}  // namespace evade::guidance_lcm::test
