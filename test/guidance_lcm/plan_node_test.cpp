// The guidance node and uplinked burn plans over memq:// (docs/GUIDANCE_NODE.md PLAN-IN-1,
// PLAN-VAL-1, PLAN-EXE-1, PLAN-END-1, PLAN-OUT-1): a plan on EVADE_BURN_PLAN is accounted like
// every input, flown when the law does not thrust, reported in the status; each rejection
// reason is counted in the status; a disarm cancels it; close-range evasion pre-empts it.
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "evade/evade_arm_t.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "node_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

using S = evade_guidance_status_t;
constexpr std::int64_t kT0 = 1'000'000'000;  // first cycle [us]

// One impulse of 0.1 m/s along track at t = 1 s after kT0: 5 cycles at 1 m/s^2.
evade_burn_plan_t plan_msg(std::int64_t seq, double t_s = 1.0, Vec3 dv = Vec3(0.0, 0.1, 0.0)) {
  BurnPlan p;
  p.plan_id = seq;
  p.n_impulses = 1;
  p.impulses[0].t_s = t_s;
  p.impulses[0].dv_rsw_mps = dv;
  evade_burn_plan_t m{};
  to_lcm(p, kT0, seq, kT0, guidance::PlanFrame::kRsw, &m);
  return m;
}

// Nav only (no angles: the law stays STANDBY) at cycle k.
const evade_thrust_cmd_t& nav_cycle(Rig& rig, int k) {
  const std::int64_t t = kT0 + k * kPeriodUs;
  evade_nav_state_t nav{};
  rig.enc.nav_at(t, &nav);
  nav.seq = k + 1;
  rig.pub.send(kChanNav, nav);
  return rig.cycle(t);
}

void expect_accounted(const Rig& rig) {
  EXPECT_EQ(rig.node.counts().received, rig.node.counts().accounted());
}

TEST(NodePlan, AcceptedPlanIsFlownWhenTheLawIsIdleAndReportedInTheStatus) {
  Rig rig;
  rig.pub.send(kChanPlan, plan_msg(1));
  int thrust_cycles = 0;
  Vec3 dv_eci = Vec3::Zero();
  Vec3 want_eci = Vec3::Zero();  // 0.02 m/s per cycle along that cycle's S axis
  for (int k = 0; k < 100; ++k) {
    const evade_thrust_cmd_t& c = nav_cycle(rig, k);
    EXPECT_NE(c.mode, 2) << "law not evading";
    if (c.accel_mps2 > 0.0) {
      ++thrust_cycles;
      dv_eci += c.accel_mps2 * 0.02 * Vec3(c.u_eci[0], c.u_eci[1], c.u_eci[2]);
      evade_nav_state_t nav{};
      rig.enc.nav_at(kT0 + k * kPeriodUs, &nav);
      const Vec3 r(nav.r_eci_m[0], nav.r_eci_m[1], nav.r_eci_m[2]);
      const Vec3 v(nav.v_eci_mps[0], nav.v_eci_mps[1], nav.v_eci_mps[2]);
      want_eci += 0.02 * r.cross(v).normalized().cross(r.normalized());
      EXPECT_GE(k, 47);  // burn [0.95, 1.05] s: first cycle 0.94 s
      EXPECT_LE(k, 51);
    }
  }
  EXPECT_EQ(thrust_cycles, 5);
  EXPECT_LT((dv_eci - want_eci).norm(), 1e-14);  // rounding of 5 sums of 0.02 m/s
  const S& s = rig.node.last_status();
  EXPECT_EQ(s.plan_id, 1);
  EXPECT_EQ(s.plan_state, S::PLAN_STATE_ENDED);
  EXPECT_EQ(s.plan_end, S::PLAN_END_COMPLETED);
  EXPECT_EQ(s.plan_n_impulses, 1);
  EXPECT_EQ(s.plan_impulses_done, 1);
  EXPECT_NEAR(s.plan_dv_delivered_mps[0], 0.1, 1e-12);
  EXPECT_EQ(s.plan_burn_start_utime[0], kT0 + 47 * kPeriodUs);
  EXPECT_EQ(s.plan_burn_end_utime[0], kT0 + 52 * kPeriodUs);
  EXPECT_EQ(s.plan_n_accepted, 1);
  expect_accounted(rig);
}

