// The node's authority over an onboard burn (docs/AUTONOMY.md AUT-7; responder.hpp's rules):
// each policy at its deadline, decisions naming the wrong proposal or arriving late, a veto
// that outlives a re-plan, supersession cancelling a loaded burn, stale worker results, one
// loaded burn at a time, and every input counted. The planning itself is replaced by
// hand-made results here (response_test.cpp runs the real one).
#include <gtest/gtest.h>

#include <cstdint>

#include "evade/autonomy/responder.hpp"

namespace evade::autonomy {
namespace {

constexpr std::int64_t kNow = 1'000'000'000'000;
constexpr std::int64_t kS = 1'000'000;  // one second [us]

// A valid event: TCA 3 h ahead, the deadline 1 h ahead, the window 1.5 h to 1 h before TCA.
ConjunctionEvent event(std::int64_t id, std::int32_t version) {
  ConjunctionEvent e;
  e.event_id = id;
  e.version = version;
  e.tca_us = kNow + 3 * 3600 * kS;
  e.x1_eci << 7078137.0, 0.0, 0.0, 0.0, -1070.3284, 7427.5644;
  e.x2_eci << 7078177.0, -11.293, -119.467, 0.0, 2443.1567, 7095.4423;
  e.cov1_eci = Mat6::Identity() * 100.0;
  e.cov2_eci = Mat6::Identity() * 400.0;
  e.hbr_m = 15.0;
  e.pc_red = 1e-4;
  e.pc_target = 1e-5;
  e.burn_start_us = e.tca_us - 5400 * kS;
  e.burn_end_us = e.tca_us - 3600 * kS;
  e.veto_deadline_us = kNow + 3600 * kS;
  return e;
}

// The worker's result for job: a proposed burn 10 min after the deadline.
Assessment proposed(const PlanningJob& job) {
  Assessment a;
  a.event_id = job.event.event_id;
  a.version = job.event.version;
  a.state = ResponseState::kProposed;
  a.pc = 3e-3;
  a.burn_us = job.event.veto_deadline_us + 600 * kS;
  a.dv_eci_mps << 0.0, 0.05, 0.0;
  a.post_pc = 9.9e-6;
  return a;
}

// Receives event e, completes every job with a proposal; returns e's slot.
std::size_t propose(Responder* r, const ConjunctionEvent& e, std::int64_t now = kNow) {
  EXPECT_NE(r->receive_event(e, now), EventResult::kBadEvent);
  PlanningJob job;
  for (std::size_t k = 0; k < kMaxEvents && r->next_job(now, &job); ++k)
    EXPECT_TRUE(r->complete(job, proposed(job), now));
  for (std::size_t i = 0; i < kMaxEvents; ++i) {
    if (r->tracked(i) && r->record(i).event_id == e.event_id) return i;
  }
  ADD_FAILURE() << "event " << e.event_id << " is not tracked";
  return 0;
}

DecisionCommand decision(DecisionCommand::Kind k, std::int64_t event_id, std::int64_t proposal_id) {
  DecisionCommand d;
  d.kind = k;
  d.event_id = event_id;
  d.proposal_id = proposal_id;
  return d;
}

TEST(Responder, VetoPolicyLoadsTheBurnAtTheDeadlineUnlessVetoed) {
  Responder r(Policy::kVeto);
  const std::size_t s = propose(&r, event(1, 1));
  EXPECT_EQ(r.record(s).state, ResponseState::kProposed);
  const std::int64_t deadline = r.record(s).veto_deadline_us;
  EXPECT_EQ(r.tick(deadline - 1, false).kind, ResponderAction::Kind::kNone) << "not before the deadline";
  const ResponderAction a = r.tick(deadline, false);
  ASSERT_EQ(a.kind, ResponderAction::Kind::kSchedule);
  EXPECT_EQ(a.proposal_id, r.record(s).proposal_id);
  EXPECT_EQ(a.burn_us, deadline + 600 * kS);
  EXPECT_EQ(r.record(s).state, ResponseState::kScheduled);
  r.scheduled(s, a.proposal_id, 42, true);
  EXPECT_EQ(r.tick(deadline + 1, false).kind, ResponderAction::Kind::kNone) << "one load, once";
  r.plan_ended(42, true);
  EXPECT_EQ(r.record(s).state, ResponseState::kExecuted);

  Responder v(Policy::kVeto);
  const std::size_t t = propose(&v, event(1, 1));
  ASSERT_EQ(v.receive_decision(decision(DecisionCommand::Kind::kVeto, 1, v.record(t).proposal_id), kNow),
            DecisionResult::kApplied);
  EXPECT_EQ(v.record(t).state, ResponseState::kVetoed);
  EXPECT_EQ(v.tick(deadline, false).kind, ResponderAction::Kind::kNone) << "a vetoed burn never loads";
  EXPECT_EQ(v.tick(deadline + 7200 * kS, false).kind, ResponderAction::Kind::kNone);
  EXPECT_EQ(v.record(t).state, ResponseState::kVetoed);
}

TEST(Responder, ApprovePolicyLoadsOnlyAnApprovedProposal) {
  Responder r(Policy::kApprove);
  const std::size_t s = propose(&r, event(1, 1));
  const std::int64_t deadline = r.record(s).veto_deadline_us;
  EXPECT_EQ(r.tick(deadline, false).kind, ResponderAction::Kind::kNone);
  EXPECT_EQ(r.record(s).state, ResponseState::kExpired);
  EXPECT_EQ(r.record(s).reason, ResponseReason::kNotApproved);

  Responder a(Policy::kApprove);
  const std::size_t t = propose(&a, event(1, 1));
  const std::int64_t pid = a.record(t).proposal_id;
  EXPECT_EQ(a.receive_decision(decision(DecisionCommand::Kind::kApprove, 1, pid + 1), kNow),
            DecisionResult::kWrongProposal);
  EXPECT_EQ(a.receive_decision(decision(DecisionCommand::Kind::kApprove, 2, pid), kNow),
            DecisionResult::kUnknownEvent);
  ASSERT_EQ(a.receive_decision(decision(DecisionCommand::Kind::kApprove, 1, pid), kNow), DecisionResult::kApplied);
  EXPECT_EQ(a.tick(deadline, false).kind, ResponderAction::Kind::kSchedule);
  EXPECT_EQ(a.counters().decisions_applied, 1);
  EXPECT_EQ(a.counters().decisions_refused, 2);
}

TEST(Responder, OffReportsOnlyAndCancelsALoadedBurn) {
  Responder r(Policy::kOff);
  const std::size_t s = propose(&r, event(1, 1));
  EXPECT_EQ(r.record(s).state, ResponseState::kReportOnly);
  const std::int64_t pid = r.record(s).proposal_id;
  EXPECT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kApprove, 1, pid), kNow), DecisionResult::kAutonomyOff);
  EXPECT_EQ(r.tick(r.record(s).veto_deadline_us, false).kind, ResponderAction::Kind::kNone);

  // Veto policy, the burn loaded after the deadline; then the ground sets autonomy off (the
  // other operator manoeuvres): the burn is cancelled at the next cycle.
  Responder v(Policy::kVeto);
  const std::size_t t = propose(&v, event(1, 1));
  const std::int64_t deadline = v.record(t).veto_deadline_us;
  const ResponderAction a = v.tick(deadline, false);
  ASSERT_EQ(a.kind, ResponderAction::Kind::kSchedule);
  v.scheduled(t, a.proposal_id, 42, true);
  DecisionCommand off;
  off.kind = DecisionCommand::Kind::kSetAutonomy;
  off.autonomy = static_cast<std::uint8_t>(Policy::kOff);
  ASSERT_EQ(v.receive_decision(off, deadline + kS), DecisionResult::kApplied);
  const ResponderAction c = v.tick(deadline + kS, false);
  EXPECT_EQ(c.kind, ResponderAction::Kind::kCancel);
  EXPECT_EQ(c.plan_id, 42);
  EXPECT_EQ(v.record(t).state, ResponseState::kReportOnly);
  off.autonomy = 3;
  EXPECT_EQ(v.receive_decision(off, deadline + kS), DecisionResult::kBadDecision) << "no such policy";
  EXPECT_EQ(v.policy(), Policy::kOff);
}

