// The onboard conjunction response's edges through the node (docs/AUTONOMY.md AUT-1, AUT-7,
// AUT-8): every problem of an uplinked event named in its acknowledgement; a retransmitted event
// or decision answered ALREADY_IN_FORCE, an altered one refused; the ninth live event
// refused as table_full; an unknown decision refused out_of_range; the loaded burn withdrawn
// (PLAN_END_CANCELLED_ONBOARD) when the autonomy goes off or a newer version arrives; a ground
// plan that replaces the onboard burn, or is active at the deadline, leaves the event to the
// ground; a disarmed node's executor refuses the burn; no navigation means no_nav. In each, no
// thrust the ground did not expect, and the accounting identity holds.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "conjunction_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

using autonomy::Policy;
using Ack = evade_cmd_ack_t;
using Prop = evade_cam_proposal_t;
using Dec = evade_cam_decision_t;

// One event per cycle (one command per cycle); returns the acknowledgement of each, in order.
std::vector<evade_cmd_ack_t> uplink_each(Flight& f, const std::vector<autonomy::ConjunctionEvent>& es) {
  std::int64_t t = kT0;
  std::int64_t seq = 0;
  for (const autonomy::ConjunctionEvent& e : es) {
    f.rig.pub.send(kChanConjunction, conjunction_msg(e, ++seq));
    f.steps(t, t + 2 * kPeriodUs);
    t += 2 * kPeriodUs;
  }
  return f.acks.acks();
}

TEST(NodeConjunctionEdges, EveryProblemOfAnEventIsNamedInItsAcknowledgement) {
  Flight f;
  std::vector<autonomy::ConjunctionEvent> es(5, node_event());
  es[0].event_id = 0;
  es[1].cov1_eci(0, 1) += 1.0;  // m^2: far above 1e-9 of the largest term (~1e4 m^2)
  es[2].burn_start_us = es[2].burn_end_us;
  es[3].tca_us += 8LL * 86'400'000'000;  // more than 7 days ahead (the window still before TCA)
  es[4].hbr_m = -1.0;
  const std::vector<evade_cmd_ack_t> acks = uplink_each(f, es);
  ASSERT_EQ(acks.size(), es.size());
  const std::int16_t want[][2] = {{Ack::REASON_OUT_OF_RANGE, Ack::CONJ_BAD_ID},
                                  {Ack::REASON_OUT_OF_RANGE, Ack::CONJ_ASYMMETRIC},
                                  {Ack::REASON_OUT_OF_RANGE, Ack::CONJ_BAD_WINDOW},
                                  {Ack::REASON_OUT_OF_RANGE, Ack::CONJ_TCA_NOT_AHEAD},
                                  {Ack::REASON_OUT_OF_RANGE, Ack::CONJ_OUT_OF_RANGE}};
  for (std::size_t i = 0; i < acks.size(); ++i) {
    EXPECT_EQ(acks[i].outcome, Ack::OUTCOME_REFUSED) << i;
    EXPECT_EQ(acks[i].reason, want[i][0]) << i;
    EXPECT_EQ(acks[i].detail, want[i][1]) << i;
  }
  EXPECT_EQ(f.rig.node.responder().counters().events_tracked, 0);
  EXPECT_EQ(reason(f.rig, Reason::kOutOfRange), 5);
  expect_accounted(f.rig);
}