struct RejectCase {
  std::int8_t code;
  evade_burn_plan_t msg;
};

// PLAN-IN-1: bytes on EVADE_BURN_PLAN that are too large, not a plan, or a plan with
// trailing bytes are rejected with their reason, counted, and never start a burn. The
// decoder's own checks, with the plan channel's authentication off (node.auth.plan_required =
// false); with it on the same bytes never reach the decoder
// (node_refuses_forged_commands_test.cpp).
TEST(NodePlan, OversizedAndUndecodablePlanBytesAreRejectedAndAccounted) {
  NodeConfig cfg;
  cfg.auth.plan_required = false;
  Rig rig(cfg);
  const std::vector<std::uint8_t> big(kMaxCommandBytes + 1, 0x5a);
  rig.pub.send_bytes(kChanPlan, big.data(), static_cast<unsigned>(big.size()));
  const std::uint8_t junk[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  rig.pub.send_bytes(kChanPlan, junk, sizeof(junk));
  std::uint8_t buf[kMaxCommandBytes] = {};
  const evade_burn_plan_t good = plan_msg(1);
  const int n = good.encode(buf, 0, static_cast<int>(sizeof(buf)));
  ASSERT_GT(n, 0);
  ASSERT_LT(n, static_cast<int>(sizeof(buf)));
  rig.pub.send_bytes(kChanPlan, buf, static_cast<unsigned>(n + 1));  // one trailing byte
  for (int k = 0; k < 100; ++k) EXPECT_EQ(nav_cycle(rig, k).accel_mps2, 0.0);
  const InputCounts& c = rig.node.counts();
  EXPECT_EQ(c.by_reason[static_cast<int>(Reason::kOversize)], 1);
  EXPECT_EQ(c.by_reason[static_cast<int>(Reason::kDecodeFailed)], 2);
  EXPECT_EQ(c.rejected, 3);
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, 0);
  expect_accounted(rig);
}

// Lockstep (NODE-RT-2): a tick is one cycle; a tick with a negative time or a replayed tick
// number is not a tick; a tick that arrives before the previous one got its cycle is
// counted as missed.
TEST(NodeLockstep, TicksAreValidatedReplaysIgnoredAndMissedTicksCounted) {
  NodeConfig cfg;
  cfg.lockstep = true;
  Rig rig(cfg);
  std::int64_t utime = 0;
  evade_sim_clock_t tick{};
  tick.utime = -5;
  tick.seq = 1;
  rig.pub.send(kChanClock, tick);
  EXPECT_EQ(rig.node.wait_for_tick(20, &utime), 0);  // invalid: no tick, times out
  EXPECT_EQ(rig.node.ticks_received(), 0);
  tick.utime = kT0;
  rig.pub.send(kChanClock, tick);
  ASSERT_EQ(rig.node.wait_for_tick(1000, &utime), 1);
  EXPECT_EQ(utime, kT0);
  rig.pub.send(kChanClock, tick);  // the same tick replayed
  EXPECT_EQ(rig.node.wait_for_tick(20, &utime), 0);
  EXPECT_EQ(rig.node.ticks_received(), 1);
  for (std::int64_t k = 2; k <= 3; ++k) {  // two ticks before one cycle
    tick.seq = k;
    tick.utime = kT0 + k * kPeriodUs;
    rig.pub.send(kChanClock, tick);
  }
  rig.node.drain();  // both ticks handled before the loop asks for one
  ASSERT_EQ(rig.node.wait_for_tick(1000, &utime), 1);
  EXPECT_EQ(utime, kT0 + 3 * kPeriodUs);
  EXPECT_EQ(rig.node.ticks_received(), 3);
  EXPECT_EQ(rig.node.ticks_missed(), 1);
}