TEST(Responder, OffThenVetoRevivesAProposalOnlyBeforeItsDeadline) {
  Responder r(Policy::kOff);
  const std::size_t s = propose(&r, event(1, 1));
  DecisionCommand on;
  on.kind = DecisionCommand::Kind::kSetAutonomy;
  on.autonomy = static_cast<std::uint8_t>(Policy::kVeto);
  const std::int64_t deadline = r.record(s).veto_deadline_us;
  ASSERT_EQ(r.receive_decision(on, deadline), DecisionResult::kApplied);
  EXPECT_EQ(r.record(s).state, ResponseState::kReportOnly) << "the ground never had its veto window";
  EXPECT_EQ(r.tick(deadline, false).kind, ResponderAction::Kind::kNone);

  Responder q(Policy::kOff);
  const std::size_t t = propose(&q, event(1, 1));
  ASSERT_EQ(q.receive_decision(on, kNow + kS), DecisionResult::kApplied);
  EXPECT_EQ(q.record(t).state, ResponseState::kProposed);
}

TEST(Responder, ARetransmittedDecisionIsAlreadyAppliedBeforeAndAfterTheDeadline) {
  Responder r(Policy::kVeto);
  const std::size_t s = propose(&r, event(1, 1));
  const std::int64_t pid = r.record(s).proposal_id;
  const std::int64_t deadline = r.record(s).veto_deadline_us;
  ASSERT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kVeto, 1, pid), kNow), DecisionResult::kApplied);
  EXPECT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kVeto, 1, pid), kNow + kS),
            DecisionResult::kAlreadyApplied);
  EXPECT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kVeto, 1, pid), deadline + kS),
            DecisionResult::kAlreadyApplied) << "a copy answered late still names the veto in force";
  EXPECT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kVeto, 1, pid + 1), kNow + kS),
            DecisionResult::kWrongProposal) << "only the very decision is a retransmission";
  EXPECT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kApprove, 1, pid), deadline + kS),
            DecisionResult::kPastDeadline) << "a change after the deadline is refused";
  EXPECT_EQ(r.record(s).state, ResponseState::kVetoed);
  const ResponderCounters& c = r.counters();
  EXPECT_EQ(c.decisions_applied, 1);
  EXPECT_EQ(c.decisions_again, 2);
  EXPECT_EQ(c.decisions_refused, 2);
}