// The ground sends a command again, signed afresh, until it hears the node's answer
// (docs/SECURITY.md UPLINK-*): the copy of a tracked event is answered ALREADY_IN_FORCE and
// changes nothing; the same version with any field changed is not a copy and is refused
// not_newer (an event changes only with a new version).
TEST(NodeConjunctionEdges, ARetransmittedEventIsAlreadyInForceAndAnAlteredOneIsRefused) {
  Flight f;
  autonomy::ConjunctionEvent altered = node_event();
  altered.hbr_m *= 2.0;
  const std::vector<evade_cmd_ack_t> acks = uplink_each(f, {node_event(), node_event(), altered});
  ASSERT_EQ(acks.size(), 3U);
  EXPECT_EQ(acks[0].outcome, Ack::OUTCOME_ACCEPTED);
  EXPECT_EQ(acks[1].outcome, Ack::OUTCOME_ALREADY_IN_FORCE);
  EXPECT_EQ(acks[1].reason, Ack::REASON_OK);
  EXPECT_EQ(acks[1].detail, Ack::CONJ_ALREADY_TRACKED);
  EXPECT_EQ(acks[2].outcome, Ack::OUTCOME_REFUSED);
  EXPECT_EQ(acks[2].detail, Ack::CONJ_NOT_NEWER);
  EXPECT_EQ(f.rig.node.responder().counters().events_tracked, 1);
  EXPECT_EQ(f.rig.node.responder().counters().events_replaced, 0);
  EXPECT_EQ(f.rig.node.responder().counters().events_again, 1);
  EXPECT_EQ(f.rig.node.responder().record(0).superseded_version, 0);
  expect_accounted(f.rig);
}

// A veto sent again, before the deadline or after it (its first copy applied in time, the
// answer lost): ALREADY_IN_FORCE, never refused past_deadline; an approval likewise.
TEST(NodeConjunctionEdges, ARetransmittedDecisionIsAlreadyInForceEvenAfterTheDeadline) {
  for (const std::int8_t kind : {Dec::DECISION_VETO, Dec::DECISION_APPROVE}) {
    Flight f(kind == Dec::DECISION_VETO ? Policy::kVeto : Policy::kApprove);
    const Prop* p = f.propose();
    ASSERT_NE(p, nullptr);
    const Prop proposed = *p;
    for (int copy = 0; copy < 2; ++copy) {
      f.decide(decision_msg(kind, 7, proposed.proposal_id));
      f.steps(kT0 + (3 + 2 * copy) * kPeriodUs, kT0 + (5 + 2 * copy) * kPeriodUs);
    }
    const std::int64_t t = proposed.veto_deadline_utime + 2 * kPeriodUs;
    f.steps(proposed.veto_deadline_utime - kPeriodUs, t);
    f.decide(decision_msg(kind, 7, proposed.proposal_id));
    f.steps(t, t + 2 * kPeriodUs);
    const std::vector<evade_cmd_ack_t>& acks = f.acks.acks();
    ASSERT_EQ(acks.size(), 4U);
    EXPECT_EQ(acks[1].outcome, Ack::OUTCOME_ACCEPTED);
    for (std::size_t i = 2; i < 4; ++i) {
      EXPECT_EQ(acks[i].outcome, Ack::OUTCOME_ALREADY_IN_FORCE) << i;
      EXPECT_EQ(acks[i].detail, Ack::DECIDE_ALREADY_APPLIED) << i;
    }
    EXPECT_EQ(f.rig.node.responder().counters().decisions_applied, 1);
    EXPECT_EQ(f.state(7), kind == Dec::DECISION_VETO ? Prop::STATE_VETOED : Prop::STATE_SCHEDULED);
    expect_accounted(f.rig);
  }
}

TEST(NodeConjunctionEdges, TheNinthLiveEventIsRefusedAsTableFull) {
  Flight f;
  std::vector<autonomy::ConjunctionEvent> es;
  for (std::int64_t id = 1; id <= static_cast<std::int64_t>(autonomy::kMaxEvents) + 1; ++id)
    es.push_back(node_event(id));
  const std::vector<evade_cmd_ack_t> acks = uplink_each(f, es);
  ASSERT_EQ(acks.size(), es.size());
  for (std::size_t i = 0; i + 1 < acks.size(); ++i) EXPECT_EQ(acks[i].detail, Ack::CONJ_TRACKED) << i;
  EXPECT_EQ(acks.back().outcome, Ack::OUTCOME_REFUSED);
  EXPECT_EQ(acks.back().reason, Ack::REASON_TABLE_FULL);
  EXPECT_EQ(acks.back().detail, Ack::CONJ_TABLE_FULL);
  EXPECT_EQ(reason(f.rig, Reason::kTableFull), 1);
  expect_accounted(f.rig);
}