// PLAN-IN-1: a plan stamped later than now + the future tolerance is rejected as from the
// future before any field check, counted, and never flown.
TEST(NodePlan, PlanStampedInTheFutureIsRejectedAndNeverFlown) {
  Rig rig;
  evade_burn_plan_t m = plan_msg(1);
  m.utime = kT0 + 50001;  // tolerance 0.05 s after the first cycle at kT0
  rig.pub.send(kChanPlan, m);
  for (int k = 0; k < 100; ++k) EXPECT_EQ(nav_cycle(rig, k).accel_mps2, 0.0);
  const InputCounts& c = rig.node.counts();
  EXPECT_EQ(c.by_reason[static_cast<int>(Reason::kFromFuture)], 1);
  EXPECT_EQ(c.rejected, 1);
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, 0);
  m.utime = kT0 + 50000;  // at the tolerance: accepted and flown (the cycle is at kT0)
  Rig edge;
  edge.pub.send(kChanPlan, m);
  int thrust = 0;
  for (int k = 0; k < 100; ++k) thrust += nav_cycle(edge, k).accel_mps2 > 0.0 ? 1 : 0;
  EXPECT_EQ(thrust, 5);
  expect_accounted(rig);
  expect_accounted(edge);
}

// PLAN-IN-1: more plans in one cycle than the inbox holds (kCommandSlots): the oldest is
// dropped and counted, the others are admitted in order and the newest is the one flown.
TEST(NodePlan, PlansBeyondTheInboxInOneCycleDropTheOldest) {
  Rig rig;
  for (std::int64_t id = 1; id <= static_cast<std::int64_t>(kCommandSlots) + 1; ++id)
    rig.pub.send(kChanPlan, plan_msg(id));
  nav_cycle(rig, 0);
  const InputCounts& c = rig.node.counts();
  EXPECT_EQ(c.dropped, 1);
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, static_cast<std::int64_t>(kCommandSlots));
  EXPECT_EQ(rig.node.last_status().plan_id, static_cast<std::int64_t>(kCommandSlots) + 1);
  expect_accounted(rig);
}

