// The node's authority over an onboard avoidance burn (include/evade/autonomy/responder.hpp
// gives the rules; docs/AUTONOMY.md AUT-7).
#include "evade/autonomy/responder.hpp"

#include <algorithm>

namespace evade::autonomy {

const char* decision_result_name(DecisionResult r) noexcept {
  static constexpr const char* kNames[] = {"applied", "bad_decision", "unknown_event", "not_pending",
                                           "wrong_proposal", "past_deadline", "autonomy_off",
                                           "already_applied"};
  const auto i = static_cast<std::size_t>(r);
  return i < sizeof(kNames) / sizeof(kNames[0]) ? kNames[i] : "unknown";
}

const char* event_result_name(EventResult r) noexcept {
  static constexpr const char* kNames[] = {"tracked", "replaced", "bad_event", "not_newer", "table_full",
                                           "already_tracked"};
  const auto i = static_cast<std::size_t>(r);
  return i < sizeof(kNames) / sizeof(kNames[0]) ? kNames[i] : "unknown";
}

namespace {

bool awaiting_decision(ResponseState s) noexcept {
  return s == ResponseState::kProposed || s == ResponseState::kVetoed || s == ResponseState::kReportOnly;
}

// The decision is the one in force for the record: a veto of a vetoed proposal, an approval of
// an approved one (waiting, loaded or flown). Before or after the deadline alike: a copy of a
// decision that was applied in time, answered after it, must not read as refused.
bool already_applied(const DecisionCommand& d, const ResponseRecord& r) noexcept {
  if (r.proposal_id == 0 || d.proposal_id != r.proposal_id) return false;
  if (d.kind == DecisionCommand::Kind::kVeto) return r.state == ResponseState::kVetoed;
  return d.kind == DecisionCommand::Kind::kApprove && r.approved &&
         (r.state == ResponseState::kProposed || r.state == ResponseState::kScheduled ||
          r.state == ResponseState::kExecuted);
}

bool counts_as_other(ResponseState s) noexcept {
  return s != ResponseState::kRefused && s != ResponseState::kExpired && s != ResponseState::kSuperseded;
}

}  // namespace

void Responder::set(std::size_t i, ResponseState s, ResponseReason r) noexcept {
  rec_[i].state = s;
  rec_[i].reason = r;
  rec_[i].changed = true;
}

void Responder::published(std::size_t slot) noexcept {
  if (slot >= kMaxEvents) return;
  rec_[slot].changed = false;
  rec_[slot].superseded_version = 0;
  rec_[slot].superseded_proposal_id = 0;
}

EventResult Responder::receive_event(const ConjunctionEvent& e, std::int64_t now_us,
                                     EventProblem* problem) noexcept {
  const EventProblem p = check_event(e, now_us);
  if (problem != nullptr) *problem = p;
  if (p != EventProblem::kNone) {
    ++counters_.events_bad;
    return EventResult::kBadEvent;
  }
  std::size_t i = kMaxEvents;
  const InsertResult ins = table_.insert(e, now_us, &i);
  if (ins == InsertResult::kNotNewer) {
    ++counters_.events_not_newer;
    return EventResult::kNotNewer;
  }
  if (ins == InsertResult::kSameVersion) {
    ++counters_.events_again;
    return EventResult::kAlreadyTracked;
  }
  if (ins == InsertResult::kTableFull) {
    ++counters_.events_table_full;
    return EventResult::kTableFull;
  }
  ResponseRecord r;
  r.event_id = e.event_id;
  r.version = e.version;
  r.veto_deadline_us = e.veto_deadline_us;
  r.generation = rec_[i].generation + 1;
  if (loaded_slot_ == i) {  // the old version's burn (or an over event's, its slot reused)
    pending_cancel_plan_ = rec_[i].plan_id;
    loaded_slot_ = kMaxEvents;
  }
  if (ins == InsertResult::kNewVersion) {
    r.superseded_version = rec_[i].version;
    r.superseded_proposal_id = rec_[i].proposal_id;
    ++counters_.events_replaced;
  } else {
    ++counters_.events_tracked;
  }
  rec_[i] = r;
  replan_others(i);
  return ins == InsertResult::kNewVersion ? EventResult::kReplaced : EventResult::kTracked;
}

void Responder::replan_others(std::size_t except) noexcept {
  for (std::size_t i = 0; i < kMaxEvents; ++i) {
    ResponseRecord& r = rec_[i];
    if (i == except || !table_.slot(i).used) continue;
    if (r.state != ResponseState::kProposed && r.state != ResponseState::kReportOnly) continue;
    r.proposal_id = 0;
    r.approved = false;
    ++r.generation;
    set(i, ResponseState::kAssessing, ResponseReason::kNone);
  }
}

DecisionResult Responder::receive_decision(const DecisionCommand& d, std::int64_t now_us) noexcept {
  const DecisionResult res = decide(d, now_us);
  if (res == DecisionResult::kApplied) {
    ++counters_.decisions_applied;
  } else if (res == DecisionResult::kAlreadyApplied) {
    ++counters_.decisions_again;
  } else {
    ++counters_.decisions_refused;
  }
  return res;
}

DecisionResult Responder::decide(const DecisionCommand& d, std::int64_t now_us) noexcept {
  if (d.kind == DecisionCommand::Kind::kSetAutonomy) {
    if (d.autonomy > static_cast<std::uint8_t>(Policy::kApprove)) return DecisionResult::kBadDecision;
    set_policy(static_cast<Policy>(d.autonomy), now_us);
    return DecisionResult::kApplied;
  }
  if (d.kind != DecisionCommand::Kind::kVeto && d.kind != DecisionCommand::Kind::kApprove)
    return DecisionResult::kBadDecision;
  const std::size_t i = table_.find(d.event_id);
  if (i >= kMaxEvents) return DecisionResult::kUnknownEvent;
  ResponseRecord& r = rec_[i];
  if (already_applied(d, r)) return DecisionResult::kAlreadyApplied;
  if (r.proposal_id == 0 || !awaiting_decision(r.state)) {
    return r.state == ResponseState::kScheduled ? DecisionResult::kPastDeadline : DecisionResult::kNotPending;
  }
  if (d.proposal_id != r.proposal_id) return DecisionResult::kWrongProposal;
  if (now_us >= r.veto_deadline_us) return DecisionResult::kPastDeadline;
  if (d.kind == DecisionCommand::Kind::kVeto) {
    r.approved = false;
    set(i, ResponseState::kVetoed, ResponseReason::kNone);
    return DecisionResult::kApplied;
  }
  if (policy_ == Policy::kOff) return DecisionResult::kAutonomyOff;
  r.approved = true;
  set(i, ResponseState::kProposed, ResponseReason::kNone);
  return DecisionResult::kApplied;
}

void Responder::set_policy(Policy p, std::int64_t now_us) noexcept {
  policy_ = p;
  for (std::size_t i = 0; i < kMaxEvents; ++i) {
    if (!table_.slot(i).used) continue;
    ResponseRecord& r = rec_[i];
    if (p == Policy::kOff && r.state == ResponseState::kProposed) {
      r.approved = false;
      set(i, ResponseState::kReportOnly, ResponseReason::kNone);
    } else if (p == Policy::kOff && r.state == ResponseState::kScheduled) {
      if (loaded_slot_ == i) {
        pending_cancel_plan_ = r.plan_id;
        loaded_slot_ = kMaxEvents;
      }
      set(i, ResponseState::kReportOnly, ResponseReason::kNone);
    } else if (p != Policy::kOff && r.state == ResponseState::kReportOnly && now_us < r.veto_deadline_us) {
      set(i, ResponseState::kProposed, ResponseReason::kNone);
    }
  }
}

bool Responder::next_job(std::int64_t now_us, PlanningJob* job) noexcept {
  if (in_flight_ < kMaxEvents) return false;
  std::size_t best = kMaxEvents;
  for (std::size_t i = 0; i < kMaxEvents; ++i) {
    if (!table_.slot(i).used || rec_[i].state != ResponseState::kAssessing) continue;
    if (best == kMaxEvents || table_.slot(i).event.tca_us < table_.slot(best).event.tca_us) best = i;
  }
  if (best == kMaxEvents) return false;
  job->slot = best;
  job->event = table_.slot(best).event;
  job->generation = rec_[best].generation;
  job->now_us = now_us;
  job->n_others = 0;
  for (std::size_t i = 0; i < kMaxEvents; ++i) {
    const EventTable::Slot& s = table_.slot(i);
    if (i == best || !s.used || s.event.tca_us <= now_us || !counts_as_other(rec_[i].state)) continue;
    job->others[job->n_others++] = s.event;
  }
  in_flight_ = best;
  ++counters_.jobs;
  return true;
}

bool Responder::complete(const PlanningJob& job, const Assessment& a, std::int64_t now_us) noexcept {
  const std::size_t i = job.slot;
  const bool was_in_flight = i < kMaxEvents && in_flight_ == i;
  if (was_in_flight) in_flight_ = kMaxEvents;
  if (!was_in_flight || !table_.slot(i).used || rec_[i].generation != job.generation ||
      rec_[i].state != ResponseState::kAssessing || a.event_id != rec_[i].event_id ||
      a.version != rec_[i].version) {
    ++counters_.stale_results;
    return false;
  }
  ResponseRecord& r = rec_[i];
  r.assessment = a;
  if (a.state != ResponseState::kProposed) {
    set(i, a.state, a.reason);
    return true;
  }
  if (now_us >= r.veto_deadline_us) {
    set(i, ResponseState::kNeedsGround, ResponseReason::kDeadlinePassed);
    return true;
  }
  last_proposal_id_ = std::max(last_proposal_id_ + 1, now_us);
  r.proposal_id = last_proposal_id_;
  r.approved = false;
  ++counters_.proposals;
  set(i, policy_ == Policy::kOff ? ResponseState::kReportOnly : ResponseState::kProposed, ResponseReason::kNone);
  return true;
}

bool Responder::tick_slot(std::size_t i, std::int64_t now_us, bool executor_busy,
                          ResponderAction* act) noexcept {
  ResponseRecord& r = rec_[i];
  const ConjunctionEvent& e = table_.slot(i).event;
  if (now_us >= e.tca_us && (r.state == ResponseState::kAssessing || r.state == ResponseState::kProposed)) {
    set(i, ResponseState::kExpired, ResponseReason::kWindowPassed);
    return false;
  }
  if (r.state != ResponseState::kProposed || now_us < r.veto_deadline_us) return false;
  if (policy_ == Policy::kApprove && !r.approved) {
    set(i, ResponseState::kExpired, ResponseReason::kNotApproved);
    return false;
  }
  if (executor_busy || loaded_slot_ < kMaxEvents || r.assessment.burn_us <= now_us) {
    set(i, ResponseState::kNeedsGround,
        r.assessment.burn_us <= now_us ? ResponseReason::kWindowPassed : ResponseReason::kExecutorBusy);
    return false;
  }
  act->kind = ResponderAction::Kind::kSchedule;
  act->slot = i;
  act->event_id = r.event_id;
  act->proposal_id = r.proposal_id;
  act->burn_us = r.assessment.burn_us;
  act->dv_eci_mps = r.assessment.dv_eci_mps;
  loaded_slot_ = i;
  set(i, ResponseState::kScheduled, ResponseReason::kNone);
  ++counters_.schedules;
  return true;
}

ResponderAction Responder::tick(std::int64_t now_us, bool executor_busy) noexcept {
  ResponderAction act;
  if (pending_cancel_plan_ != 0) {
    act.kind = ResponderAction::Kind::kCancel;
    act.plan_id = pending_cancel_plan_;
    pending_cancel_plan_ = 0;
    ++counters_.cancels;
    return act;
  }
  for (std::size_t i = 0; i < kMaxEvents; ++i) {
    if (table_.slot(i).used && tick_slot(i, now_us, executor_busy, &act)) return act;
  }
  return act;
}

void Responder::scheduled(std::size_t slot, std::int64_t proposal_id, std::int64_t plan_id,
                          bool accepted) noexcept {
  if (slot >= kMaxEvents || loaded_slot_ != slot || rec_[slot].proposal_id != proposal_id) return;
  if (accepted) {
    rec_[slot].plan_id = plan_id;
    rec_[slot].changed = true;
    return;
  }
  loaded_slot_ = kMaxEvents;
  set(slot, ResponseState::kNeedsGround, ResponseReason::kPlanRejected);
}

void Responder::plan_ended(std::int64_t plan_id, bool completed) noexcept {
  if (plan_id == 0 || loaded_slot_ >= kMaxEvents || rec_[loaded_slot_].plan_id != plan_id) return;
  const std::size_t i = loaded_slot_;
  loaded_slot_ = kMaxEvents;
  set(i, completed ? ResponseState::kExecuted : ResponseState::kNeedsGround,
      completed ? ResponseReason::kNone : ResponseReason::kBurnAbandoned);
}

}  // namespace evade::autonomy
