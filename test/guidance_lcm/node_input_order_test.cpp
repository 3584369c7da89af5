// Messages out of time or order are refused and counted, never used (docs/GUIDANCE_NODE.md NODE-IN-1,
// NODE-IN-3, NODE-IN-4): stale and future utimes, duplicated, out-of-order and gapped seqs, a spoofed
// seq jump, a genuine sender restart, bursts past the queue, arm commands in arrival order.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fault_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

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

}  // namespace
}  // namespace evade::guidance_lcm::test