TEST(NodePlan, EachRejectionReasonIsCountedInTheStatus) {
  const double nan = std::nan("");
  std::vector<RejectCase> cases;
  auto add = [&](std::int8_t code, evade_burn_plan_t m) { cases.push_back({code, m}); };
  evade_burn_plan_t m = plan_msg(10);
  m.source = 9;
  add(S::PLAN_REJECT_MALFORMED, m);
  m = plan_msg(11);
  m.n_impulses = 0;
  add(S::PLAN_REJECT_IMPULSE_COUNT, m);
  m = plan_msg(12);
  m.impulse_dv_rsw_mps[0][1] = nan;
  add(S::PLAN_REJECT_NOT_FINITE, m);
  m = plan_msg(13);
  m.frame = 5;
  add(S::PLAN_REJECT_UNKNOWN_FRAME, m);
  add(S::PLAN_REJECT_BURN_IN_PAST, plan_msg(14, -1.0));
  m = plan_msg(15);
  m.n_impulses = 2;
  m.impulse_t_s[1] = 0.5;
  m.impulse_dv_rsw_mps[1][0] = 0.01;
  add(S::PLAN_REJECT_NOT_ORDERED, m);
  m.impulse_t_s[1] = 1.07;  // first burn ends at 1.05 s: closer than one cycle
  m.seq = 16;
  add(S::PLAN_REJECT_OVERLAPPING, m);
  add(S::PLAN_REJECT_OVER_BUDGET, plan_msg(17, 100.0, Vec3(0.0, 150.0, 0.0)));  // budget 100
  add(S::PLAN_REJECT_OVER_THRUST_LIMIT, plan_msg(18, 1000.0, Vec3(0.0, 700.0, 0.0)));
  Rig rig;
  nav_cycle(rig, 0);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    rig.pub.send(kChanPlan, cases[i].msg);
    nav_cycle(rig, static_cast<int>(i) + 1);
    const S& s = rig.node.last_status();
    EXPECT_EQ(s.plan_last_reject, cases[i].code) << i;
    EXPECT_EQ(s.plan_n_rejected[cases[i].code], 1) << i;
  }
  // Not newer: accept 30, then another plan 30 and a 29; the very plan 30 sent again (a
  // retransmission, signed afresh) is the plan in force, not a rejection.
  rig.pub.send(kChanPlan, plan_msg(30, 5.0));
  rig.pub.send(kChanPlan, plan_msg(30, 5.5));
  rig.pub.send(kChanPlan, plan_msg(29, 5.0));
  rig.pub.send(kChanPlan, plan_msg(30, 5.0));
  nav_cycle(rig, 20);
  EXPECT_EQ(rig.node.last_status().plan_n_rejected[S::PLAN_REJECT_NOT_NEWER], 2);
  EXPECT_EQ(rig.node.last_status().plan_id, 30);
  EXPECT_EQ(rig.node.last_ack().outcome, evade_cmd_ack_t::OUTCOME_ALREADY_IN_FORCE);
  EXPECT_EQ(rig.node.counts().by_reason[static_cast<int>(Reason::kDuplicateSeq)], 1);
  // Disarmed: the arm message cancels plan 30, then plan 31 is refused.
  evade_arm_t arm{};
  arm.utime = kT0 + 21 * kPeriodUs;
  arm.seq = 1;
  arm.armed = false;
  rig.pub.send(kChanArm, arm);
  nav_cycle(rig, 21);
  EXPECT_EQ(rig.node.last_status().plan_end, S::PLAN_END_CANCELLED_DISARM);
  rig.pub.send(kChanPlan, plan_msg(31, 5.0));
  nav_cycle(rig, 22);
  EXPECT_EQ(rig.node.last_status().plan_n_rejected[S::PLAN_REJECT_DISARMED], 1);
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, 1);
  // Bytes that are not a plan: refused by the authentication (too short for a trailer).
  const std::uint8_t junk[40] = {1, 2, 3};
  rig.pub.send_bytes(kChanPlan, junk, sizeof junk);
  const auto short_before = rig.node.counts().by_reason[static_cast<int>(Reason::kTooShortForTrailer)];
  nav_cycle(rig, 23);
  EXPECT_EQ(rig.node.counts().by_reason[static_cast<int>(Reason::kTooShortForTrailer)],
            short_before + 1);
  expect_accounted(rig);
}

TEST(NodePlan, CloseRangeEvasionPreemptsAWaitingPlanWhichIsAbandoned) {
  Rig rig;
  rig.pub.send(kChanPlan, plan_msg(1, 2.0));
  for (int k = 0; k < 60; ++k) {
    const evade_thrust_cmd_t& c = rig.good_cycle(kT0 + k * kPeriodUs, k + 1);
    if (c.mode == 2) {
      EXPECT_EQ(rig.node.last_status().plan_end, S::PLAN_END_PREEMPTED_EVASION);
    }
  }
  const S& s = rig.node.last_status();
  EXPECT_EQ(s.mode, 2);  // the law evades (paper 000)
  EXPECT_EQ(s.plan_id, 1);
  EXPECT_EQ(s.plan_state, S::PLAN_STATE_ENDED);
  EXPECT_EQ(s.plan_end, S::PLAN_END_PREEMPTED_EVASION);
  EXPECT_EQ(s.plan_impulses_done, 0);
  EXPECT_EQ(s.plan_dv_delivered_mps[0], 0.0);
  expect_accounted(rig);
}

}  // namespace
}  // namespace evade::guidance_lcm::test
