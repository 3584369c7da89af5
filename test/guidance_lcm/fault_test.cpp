// Fault tests of the guidance node over memq:// (docs/GUIDANCE_NODE.md NODE-IN-1..5, NODE-WD-1,
// NODE-OUT-1). Each case: no crash, no thrust from bad data (the commands equal those of a
// reference node that saw only the good messages), and every published input message is
// counted exactly once: consumed + rejected + stale + superseded + dropped = published.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "node_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

void expect_accounted(const GuidanceNode& node, std::int64_t published) {
  const InputCounts& c = node.counts();
  EXPECT_EQ(c.received, published);
  EXPECT_EQ(c.accounted(), published)
      << "consumed " << c.consumed << " rejected " << c.rejected << " stale " << c.stale
      << " superseded " << c.superseded << " dropped " << c.dropped;
}

bool same_command(const evade_thrust_cmd_t& a, const evade_thrust_cmd_t& b) {
  return a.utime == b.utime && a.seq == b.seq && a.mode == b.mode && a.reason == b.reason &&
         a.accel_mps2 == b.accel_mps2 && a.u_eci[0] == b.u_eci[0] && a.u_eci[1] == b.u_eci[1] &&
         a.u_eci[2] == b.u_eci[2] && a.input_utime == b.input_utime;
}

// A bad message injected into cycle k by `inject`; the reference rig sees only good data.
// Returns the number of bad messages published.
template <typename Inject>
void run_against_reference(int cycles, Inject inject, Verdict expected_verdict,
                           std::int64_t expected_bad) {
  Rig dut;
  Rig ref;
  std::int64_t bad = 0;
  bool evaded = false;
  for (int k = 0; k < cycles; ++k) {
    const std::int64_t t = 1000000 + k * kPeriodUs;
    dut.send_good(t, k + 1);
    bad += inject(dut, k, t);
    const evade_thrust_cmd_t c = dut.cycle(t);
    const evade_thrust_cmd_t r = ref.good_cycle(t, k + 1);
    ASSERT_TRUE(same_command(c, r)) << "cycle " << k << ": bad data changed the command";
    evaded = evaded || c.accel_mps2 > 0.0;
  }
  EXPECT_TRUE(evaded) << "the scenario must make the law thrust, or the test proves nothing";
  EXPECT_EQ(bad, expected_bad);
  expect_accounted(dut.node, dut.pub.published());
  const InputCounts& c = dut.node.counts();
  const std::int64_t bad_counted = expected_verdict == Verdict::kRejected ? c.rejected : c.stale;
  EXPECT_EQ(bad_counted, expected_bad);
}

TEST(NodeFaults, RejectsNaNInfAndOutOfRangeAngles) {
  // Every 3rd cycle one bad angles message with a fresh seq, after the good one.
  std::int64_t seq = 100000;
  run_against_reference(
      150,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 3 != 0) return 0;
        evade_angles_t a{};
        r.enc.angles_at(t, &a);
        a.seq = ++seq;  // newer seq than the good one: only validation can stop it
        switch ((k / 3) % 6) {
          case 0: a.elevation_rad = kNaN; break;
          case 1: a.azimuth_rad = kInf; break;
          case 2: a.elevation_rad = 1.6; break;  // > pi/2
          case 3: a.azimuth_rad = 7.0; break;    // > 2 pi
          case 4: a.sigma_angle_rad = -1e-3; break;
          case 5: a.has_rates = true; a.elevation_rate_radps = kNaN; a.sigma_rate_radps = 1e-4; break;
        }
        r.pub.send(kChanAngles, a);
        return 1;
      },
      Verdict::kRejected, 50);
}

TEST(NodeFaults, RejectsNaNNavState) {
  std::int64_t seq = 100000;
  run_against_reference(
      100,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 4 != 1) return 0;
        evade_nav_state_t n{};
        r.enc.nav_at(t, &n);
        n.seq = ++seq;
        if (k % 8 == 1) n.r_eci_m[1] = kNaN; else n.v_eci_mps[2] = -kInf;
        r.pub.send(kChanNav, n);
        return 1;
      },
      Verdict::kRejected, 25);
}

