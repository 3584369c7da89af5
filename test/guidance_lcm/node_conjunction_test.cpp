// The onboard conjunction response through the node (docs/AUTONOMY.md AUT-1, AUT-7, AUT-8;
// docs/SECURITY.md AUTH-2): a signed evade_conjunction_t is tracked, assessed by the planning
// worker beside the cycle and proposed in a signed evade_cam_proposal_t; the ground's signed
// evade_cam_decision_t vetoes, approves or switches the autonomy off; the burn is flown by the
// plan executor at the proposed time. Every forged, replayed, unsigned or misdirected
// conjunction and decision is refused before anything in it is used, counted under its reason,
// and changes nothing (no event, no thrust); the accounting identity holds throughout.
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "conjunction_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

using autonomy::Policy;
using autonomy::ResponseState;
using Ack = evade_cmd_ack_t;
using Prop = evade_cam_proposal_t;
using Dec = evade_cam_decision_t;

TEST(NodeConjunction, SignedConjunctionIsTrackedAssessedBesideTheCycleAndProposed) {
  Flight f;
  const autonomy::ConjunctionEvent e = node_event();
  const Prop* p = f.propose(e);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(f.proposals.unverified(), 0);
  EXPECT_EQ(p->state, Prop::STATE_PROPOSED);
  EXPECT_GT(p->proposal_id, 0);
  EXPECT_EQ(p->pc_method, Prop::METHOD_2D);
  EXPECT_GT(p->pc, e.pc_red);        // the example's Pc is about 1e-3
  EXPECT_LT(p->post_pc, e.pc_target);
  // Nav on the event's own orbit: only the two RK4 integrations differ (10 s steps back from
  // TCA here, the node's step forward), well under 2 m over 10 h against sigmas of 20 m or more.
  EXPECT_LT(p->nav_mismatch_sigma, 0.1);
  EXPECT_GE(p->burn_utime, e.veto_deadline_us + 60'000'000);  // node.autonomy.decision_lead_s
  EXPECT_LE(p->burn_utime, e.burn_end_us);
  EXPECT_GT(std::hypot(p->dv_eci_mps[0], p->dv_eci_mps[1], p->dv_eci_mps[2]), 0.0);
  EXPECT_EQ(p->autonomy, Dec::AUTONOMY_VETO);
  ASSERT_EQ(f.acks.acks().size(), 1U);
  const evade_cmd_ack_t& a = f.acks.acks()[0];
  EXPECT_EQ(a.command, Ack::COMMAND_CONJUNCTION);
  EXPECT_EQ(a.outcome, Ack::OUTCOME_ACCEPTED);
  EXPECT_EQ(a.detail, Ack::CONJ_TRACKED);
  EXPECT_EQ(f.rig.node.last_status().auth_required & evade_guidance_status_t::AUTH_CONJUNCTION,
            evade_guidance_status_t::AUTH_CONJUNCTION);
  EXPECT_EQ(f.rig.node.responder().counters().events_tracked, 1);
  EXPECT_EQ(f.rig.node.plan_executor().status().accepted, 0);  // nothing loaded before the deadline
  expect_accounted(f.rig);
}

TEST(NodeConjunction, VetoPolicyFliesTheBurnAtItsTimeWhenTheGroundDoesNotVeto) {
  Flight f;
  const autonomy::ConjunctionEvent e = node_event();
  const Prop* p = f.propose(e);
  ASSERT_NE(p, nullptr);
  const Prop proposed = *p;
  EXPECT_EQ(f.steps(e.veto_deadline_us - 2 * kPeriodUs, e.veto_deadline_us + 2 * kPeriodUs), 0);
  EXPECT_EQ(f.state(7), Prop::STATE_SCHEDULED);
  const guidance::PlanExecStatus& st = f.rig.node.plan_executor().status();
  EXPECT_EQ(st.accepted, 1);
  EXPECT_EQ(f.proposals.last(7)->plan_id, st.plan_id);
  const int thrust = f.steps(proposed.burn_utime - 2'000'000, proposed.burn_utime + 2'000'000);
  EXPECT_GT(thrust, 0);
  const double dv = std::hypot(proposed.dv_eci_mps[0], proposed.dv_eci_mps[1], proposed.dv_eci_mps[2]);
  // The executor delivers N whole cycles at |dv| / (N T): the sum of N products, exact to
  // rounding (1e-9 m/s is a million times the double's error on these magnitudes).
  EXPECT_NEAR(f.rig.node.plan_executor().status().dv_total_mps, dv, 1e-9);
  f.steps(proposed.burn_utime + 2'000'000, proposed.burn_utime + 2'000'000 + 3 * kPeriodUs);
  EXPECT_EQ(f.state(7), Prop::STATE_EXECUTED);
  expect_accounted(f.rig);
}