TEST(Responder, DecisionsAfterTheDeadlineAreRefusedAndTheLatestBeforeItCounts) {
  Responder r(Policy::kVeto);
  const std::size_t s = propose(&r, event(1, 1));
  const std::int64_t pid = r.record(s).proposal_id;
  const std::int64_t deadline = r.record(s).veto_deadline_us;
  ASSERT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kVeto, 1, pid), kNow), DecisionResult::kApplied);
  ASSERT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kApprove, 1, pid), kNow + kS), DecisionResult::kApplied);
  EXPECT_EQ(r.record(s).state, ResponseState::kProposed);
  EXPECT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kVeto, 1, pid), deadline), DecisionResult::kPastDeadline);
  EXPECT_EQ(r.tick(deadline, false).kind, ResponderAction::Kind::kSchedule);
  EXPECT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kVeto, 1, pid), deadline + kS),
            DecisionResult::kPastDeadline) << "a loaded burn is past its deadline";
}

TEST(Responder, ANewerVersionSupersedesCancelsItsLoadedBurnAndOldDecisionsMissTheNewProposal) {
  Responder r(Policy::kVeto);
  const std::size_t s = propose(&r, event(1, 1));
  const std::int64_t old_pid = r.record(s).proposal_id;
  const std::int64_t deadline = r.record(s).veto_deadline_us;
  const ResponderAction a = r.tick(deadline, false);
  ASSERT_EQ(a.kind, ResponderAction::Kind::kSchedule);
  r.scheduled(s, a.proposal_id, 42, true);
  ConjunctionEvent v2 = event(1, 2);
  v2.veto_deadline_us = deadline + 600 * kS;
  v2.burn_start_us = v2.veto_deadline_us;
  ASSERT_EQ(r.receive_event(v2, deadline + kS), EventResult::kReplaced);
  EXPECT_EQ(r.record(s).superseded_version, 1);
  EXPECT_EQ(r.record(s).superseded_proposal_id, old_pid);
  const ResponderAction c = r.tick(deadline + kS, false);
  EXPECT_EQ(c.kind, ResponderAction::Kind::kCancel);
  EXPECT_EQ(c.plan_id, 42);
  EXPECT_EQ(r.receive_event(event(1, 1), deadline + kS), EventResult::kNotNewer);
  PlanningJob job;
  ASSERT_TRUE(r.next_job(deadline + kS, &job));
  ASSERT_TRUE(r.complete(job, proposed(job), deadline + kS));
  EXPECT_NE(r.record(s).proposal_id, old_pid);
  EXPECT_EQ(r.receive_decision(decision(DecisionCommand::Kind::kVeto, 1, old_pid), deadline + kS),
            DecisionResult::kWrongProposal);
  r.published(s);
  EXPECT_EQ(r.record(s).superseded_version, 0) << "reported once";
}