TEST(NodeFaults, StaleUtimeIsCountedStaleAndIgnored) {
  std::int64_t seq = 100000;
  run_against_reference(
      100,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 5 != 2) return 0;
        evade_angles_t a{};
        r.enc.angles_at(t - 600000, &a);  // 0.6 s old > 0.5 s stale limit
        a.elevation_rad += 0.1;           // and wrong, so using it would show
        a.seq = ++seq;
        r.pub.send(kChanAngles, a);
        return 1;
      },
      Verdict::kStale, 20);
}

TEST(NodeFaults, DuplicatedAndOutOfOrderSeqAreStale) {
  run_against_reference(
      100,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k < 2 || k % 2 != 0) return 0;
        evade_angles_t a{};
        r.enc.angles_at(t, &a);
        a.elevation_rad += 0.05;                 // wrong data: must not be used
        a.seq = (k % 4 == 0) ? k + 1 : k - 1;    // duplicate of this cycle's, or older
        r.pub.send(kChanAngles, a);
        return 1;
      },
      Verdict::kStale, 49);
}

TEST(NodeFaults, WrongTypeAndCorruptBytesAreRejected) {
  run_against_reference(
      60,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 2 != 1) return 0;
        switch ((k / 2) % 4) {
          case 0: {  // a nav message on the angles channel: fingerprint mismatch
            evade_nav_state_t n{};
            r.enc.nav_at(t, &n);
            n.seq = 1000000 + k;
            r.pub.send(kChanAngles, n);
            break;
          }
          case 1: {  // an angles message truncated by 5 bytes
            evade_angles_t a{};
            r.enc.angles_at(t, &a);
            a.seq = 1000000 + k;
            std::uint8_t buf[512];
            const int n = a.encode(buf, 0, sizeof(buf));
            r.pub.send_bytes(kChanAngles, buf, static_cast<unsigned>(n - 5));
            break;
          }
          case 2: {  // random bytes on the nav channel
            std::uint8_t buf[64];
            for (int i = 0; i < 64; ++i) buf[i] = static_cast<std::uint8_t>(37 * i + k);
            r.pub.send_bytes(kChanNav, buf, sizeof(buf));
            break;
          }
          case 3: {  // larger than any input type
            static std::uint8_t big[4096] = {};
            r.pub.send_bytes(kChanAngles, big, sizeof(big));
            break;
          }
        }
        return 1;
      },
      Verdict::kRejected, 30);
}

TEST(NodeFaults, GappedSeqIsUsedAndGapsCounted) {
  Rig rig;
  std::int64_t t = 1000000;
  std::int64_t seqs[] = {1, 2, 3, 7, 8, 20};
  for (std::int64_t s : seqs) {
    rig.good_cycle(t, s);
    t += kPeriodUs;
  }
  EXPECT_EQ(rig.node.counts().seq_gaps, 2 * (3 + 11));  // nav and angles each: 4..6, 9..19
  EXPECT_EQ(rig.node.counts().consumed, 2 * 6);
  expect_accounted(rig.node, rig.pub.published());
}

TEST(NodeFaults, FutureUtimeIsRejected) {
  Rig rig;
  rig.good_cycle(1000000, 1);
  evade_angles_t a{};
  rig.enc.angles_at(1000000 + kPeriodUs + 200000, &a);  // 0.2 s ahead > 0.05 s tolerance
  a.seq = 2;
  rig.pub.send(kChanAngles, a);
  rig.cycle(1000000 + kPeriodUs);
  EXPECT_EQ(rig.node.counts().by_reason[static_cast<int>(Reason::kFromFuture)], 1);
  expect_accounted(rig.node, rig.pub.published());
}