TEST(NodeConjunction, GroundVetoBeforeTheDeadlineMeansNoBurn) {
  Flight f;
  const Prop* p = f.propose();
  ASSERT_NE(p, nullptr);
  const Prop proposed = *p;
  f.decide(decision_msg(Dec::DECISION_VETO, 7, proposed.proposal_id));
  f.steps(kT0 + 3 * kPeriodUs, kT0 + 6 * kPeriodUs);
  EXPECT_EQ(f.state(7), Prop::STATE_VETOED);
  const evade_cmd_ack_t& a = f.acks.acks().back();
  EXPECT_EQ(a.command, Ack::COMMAND_CAM_DECISION);
  EXPECT_EQ(a.outcome, Ack::OUTCOME_ACCEPTED);
  EXPECT_EQ(a.detail, Ack::DECIDE_APPLIED);
  EXPECT_EQ(f.steps(proposed.veto_deadline_utime - kPeriodUs, proposed.veto_deadline_utime + 2 * kPeriodUs), 0);
  EXPECT_EQ(f.steps(proposed.burn_utime - 2'000'000, proposed.burn_utime + 2'000'000), 0);
  EXPECT_EQ(f.rig.node.plan_executor().status().accepted, 0);
  expect_accounted(f.rig);
}

TEST(NodeConjunction, ApprovePolicyWithoutApprovalExpiresAndNeverBurns) {
  Flight f(Policy::kApprove);
  const Prop* p = f.propose();
  ASSERT_NE(p, nullptr);
  const Prop proposed = *p;
  EXPECT_EQ(f.steps(proposed.veto_deadline_utime - kPeriodUs, proposed.veto_deadline_utime + 2 * kPeriodUs), 0);
  EXPECT_EQ(f.state(7), Prop::STATE_EXPIRED);
  EXPECT_EQ(f.proposals.last(7)->reason, Prop::REASON_NOT_APPROVED);
  EXPECT_EQ(f.steps(proposed.burn_utime - 2'000'000, proposed.burn_utime + 2'000'000), 0);
  expect_accounted(f.rig);
}

TEST(NodeConjunction, ApprovePolicyFliesWhatTheGroundApproved) {
  Flight f(Policy::kApprove);
  const Prop* p = f.propose();
  ASSERT_NE(p, nullptr);
  const Prop proposed = *p;
  f.decide(decision_msg(Dec::DECISION_APPROVE, 7, proposed.proposal_id));
  f.steps(proposed.veto_deadline_utime - kPeriodUs, proposed.veto_deadline_utime + 2 * kPeriodUs);
  EXPECT_EQ(f.state(7), Prop::STATE_SCHEDULED);
  EXPECT_GT(f.steps(proposed.burn_utime - 2'000'000, proposed.burn_utime + 2'000'000), 0);
  expect_accounted(f.rig);
}

TEST(NodeConjunction, AutonomyOffReportsOnlyAndADecisionOnAnotherProposalIsRefused) {
  Flight f;
  const Prop* p = f.propose();
  ASSERT_NE(p, nullptr);
  const Prop proposed = *p;
  f.decide(decision_msg(Dec::DECISION_APPROVE, 7, proposed.proposal_id + 1));  // not its proposal
  f.decide(decision_msg(Dec::DECISION_VETO, 8, proposed.proposal_id));          // not an event
  f.decide(decision_msg(Dec::DECISION_SET_AUTONOMY, 0, 0, Dec::AUTONOMY_OFF));
  f.steps(kT0 + 3 * kPeriodUs, kT0 + 6 * kPeriodUs);
  const std::vector<evade_cmd_ack_t>& acks = f.acks.acks();
  ASSERT_EQ(acks.size(), 4U);
  EXPECT_EQ(acks[1].reason, Ack::REASON_NOT_APPLICABLE);
  EXPECT_EQ(acks[1].detail, Ack::DECIDE_WRONG_PROPOSAL);
  EXPECT_EQ(acks[2].detail, Ack::DECIDE_UNKNOWN_EVENT);
  EXPECT_EQ(acks[3].outcome, Ack::OUTCOME_ACCEPTED);
  EXPECT_EQ(f.state(7), Prop::STATE_REPORT_ONLY);
  EXPECT_EQ(f.proposals.last(7)->autonomy, Dec::AUTONOMY_OFF);
  EXPECT_EQ(f.steps(proposed.veto_deadline_utime - kPeriodUs, proposed.veto_deadline_utime + 2 * kPeriodUs), 0);
  EXPECT_EQ(f.steps(proposed.burn_utime - 2'000'000, proposed.burn_utime + 2'000'000), 0);
  EXPECT_EQ(reason(f.rig, Reason::kNotApplicable), 2);
  expect_accounted(f.rig);
}

