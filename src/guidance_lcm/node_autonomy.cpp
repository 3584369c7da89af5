// The guidance node's onboard conjunction response (docs/AUTONOMY.md AUT-1, AUT-7, AUT-8):
// what the node does with an authenticated evade_conjunction_t or evade_cam_decision_t (the
// responder's answer, counted and acknowledged like every command), the planning worker's
// hand-over once per cycle (planning_mailbox.hpp: the assessment runs beside the cycle, never
// inside it), the responder's one action of the cycle on the plan executor (load the onboard
// burn, or withdraw it), and the signed proposals (evade_cam_proposal_t). The burn is flown by
// the plan executor like an uplinked plan, so close-range evasion (paper 000) still pre-empts
// it. Members of NodeCore (internal/node_core.hpp).
#include <algorithm>

#include "evade/guidance_lcm/autonomy_convert.hpp"
#include "evade/guidance_lcm/internal/node_core.hpp"

namespace evade::guidance_lcm::internal {
namespace {

using Ack = evade_cmd_ack_t;

std::int8_t outcome_code(const CommandOutcome& o) noexcept {
  if (o.in_force) return Ack::OUTCOME_ALREADY_IN_FORCE;  // a retransmission: nothing changed
  return o.reason == Reason::kOk ? Ack::OUTCOME_ACCEPTED : Ack::OUTCOME_REFUSED;
}

}  // namespace

void NodeCore::execute_conjunction(CommandInbox::Slot& s, std::int64_t now_us) noexcept {
  from_lcm(conj_msg_, &event_);
  autonomy::EventProblem problem = autonomy::EventProblem::kNone;
  const autonomy::EventResult r = responder_.receive_event(event_, now_us, &problem);
  const CommandOutcome o = conjunction_outcome(r, problem);
  counts_.add(o.verdict, o.reason);
  ack(s, outcome_code(o), o.in_force ? Reason::kOk : o.reason, o.detail, 0, now_us);
}

void NodeCore::execute_decision(CommandInbox::Slot& s, std::int64_t now_us) noexcept {
  from_lcm(decision_msg_, &decision_);
  const CommandOutcome o = decision_outcome(responder_.receive_decision(decision_, now_us));
  counts_.add(o.verdict, o.reason);
  ack(s, outcome_code(o), o.in_force ? Reason::kOk : o.reason, o.detail, 0, now_us);
}

// Once per cycle, after the commands: the worker's finished job back to the responder, the
// next job out, the end of the onboard burn noticed, and the responder's action taken.
void NodeCore::step_autonomy(std::int64_t now_us) noexcept {
  if (planner_.take_result(&job_back_, &assessment_back_)) {
    last_planning_us_ = planner_.last_work_us();
    max_planning_us_ = std::max(max_planning_us_, last_planning_us_);
    (void)responder_.complete(job_back_, assessment_back_, now_us);  // stale: counted there
  }
  hand_out_job(now_us);
  watch_onboard_plan();
  const guidance::PlanExecStatus& st = plan_exec_.status();
  const bool ground_plan_active = st.plan_id != onboard_plan_id_ &&
                                  (st.state == guidance::PlanState::kWaiting ||
                                   st.state == guidance::PlanState::kBurning);
  const autonomy::ResponderAction act = responder_.tick(now_us, ground_plan_active);
  if (act.kind == autonomy::ResponderAction::Kind::kSchedule) schedule_burn(act, now_us);
  if (act.kind == autonomy::ResponderAction::Kind::kCancel) cancel_burn(act);
}

// The job carries the node's navigation at its own time of validity (the nav check
// propagates from there), or none when the node has no fresh navigation (no_nav).
void NodeCore::hand_out_job(std::int64_t now_us) noexcept {
  if (!planner_.idle() || !responder_.next_job(now_us, &job_out_)) return;
  const guidance::NavState& nav = input_.nav;
  job_out_.nav_valid = nav.valid && nav.utime_us <= now_us && now_us - nav.utime_us <= stale_us_;
  if (job_out_.nav_valid) {
    job_out_.now_us = nav.utime_us;
    job_out_.x_nav_eci.head<3>() = nav.r_eci_m;
    job_out_.x_nav_eci.tail<3>() = nav.v_eci_mps;
  }
  (void)planner_.post(job_out_);  // idle above: cannot refuse
}

// The executor ended the onboard burn (completed, or abandoned: evasion, safe, a missed
// start), or a ground plan replaced it: the responder learns which.
void NodeCore::watch_onboard_plan() noexcept {
  if (onboard_plan_id_ == 0) return;
  const guidance::PlanExecStatus& st = plan_exec_.status();
  if (st.plan_id == onboard_plan_id_ && st.state != guidance::PlanState::kEnded) return;
  const bool completed = st.plan_id == onboard_plan_id_ && st.end == guidance::PlanEnd::kCompleted;
  responder_.plan_ended(onboard_plan_id_, completed);
  onboard_plan_id_ = 0;
}

// The proposal as a one-impulse plan in ECI at the burn's centre, its id the next after the
// executor's (an uplinked plan after it must be newer still: the acknowledgement's plan_id
// tells the ground). The executor validates it like any plan (budget, thrust, armed).
void NodeCore::schedule_burn(const autonomy::ResponderAction& act, std::int64_t now_us) noexcept {
  onboard_plan_ = guidance::UplinkedPlan{};
  const std::int64_t id = plan_exec_.status().plan_id + 1;
  onboard_plan_.plan.plan_id = id;
  onboard_plan_.plan.n_impulses = 1;
  onboard_plan_.plan.source = static_cast<int>(PlanSource::kCollisionAvoidance);
  ImpulsiveBurn& b = onboard_plan_.plan.impulses[0];
  b.t_s = 0.0;
  b.dv_eci_valid = true;
  b.dv_eci_mps = act.dv_eci_mps;
  if (act.slot < autonomy::kMaxEvents) b.dv_rsw_mps = responder_.record(act.slot).assessment.dv_rsw_mps;
  onboard_plan_.epoch_utime_us = act.burn_us;
  onboard_plan_.frame = guidance::PlanFrame::kEci;
  const bool ok = plan_exec_.load(onboard_plan_, now_us, armed_, law_.status().dv_used_mps) ==
                  guidance::PlanReject::kNone;
  if (ok) {
    onboard_plan_id_ = id;
    plan_in_force_size_ = 0;  // the plan in force is no longer an uplinked message
  }
  responder_.scheduled(act.slot, act.proposal_id, ok ? id : 0, ok);
}

void NodeCore::cancel_burn(const autonomy::ResponderAction& act) noexcept {
  if (act.plan_id == 0 || act.plan_id != onboard_plan_id_) return;
  if (plan_exec_.status().plan_id == act.plan_id) plan_exec_.cancel(guidance::PlanEnd::kCancelledOnboard);
  onboard_plan_id_ = 0;
}

// Every record that changed this cycle, and every tracked one once a second; a superseded
// version's notice before its successor. At most 2 kMaxEvents messages per cycle.
void NodeCore::publish_proposals(std::int64_t now_us) noexcept {
  const bool periodic = cycles_ % proposal_period_cycles_ == 0;
  for (std::size_t i = 0; i < autonomy::kMaxEvents; ++i) {
    if (!responder_.tracked(i)) continue;
    const autonomy::ResponseRecord& r = responder_.record(i);
    if (!r.changed && !periodic) continue;
    if (r.superseded_version > 0) publish_proposal(r, true, now_us);
    publish_proposal(r, false, now_us);
    responder_.published(i);
  }
}

void NodeCore::publish_proposal(const autonomy::ResponseRecord& r, bool superseded,
                                std::int64_t now_us) noexcept {
  to_lcm(r, responder_.policy(), now_us, superseded, &proposal_msg_);
  proposal_msg_.seq = ++proposal_seq_;
  if (proposal_pub_.publish(proposal_msg_) != 0) ++publish_failures_;
}

}  // namespace evade::guidance_lcm::internal