TEST(NodeFaults, BurstLargerThanQueueIsDroppedAndCounted) {
  NodeConfig cfg;
  cfg.queue_capacity = 8;
  Rig rig(cfg);
  std::int64_t t = 1000000;
  std::int64_t seq = 1;
  for (int k = 0; k < 10; ++k, t += kPeriodUs) rig.good_cycle(t, seq++);
  const InputCounts before = rig.node.counts();
  // 40 angles messages between two cycles: the queue keeps the newest 8.
  for (int i = 0; i < 40; ++i) {
    evade_angles_t a{};
    rig.enc.angles_at(t - (40 - i) * 100, &a);
    a.seq = seq++;
    rig.pub.send(kChanAngles, a);
  }
  const evade_thrust_cmd_t c = rig.cycle(t);
  const InputCounts& after = rig.node.counts();
  EXPECT_EQ(after.dropped - before.dropped, 32);
  EXPECT_EQ(after.superseded - before.superseded, 7);
  EXPECT_EQ(after.consumed - before.consumed, 1);
  EXPECT_EQ(c.input_utime, t - 100) << "the newest message of the burst is the one used";
  expect_accounted(rig.node, rig.pub.published());
}

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

TEST(NodeFaults, OnlyBadDataNeverThrusts) {
  Rig rig;
  std::int64_t t = 1000000;
  for (int k = 0; k < 100; ++k, t += kPeriodUs) {
    evade_nav_state_t n{};
    rig.enc.nav_at(t, &n);
    n.seq = k + 1;
    rig.pub.send(kChanNav, n);
    evade_angles_t a{};
    rig.enc.angles_at(t, &a);
    a.seq = k + 1;
    a.elevation_rad = (k % 2) ? kNaN : 2.0;
    rig.pub.send(kChanAngles, a);
    EXPECT_EQ(rig.cycle(t).accel_mps2, 0.0);
  }
  EXPECT_EQ(rig.node.counts().rejected, 100);
  expect_accounted(rig.node, rig.pub.published());
}

// NODE-IN-4 (issue: one well-formed message with seq + 10^12 used to be accepted, and every
// genuine message after it was out of order: the node sat in SAFE). The spoof is rejected
// and the commands equal those of a node that never saw it.
TEST(NodeFaults, OneSpoofedSeqJumpCannotLockOutTheSensor) {
  run_against_reference(
      150,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k != 10) return 0;
        evade_angles_t a{};
        r.enc.angles_at(t, &a);
        a.elevation_rad += 0.05;               // wrong data: must not be used
        a.seq = k + 1 + 1000000000000LL;       // seq + 10^12
        r.pub.send(kChanAngles, a);
        return 1;
      },
      Verdict::kRejected, 1);
}

// NODE-IN-4: a genuine sender restart (seq back to 1, time going on) is followed after one
// message per channel; the node keeps evading.
TEST(NodeFaults, GenuineSenderRestartIsFollowed) {
  Rig rig;
  std::int64_t t = 1000000;
  for (int k = 0; k < 40; ++k, t += kPeriodUs) rig.good_cycle(t, 1000 + k);
  for (int k = 0; k < 40; ++k, t += kPeriodUs) {
    const evade_thrust_cmd_t& c = rig.good_cycle(t, 1 + k);  // the sender restarted
    if (k >= 2) {
      EXPECT_NE(c.mode, evade_thrust_cmd_t::MODE_SAFE) << "cycle " << k << " after the restart";
    }
  }
  EXPECT_EQ(rig.node.counts().seq_restarts, 2);  // angles and nav
  EXPECT_EQ(rig.node.counts().by_reason[static_cast<int>(Reason::kOutOfOrderSeq)], 2);
  EXPECT_EQ(rig.node.counts().seq_gaps, 0);
  expect_accounted(rig.node, rig.pub.published());
}

// seq_gaps means numbers never received: messages the node dropped from its own full queue
// were received and counted as dropped, not as gaps.
TEST(NodeFaults, QueueDropsAreNotCountedAsSeqGaps) {
  NodeConfig cfg;
  cfg.queue_capacity = 4;
  Rig rig(cfg);
  std::int64_t t = 1000000;
  rig.good_cycle(t, 1);
  t += kPeriodUs;
  evade_nav_state_t nav{};
  rig.enc.nav_at(t, &nav);
  nav.seq = 2;
  for (std::int64_t s = 2; s <= 11; ++s) {  // a burst of ten angles messages
    evade_angles_t a{};
    rig.enc.angles_at(t, &a);
    a.seq = s;
    rig.pub.send(kChanAngles, a);
  }
  rig.pub.send(kChanNav, nav);
  rig.cycle(t);
  const InputCounts& c = rig.node.counts();
  EXPECT_EQ(c.dropped, 7);     // angles 2..8 made room for 9, 10, 11 and the nav message
  EXPECT_EQ(c.superseded, 2);  // angles 9 and 10 (11 is used)
  EXPECT_EQ(c.seq_gaps, 0);
  expect_accounted(rig.node, rig.pub.published());
}