// A newer version replaces the older one: its superseded notice goes out before the new
// version, which is assessed afresh (the worker's next job).
TEST(NodeConjunction, NewerVersionSupersedesTheOlderProposal) {
  Flight f;
  const Prop* p = f.propose();
  ASSERT_NE(p, nullptr);
  const std::int64_t old_id = p->proposal_id;
  f.rig.pub.send(kChanConjunction, conjunction_msg(node_event(7, 2), 2));
  f.steps(kT0 + 3 * kPeriodUs, kT0 + 5 * kPeriodUs);
  const Prop* old_v = f.proposals.last(7, 1);
  ASSERT_NE(old_v, nullptr);
  EXPECT_EQ(old_v->state, Prop::STATE_SUPERSEDED);
  EXPECT_EQ(old_v->proposal_id, old_id);
  EXPECT_EQ(f.proposals.last(7, 2)->state, Prop::STATE_ASSESSING);
  EXPECT_EQ(f.acks.acks().back().detail, Ack::CONJ_REPLACED);
  EXPECT_TRUE(f.rig.node.plan_once());
  f.steps(kT0 + 5 * kPeriodUs, kT0 + 8 * kPeriodUs);
  EXPECT_EQ(f.proposals.last(7, 2)->state, Prop::STATE_PROPOSED);
  EXPECT_NE(f.proposals.last(7, 2)->proposal_id, old_id);
  // The older version again is not newer: refused, counted stale, nothing changes.
  f.rig.pub.send(kChanConjunction, conjunction_msg(node_event(7, 1), 3));
  f.steps(kT0 + 8 * kPeriodUs, kT0 + 10 * kPeriodUs);
  EXPECT_EQ(f.acks.acks().back().detail, Ack::CONJ_NOT_NEWER);
  EXPECT_EQ(f.acks.acks().back().reason, Ack::REASON_OUT_OF_ORDER_SEQ);
  expect_accounted(f.rig);
}

TEST(NodeConjunction, BadFieldsAndAFutureStampAreRefusedNamingTheProblem) {
  Flight f;
  autonomy::ConjunctionEvent e = node_event();
  e.cov1_eci(0, 0) = std::numeric_limits<double>::quiet_NaN();
  f.rig.pub.send(kChanConjunction, conjunction_msg(e, 1));
  f.rig.pub.send(kChanConjunction, conjunction_msg(node_event(9), 2, kT0 + 10'000'000));
  f.steps(kT0, kT0 + 3 * kPeriodUs);
  ASSERT_EQ(f.acks.acks().size(), 2U);
  const evade_cmd_ack_t* nan = f.acks.find(test_command_key().id, 1);
  const evade_cmd_ack_t* future = f.acks.find(test_command_key().id, 2);
  ASSERT_TRUE(nan != nullptr && future != nullptr);
  EXPECT_EQ(nan->reason, Ack::REASON_NOT_FINITE);
  EXPECT_EQ(nan->detail, Ack::CONJ_NOT_FINITE);
  EXPECT_EQ(future->reason, Ack::REASON_FROM_FUTURE);
  EXPECT_EQ(f.rig.node.responder().counters().events_tracked, 0);
  EXPECT_FALSE(f.rig.node.plan_once());
  EXPECT_TRUE(f.proposals.all().empty());
  expect_accounted(f.rig);
}

// An attack on the conjunction or decision channel: nothing tracked or decided, no job for the
// worker, no thrust, the reason counted once, the identity holds.
void expect_refused(Flight& f, Reason why, std::int64_t auth_failed, std::int64_t replayed = 0) {
  EXPECT_EQ(f.steps(kT0 + 10 * kPeriodUs, kT0 + 60 * kPeriodUs), 0);
  EXPECT_EQ(reason(f.rig, why), 1) << reason_name(why);
  EXPECT_EQ(f.rig.node.counts().auth_failed, auth_failed);
  EXPECT_EQ(f.rig.node.counts().replayed, replayed);
  EXPECT_EQ(f.rig.node.responder().counters().decisions_applied, 0);
  expect_accounted(f.rig);
}

TEST(NodeConjunctionAttack, UnsignedConjunctionAndDecisionAreRefused) {
  for (const char* ch : {kChanConjunction, kChanCamDecision}) {
    Flight f;
    f.rig.pub.set_signing(false);
    if (ch == kChanConjunction) {
      f.rig.pub.send(ch, conjunction_msg(node_event(), 1));
    } else {
      f.rig.pub.send(ch, decision_msg(Dec::DECISION_SET_AUTONOMY, 0, 0, Dec::AUTONOMY_OFF));
    }
    f.rig.pub.set_signing(true);
    expect_refused(f, Reason::kUnsigned, 1);
    EXPECT_EQ(f.rig.node.responder().counters().events_tracked, 0);
    EXPECT_EQ(f.rig.node.responder().policy(), Policy::kVeto);
  }
}