TEST(Responder, AResultForASupersededOrReplannedEventIsStale) {
  Responder r(Policy::kVeto);
  ASSERT_EQ(r.receive_event(event(1, 1), kNow), EventResult::kTracked);
  PlanningJob job;
  ASSERT_TRUE(r.next_job(kNow, &job));
  PlanningJob none;
  EXPECT_FALSE(r.next_job(kNow, &none)) << "one job with the worker at a time";
  ASSERT_EQ(r.receive_event(event(1, 2), kNow), EventResult::kReplaced);
  EXPECT_FALSE(r.complete(job, proposed(job), kNow));
  EXPECT_EQ(r.record(job.slot).state, ResponseState::kAssessing);
  EXPECT_FALSE(r.complete(job, proposed(job), kNow)) << "a result nobody asked for";
  EXPECT_EQ(r.counters().stale_results, 2);

  // A proposal of event 1 goes back to assessment when event 2 arrives (its burn was not
  // checked against event 2); its approval does not carry over, a veto of it does.
  Responder q(Policy::kApprove);
  const std::size_t s1 = propose(&q, event(1, 1));
  const std::int64_t pid1 = q.record(s1).proposal_id;
  ASSERT_EQ(q.receive_decision(decision(DecisionCommand::Kind::kApprove, 1, pid1), kNow), DecisionResult::kApplied);
  ASSERT_EQ(q.receive_event(event(2, 1), kNow), EventResult::kTracked);
  EXPECT_EQ(q.record(s1).state, ResponseState::kAssessing);
  EXPECT_EQ(q.record(s1).proposal_id, 0);
  EXPECT_FALSE(q.record(s1).approved);
  for (std::size_t k = 0; k < kMaxEvents && q.next_job(kNow, &job); ++k)
    ASSERT_TRUE(q.complete(job, proposed(job), kNow));
  EXPECT_EQ(q.receive_decision(decision(DecisionCommand::Kind::kApprove, 1, pid1), kNow),
            DecisionResult::kWrongProposal) << "the approval was of the old burn";
  ASSERT_EQ(q.receive_decision(decision(DecisionCommand::Kind::kVeto, 1, q.record(s1).proposal_id), kNow),
            DecisionResult::kApplied);
  ASSERT_EQ(q.receive_event(event(3, 1), kNow), EventResult::kTracked);
  EXPECT_EQ(q.record(s1).state, ResponseState::kVetoed) << "a veto outlives a newcomer";
}