TEST(NodeConjunctionEdges, UnknownDecisionOrAutonomyValueIsRefusedOutOfRange) {
  Flight f;
  const Prop* p = f.propose();
  ASSERT_NE(p, nullptr);
  f.decide(decision_msg(9, 7, p->proposal_id));
  f.steps(kT0 + 3 * kPeriodUs, kT0 + 5 * kPeriodUs);
  f.decide(decision_msg(Dec::DECISION_SET_AUTONOMY, 0, 0, 7));
  f.steps(kT0 + 5 * kPeriodUs, kT0 + 7 * kPeriodUs);
  const std::vector<evade_cmd_ack_t>& acks = f.acks.acks();
  ASSERT_EQ(acks.size(), 3U);
  for (std::size_t i = 1; i < 3; ++i) {
    EXPECT_EQ(acks[i].outcome, Ack::OUTCOME_REFUSED) << i;
    EXPECT_EQ(acks[i].reason, Ack::REASON_OUT_OF_RANGE) << i;
    EXPECT_EQ(acks[i].detail, Ack::DECIDE_BAD_DECISION) << i;
  }
  EXPECT_EQ(f.rig.node.responder().policy(), Policy::kVeto);
  EXPECT_EQ(f.state(7), Prop::STATE_PROPOSED);
  expect_accounted(f.rig);
}

// Proposed and left to its deadline: the burn is loaded (STATE_SCHEDULED); returns the proposal.
Prop scheduled(Flight& f) {
  const Prop* p = f.propose();
  EXPECT_NE(p, nullptr);
  if (p == nullptr) return Prop{};
  const Prop proposed = *p;
  f.steps(proposed.veto_deadline_utime - kPeriodUs, proposed.veto_deadline_utime + 2 * kPeriodUs);
  EXPECT_EQ(f.state(7), Prop::STATE_SCHEDULED);
  return proposed;
}

void expect_withdrawn(Flight& f, const Prop& proposed) {
  const guidance::PlanExecStatus& st = f.rig.node.plan_executor().status();
  EXPECT_EQ(st.state, guidance::PlanState::kEnded);
  EXPECT_EQ(st.end, guidance::PlanEnd::kCancelledOnboard);
  EXPECT_EQ(f.steps(proposed.burn_utime - 2'000'000, proposed.burn_utime + 2'000'000), 0);
  EXPECT_EQ(st.dv_total_mps, 0.0);
  expect_accounted(f.rig);
}

TEST(NodeConjunctionEdges, AutonomyOffWithdrawsTheLoadedBurn) {
  Flight f;
  const Prop proposed = scheduled(f);
  const std::int64_t t = proposed.veto_deadline_utime + 2 * kPeriodUs;
  f.decide(decision_msg(Dec::DECISION_SET_AUTONOMY, 0, 0, Dec::AUTONOMY_OFF));
  f.steps(t, t + 3 * kPeriodUs);
  EXPECT_EQ(f.state(7), Prop::STATE_REPORT_ONLY);
  EXPECT_EQ(f.rig.node.responder().counters().cancels, 1);
  expect_withdrawn(f, proposed);
}

TEST(NodeConjunctionEdges, ANewerVersionWithdrawsTheOldVersionsLoadedBurn) {
  Flight f;
  const Prop proposed = scheduled(f);
  const std::int64_t t = proposed.veto_deadline_utime + 2 * kPeriodUs;
  f.rig.pub.send(kChanConjunction, conjunction_msg(node_event(7, 2), 2, t));
  f.steps(t, t + 3 * kPeriodUs);
  EXPECT_EQ(f.acks.acks().back().detail, Ack::CONJ_REPLACED);
  EXPECT_EQ(f.proposals.last(7, 1)->state, Prop::STATE_SUPERSEDED);
  expect_withdrawn(f, proposed);
}