TEST(NodeConjunctionAttack, ForgedConjunctionIsRefusedAndTracksNothing) {
  Flight f;
  send(f.rig, kChanConjunction,
       signed_bytes(conjunction_msg(node_event(), 1), kChanConjunction, test_key(1, 0x77), 5));
  expect_refused(f, Reason::kBadMac, 1);
  EXPECT_EQ(f.rig.node.responder().counters().events_tracked, 0);
  EXPECT_FALSE(f.rig.node.plan_once());
}

TEST(NodeConjunctionAttack, ConjunctionSignedForAnotherChannelIsRefused) {
  Flight f;
  send(f.rig, kChanConjunction,
       signed_bytes(conjunction_msg(node_event(), 1), kChanPlan, test_command_key(), 5));
  expect_refused(f, Reason::kBadMac, 1);
  EXPECT_EQ(f.rig.node.responder().counters().events_tracked, 0);
}

// Signed for the plan channel and sent there: authentic, but not a plan.
TEST(NodeConjunctionAttack, ConjunctionBytesOnThePlanChannelDoNotDecode) {
  Flight f;
  send(f.rig, kChanPlan, signed_bytes(conjunction_msg(node_event(), 1), kChanPlan, test_command_key(), 5));
  expect_refused(f, Reason::kDecodeFailed, 0);
  EXPECT_EQ(f.rig.node.plan_executor().status().accepted, 0);
  EXPECT_EQ(f.rig.node.responder().counters().events_tracked, 0);
}

TEST(NodeConjunctionAttack, ReplayedConjunctionAndDecisionAreReplays) {
  Flight f;
  const std::vector<std::uint8_t> c =
      signed_bytes(conjunction_msg(node_event(), 1), kChanConjunction, test_command_key(), 5);
  send(f.rig, kChanConjunction, c);
  f.steps(kT0, kT0 + 2 * kPeriodUs);
  EXPECT_EQ(f.rig.node.responder().counters().events_tracked, 1);
  send(f.rig, kChanConjunction, c);
  expect_refused(f, Reason::kReplayedArsn, 0, 1);
  // A decision recorded on the bus and sent again later: the ARSN already passed.
  const std::vector<std::uint8_t> d = signed_bytes(
      decision_msg(Dec::DECISION_SET_AUTONOMY, 0, 0, Dec::AUTONOMY_OFF), kChanCamDecision,
      test_command_key(), 6);
  send(f.rig, kChanCamDecision, d);
  f.steps(kT0 + 60 * kPeriodUs, kT0 + 62 * kPeriodUs);
  EXPECT_EQ(f.rig.node.responder().policy(), Policy::kOff);
  send(f.rig, kChanCamDecision,
       signed_bytes(decision_msg(Dec::DECISION_SET_AUTONOMY, 0, 0, Dec::AUTONOMY_VETO),
                    kChanCamDecision, test_command_key(), 7));
  f.steps(kT0 + 62 * kPeriodUs, kT0 + 64 * kPeriodUs);
  EXPECT_EQ(f.rig.node.responder().policy(), Policy::kVeto);
  send(f.rig, kChanCamDecision, d);  // the replayed "off"
  f.steps(kT0 + 64 * kPeriodUs, kT0 + 66 * kPeriodUs);
  EXPECT_EQ(f.rig.node.responder().policy(), Policy::kVeto);
  EXPECT_EQ(reason(f.rig, Reason::kReplayedArsn), 2);
  expect_accounted(f.rig);
}

TEST(NodeConjunctionAttack, ForgedOrMisdirectedDecisionIsRefused) {
  Flight f;
  const Dec off = decision_msg(Dec::DECISION_SET_AUTONOMY, 0, 0, Dec::AUTONOMY_OFF);
  send(f.rig, kChanCamDecision, signed_bytes(off, kChanCamDecision, test_key(1, 0x99), 9));
  send(f.rig, kChanCamDecision, signed_bytes(off, kChanArm, test_command_key(), 10));
  send(f.rig, kChanCamDecision, signed_bytes(off, kChanCamDecision, test_sensor_key(), 11));
  EXPECT_EQ(f.steps(kT0, kT0 + 50 * kPeriodUs), 0);
  EXPECT_EQ(reason(f.rig, Reason::kBadMac), 2);
  EXPECT_EQ(reason(f.rig, Reason::kWrongKeyRole), 1);
  EXPECT_EQ(f.rig.node.responder().policy(), Policy::kVeto);
  EXPECT_EQ(f.rig.node.counts().auth_failed, 3);
  expect_accounted(f.rig);
}

}  // namespace
}  // namespace evade::guidance_lcm::test