TEST(Responder, OneOnboardBurnLoadsAtATimeAndNoneOverTheGroundsPlan) {
  Responder r(Policy::kVeto);
  const std::size_t s1 = propose(&r, event(1, 1));
  propose(&r, event(2, 1));
  const std::int64_t deadline = r.record(s1).veto_deadline_us;
  ASSERT_EQ(r.tick(deadline, false).kind, ResponderAction::Kind::kSchedule);
  EXPECT_EQ(r.tick(deadline, false).kind, ResponderAction::Kind::kNone);
  int busy = 0;
  for (std::size_t i = 0; i < kMaxEvents; ++i)
    busy += r.tracked(i) && r.record(i).reason == ResponseReason::kExecutorBusy ? 1 : 0;
  EXPECT_EQ(busy, 1) << "the second event's burn waits for the ground";

  Responder g(Policy::kVeto);
  const std::size_t s = propose(&g, event(1, 1));
  EXPECT_EQ(g.tick(deadline, true).kind, ResponderAction::Kind::kNone) << "the ground's plan is active";
  EXPECT_EQ(g.record(s).reason, ResponseReason::kExecutorBusy);
}

TEST(Responder, AProposalReadyAfterTheDeadlineNeedsTheGround) {
  Responder r(Policy::kVeto);
  ASSERT_EQ(r.receive_event(event(1, 1), kNow), EventResult::kTracked);
  PlanningJob job;
  ASSERT_TRUE(r.next_job(kNow, &job));
  ASSERT_TRUE(r.complete(job, proposed(job), job.event.veto_deadline_us));
  EXPECT_EQ(r.record(job.slot).state, ResponseState::kNeedsGround);
  EXPECT_EQ(r.record(job.slot).reason, ResponseReason::kDeadlinePassed);
  EXPECT_EQ(r.tick(job.event.veto_deadline_us, false).kind, ResponderAction::Kind::kNone);
}

TEST(Responder, EveryEventIsCountedWhateverBecomesOfIt) {
  Responder r(Policy::kVeto);
  ConjunctionEvent bad = event(1, 1);
  bad.hbr_m = -1.0;
  EventProblem p = EventProblem::kNone;
  EXPECT_EQ(r.receive_event(bad, kNow, &p), EventResult::kBadEvent);
  EXPECT_EQ(p, EventProblem::kOutOfRange);
  for (std::int64_t id = 1; id <= static_cast<std::int64_t>(kMaxEvents); ++id)
    EXPECT_EQ(r.receive_event(event(id, 1), kNow), EventResult::kTracked);
  EXPECT_EQ(r.receive_event(event(99, 1), kNow), EventResult::kTableFull);
  EXPECT_EQ(r.receive_event(event(3, 1), kNow), EventResult::kAlreadyTracked) << "a retransmission";
  ConjunctionEvent altered = event(3, 1);
  altered.hbr_m += 1.0;
  EXPECT_EQ(r.receive_event(altered, kNow), EventResult::kNotNewer) << "version 1 again, altered";
  const ResponderCounters& c = r.counters();
  EXPECT_EQ(c.events_bad + c.events_tracked + c.events_table_full + c.events_not_newer +
                c.events_again,
            12);
  EXPECT_EQ(c.events_again, 1);
  EXPECT_EQ(c.events_tracked, static_cast<std::int64_t>(kMaxEvents));
  // An assessing event whose TCA passes expires.
  EXPECT_EQ(r.tick(event(1, 1).tca_us, false).kind, ResponderAction::Kind::kNone);
  EXPECT_EQ(r.record(0).state, ResponseState::kExpired);
}

}  // namespace
}  // namespace evade::autonomy