// NODE-IN-2: NaN or Inf in a field the flags mark unused rejects the whole message (its
// angles used to drive thrust); the commands equal those of a node that never saw it.
TEST(NodeFaults, NaNInUnusedFieldsRejectsTheWholeMessage) {
  run_against_reference(
      120,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 4 != 1) return 0;
        evade_angles_t a{};
        r.enc.angles_at(t, &a);
        a.elevation_rad += 0.05;  // wrong data: must not be used
        a.seq = k + 2;            // newer than this cycle's good message
        a.has_rates = false;
        a.has_range = false;
        if ((k / 4) % 2 == 0) a.elevation_rate_radps = kNaN; else a.range_m = kInf;
        r.pub.send(kChanAngles, a);
        return 1;
      },
      Verdict::kRejected, 30);
}

// NODE-IN-2: a complete angles message followed by one more byte is not a message of the
// type (the decoder stops early): rejected as decode_failed, never used.
TEST(NodeFaults, MessageWithTrailingBytesIsRejected) {
  run_against_reference(
      60,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 3 != 1) return 0;
        evade_angles_t a{};
        r.enc.angles_at(t, &a);
        a.elevation_rad += 0.05;  // wrong data: must not be used
        a.seq = k + 2;            // newer than this cycle's good message
        std::uint8_t buf[512] = {};
        const int n = a.encode(buf, 0, sizeof(buf));
        r.pub.send_bytes(kChanAngles, buf, static_cast<unsigned>(n + 1));
        return 1;
      },
      Verdict::kRejected, 20);
  Rig rig;
  evade_angles_t a{};
  rig.enc.angles_at(1000000, &a);
  a.seq = 1;
  std::uint8_t buf[512] = {};
  const int n = a.encode(buf, 0, sizeof(buf));
  rig.pub.send_bytes(kChanAngles, buf, static_cast<unsigned>(n + 1));
  rig.cycle(1000000);
  EXPECT_EQ(rig.node.counts().by_reason[static_cast<int>(Reason::kDecodeFailed)], 1);
}

// NODE-IN-3 on the arm channel: arm/disarm commands take effect in arrival order, each one
// counted consumed (a command is never superseded: docs/SECURITY.md AUTH-5), so of two in one
// cycle the later decides, whichever way they point.
TEST(NodeFaults, ArmCommandsOfACycleTakeEffectInOrderTheLaterDecides) {
  Rig rig;
  std::int64_t t = 1000000;
  std::int64_t seq = 1;
  for (int k = 0; k < 30; ++k, t += kPeriodUs) rig.good_cycle(t, seq++);
  ASSERT_GT(rig.node.last_command().accel_mps2, 0.0);
  evade_arm_t arm{};
  arm.utime = t;
  arm.seq = 1;
  arm.armed = true;
  rig.pub.send(kChanArm, arm);
  arm.seq = 2;
  arm.armed = false;
  rig.pub.send(kChanArm, arm);
  std::int64_t consumed = rig.node.counts().consumed;
  EXPECT_EQ(rig.good_cycle(t, seq++).accel_mps2, 0.0);
  EXPECT_FALSE(rig.node.armed());
  EXPECT_EQ(rig.node.counts().consumed - consumed, 4);  // two arms, nav and angles
  EXPECT_EQ(rig.node.counts().superseded, 0);
  t += kPeriodUs;
  arm.utime = t;
  arm.seq = 3;
  arm.armed = false;
  rig.pub.send(kChanArm, arm);
  arm.seq = 4;
  arm.armed = true;
  rig.pub.send(kChanArm, arm);
  consumed = rig.node.counts().consumed;
  rig.good_cycle(t, seq++);
  EXPECT_TRUE(rig.node.armed());
  EXPECT_EQ(rig.node.counts().consumed - consumed, 4);
  EXPECT_EQ(rig.node.counts().superseded, 0);
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

}  // namespace
}  // namespace evade::guidance_lcm::test