// A ground plan stamped at t: one impulse 10 s later (RSW, 0.1 m/s along track).
evade_burn_plan_t ground_plan(std::int64_t plan_id, std::int64_t t) {
  BurnPlan p;
  p.plan_id = plan_id;
  p.n_impulses = 1;
  p.impulses[0].t_s = 10.0;
  p.impulses[0].dv_rsw_mps = Vec3(0.0, 0.1, 0.0);
  evade_burn_plan_t m{};
  to_lcm(p, t, plan_id, t, guidance::PlanFrame::kRsw, &m);
  return m;
}

TEST(NodeConjunctionEdges, AGroundPlanReplacingTheOnboardBurnLeavesTheEventToTheGround) {
  Flight f;
  const Prop proposed = scheduled(f);
  const std::int64_t t = proposed.veto_deadline_utime + 2 * kPeriodUs;
  f.rig.pub.send(kChanPlan, ground_plan(50, t));
  f.steps(t, t + 3 * kPeriodUs);
  EXPECT_EQ(f.rig.node.plan_executor().status().plan_id, 50);
  EXPECT_EQ(f.state(7), Prop::STATE_NEEDS_GROUND);
  EXPECT_EQ(f.proposals.last(7)->reason, Prop::REASON_BURN_ABANDONED);
  EXPECT_EQ(f.steps(proposed.burn_utime - 2'000'000, proposed.burn_utime + 2'000'000), 0);
  expect_accounted(f.rig);
}

TEST(NodeConjunctionEdges, AGroundPlanActiveAtTheDeadlineLeavesTheEventToTheGround) {
  Flight f;
  const Prop* p = f.propose();
  ASSERT_NE(p, nullptr);
  const Prop proposed = *p;
  const std::int64_t t = proposed.veto_deadline_utime - 4 * kPeriodUs;
  f.rig.pub.send(kChanPlan, ground_plan(50, t));
  f.steps(t, proposed.veto_deadline_utime + 2 * kPeriodUs);
  EXPECT_EQ(f.rig.node.plan_executor().status().plan_id, 50);
  EXPECT_EQ(f.state(7), Prop::STATE_NEEDS_GROUND);
  EXPECT_EQ(f.proposals.last(7)->reason, Prop::REASON_EXECUTOR_BUSY);
  expect_accounted(f.rig);
}

TEST(NodeConjunctionEdges, ADisarmedNodesExecutorRefusesTheBurn) {
  NodeConfig c = config();
  c.guidance.armed = false;
  Flight f(c);
  const Prop* p = f.propose();
  ASSERT_NE(p, nullptr);
  const Prop proposed = *p;
  f.steps(proposed.veto_deadline_utime - kPeriodUs, proposed.veto_deadline_utime + 2 * kPeriodUs);
  EXPECT_EQ(f.state(7), Prop::STATE_NEEDS_GROUND);
  EXPECT_EQ(f.proposals.last(7)->reason, Prop::REASON_PLAN_REJECTED);
  EXPECT_EQ(f.rig.node.plan_executor().status().accepted, 0);
  EXPECT_EQ(f.steps(proposed.burn_utime - 2'000'000, proposed.burn_utime + 2'000'000), 0);
  expect_accounted(f.rig);
}

TEST(NodeConjunctionEdges, WithoutNavigationTheEventNeedsTheGround) {
  Flight f;
  f.rig.pub.send(kChanConjunction, conjunction_msg(node_event(), 1));
  f.rig.cycle(kT0);  // no nav message: the node has no navigation
  ASSERT_TRUE(f.rig.node.plan_once());
  for (int k = 1; k <= 3; ++k) f.rig.cycle(kT0 + k * kPeriodUs);
  EXPECT_EQ(f.state(7), Prop::STATE_NEEDS_GROUND);
  EXPECT_EQ(f.proposals.last(7)->reason, Prop::REASON_NO_NAV);
  expect_accounted(f.rig);
}

}  // namespace
}  // namespace evade::guidance_lcm::test
