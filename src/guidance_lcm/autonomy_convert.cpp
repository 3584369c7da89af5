// The onboard conjunction response's LCM conversions (include/evade/guidance_lcm/
// autonomy_convert.hpp). The codes of the autonomy library are the messages' constants, value
// for value (the static_asserts below).
#include "evade/guidance_lcm/autonomy_convert.hpp"

#include "evade/evade_cmd_ack_t.hpp"

namespace evade::guidance_lcm {
namespace {

using autonomy::DecisionResult;
using autonomy::EventProblem;
using autonomy::EventResult;
using Ack = evade_cmd_ack_t;
using Prop = evade_cam_proposal_t;

static_assert(static_cast<int>(autonomy::ResponseState::kReportOnly) == Prop::STATE_REPORT_ONLY &&
                  static_cast<int>(autonomy::ResponseState::kAssessing) == Prop::STATE_ASSESSING,
              "ResponseState values are the proposal's STATE_* codes");
static_assert(static_cast<int>(autonomy::ResponseReason::kDeadlinePassed) == Prop::REASON_DEADLINE_PASSED &&
                  static_cast<int>(autonomy::ResponseReason::kNavMismatch) == Prop::REASON_NAV_MISMATCH,
              "ResponseReason values are the proposal's REASON_* codes");
static_assert(static_cast<int>(autonomy::Policy::kApprove) == evade_cam_decision_t::AUTONOMY_APPROVE &&
                  static_cast<int>(autonomy::Policy::kOff) == evade_cam_decision_t::AUTONOMY_OFF,
              "Policy values are the decision's AUTONOMY_* codes");
static_assert(static_cast<int>(autonomy::DecisionCommand::Kind::kSetAutonomy) ==
                  evade_cam_decision_t::DECISION_SET_AUTONOMY,
              "DecisionCommand::Kind values are the decision's DECISION_* codes");
static_assert(static_cast<int>(DecisionResult::kAlreadyApplied) == Ack::DECIDE_ALREADY_APPLIED &&
                  static_cast<int>(DecisionResult::kAutonomyOff) == Ack::DECIDE_AUTONOMY_OFF &&
                  static_cast<int>(DecisionResult::kUnknownEvent) == Ack::DECIDE_UNKNOWN_EVENT,
              "DecisionResult values are the acknowledgement's DECIDE_* codes");

template <int N>
void copy3(const double (&a)[N], Vec3* v) noexcept {
  static_assert(N == 3, "a 3-vector");
  for (int i = 0; i < 3; ++i) (*v)(i) = a[i];
}

void copy6(const double (&a)[6][6], Mat6* m) noexcept {
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) (*m)(i, j) = a[i][j];
  }
}

void state6(const double (&r)[3], const double (&v)[3], Vec6* x) noexcept {
  for (int i = 0; i < 3; ++i) {
    (*x)(i) = r[i];
    (*x)(i + 3) = v[i];
  }
}

void put3(const Vec3& v, double (&a)[3]) noexcept {
  for (int i = 0; i < 3; ++i) a[i] = v(i);
}

void put_state6(const Vec6& x, double (&r)[3], double (&v)[3]) noexcept {
  for (int i = 0; i < 3; ++i) {
    r[i] = x(i);
    v[i] = x(i + 3);
  }
}

void put6(const Mat6& m, double (&a)[6][6]) noexcept {
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) a[i][j] = m(i, j);
  }
}

void put_assessment(const autonomy::Assessment& a, evade_cam_proposal_t* out) noexcept {
  out->miss_m = a.miss_m;
  out->pc = a.pc;
  out->pc_method = a.miss_m > 0.0 ? Prop::METHOD_2D : Prop::METHOD_NONE;  // the 2D step ran
  out->usage_flags = static_cast<std::int16_t>(a.usage_failed);
  out->nav_mismatch_sigma = a.nav_mismatch_sigma;
}

void put_burn(const autonomy::Assessment& a, evade_cam_proposal_t* out) noexcept {
  out->burn_utime = a.burn_us;
  put3(a.dv_rsw_mps, out->dv_rsw_mps);
  put3(a.dv_eci_mps, out->dv_eci_mps);
  out->post_pc = a.post_pc;
  out->post_miss_m = a.post_miss_m;
  out->other_events_max_post_pc = a.other_events_max_post_pc;
}

std::int16_t problem_detail(EventProblem p) noexcept {
  switch (p) {
    case EventProblem::kBadId: return Ack::CONJ_BAD_ID;
    case EventProblem::kNotFinite: return Ack::CONJ_NOT_FINITE;
    case EventProblem::kAsymmetric: return Ack::CONJ_ASYMMETRIC;
    case EventProblem::kBadWindow: return Ack::CONJ_BAD_WINDOW;
    case EventProblem::kTcaNotAhead: return Ack::CONJ_TCA_NOT_AHEAD;
    case EventProblem::kOutOfRange:
    case EventProblem::kNone: break;
  }
  return Ack::CONJ_OUT_OF_RANGE;
}

}  // namespace

void from_lcm(const evade_conjunction_t& m, autonomy::ConjunctionEvent* out) noexcept {
  out->event_id = m.event_id;
  out->version = m.version;
  out->tca_us = m.tca_utime;
  state6(m.r1_eci_m, m.v1_eci_mps, &out->x1_eci);
  state6(m.r2_eci_m, m.v2_eci_mps, &out->x2_eci);
  copy6(m.cov1_eci, &out->cov1_eci);
  copy6(m.cov2_eci, &out->cov2_eci);
  out->hbr_m = m.hbr_m;
  out->pc_red = m.pc_red;
  out->pc_target = m.pc_target;
  out->burn_start_us = m.burn_window_start_utime;
  out->burn_end_us = m.burn_window_end_utime;
  out->veto_deadline_us = m.veto_deadline_utime;
}

// An unknown decision or autonomy value passes through as it is: the responder refuses it
// (bad_decision), so the acknowledgement names the problem instead of a silent default.
void from_lcm(const evade_cam_decision_t& m, autonomy::DecisionCommand* out) noexcept {
  out->kind = static_cast<autonomy::DecisionCommand::Kind>(static_cast<std::uint8_t>(m.decision));
  out->event_id = m.event_id;
  out->proposal_id = m.proposal_id;
  out->autonomy = static_cast<std::uint8_t>(m.autonomy);
}

void to_lcm(const autonomy::ConjunctionEvent& e, std::int64_t utime, std::int64_t seq,
            evade_conjunction_t* out) noexcept {
  out->utime = utime;
  out->seq = seq;
  out->event_id = e.event_id;
  out->version = e.version;
  out->tca_utime = e.tca_us;
  put_state6(e.x1_eci, out->r1_eci_m, out->v1_eci_mps);
  put_state6(e.x2_eci, out->r2_eci_m, out->v2_eci_mps);
  put6(e.cov1_eci, out->cov1_eci);
  put6(e.cov2_eci, out->cov2_eci);
  out->hbr_m = e.hbr_m;
  out->pc_red = e.pc_red;
  out->pc_target = e.pc_target;
  out->burn_window_start_utime = e.burn_start_us;
  out->burn_window_end_utime = e.burn_end_us;
  out->veto_deadline_utime = e.veto_deadline_us;
}

void to_lcm(const autonomy::DecisionCommand& d, std::int64_t utime, std::int64_t seq,
            evade_cam_decision_t* out) noexcept {
  out->utime = utime;
  out->seq = seq;
  out->decision = static_cast<std::int8_t>(d.kind);
  out->event_id = d.event_id;
  out->proposal_id = d.proposal_id;
  out->autonomy = static_cast<std::int8_t>(d.autonomy);
}

void to_lcm(const autonomy::ResponseRecord& r, autonomy::Policy policy, std::int64_t now_us,
            bool superseded, evade_cam_proposal_t* out) noexcept {
  out->utime = now_us;
  out->event_id = r.event_id;
  out->version = superseded ? r.superseded_version : r.version;
  out->proposal_id = superseded ? r.superseded_proposal_id : r.proposal_id;
  out->state = static_cast<std::int8_t>(superseded ? autonomy::ResponseState::kSuperseded : r.state);
  out->reason = static_cast<std::int16_t>(superseded ? autonomy::ResponseReason::kNone : r.reason);
  out->autonomy = static_cast<std::int8_t>(policy);
  out->veto_deadline_utime = r.veto_deadline_us;
  out->plan_id = superseded ? 0 : r.plan_id;
  put_assessment(autonomy::Assessment{}, out);  // nothing assessed (yet) for this version
  put_burn(autonomy::Assessment{}, out);
  const autonomy::Assessment& a = r.assessment;
  if (superseded || a.event_id != r.event_id || a.version != r.version) return;
  put_assessment(a, out);
  if (a.burn_us != 0) put_burn(a, out);
}

CommandOutcome conjunction_outcome(EventResult r, EventProblem p) noexcept {
  switch (r) {
    case EventResult::kTracked: return {Verdict::kConsumed, Reason::kOk, Ack::CONJ_TRACKED};
    case EventResult::kReplaced: return {Verdict::kConsumed, Reason::kOk, Ack::CONJ_REPLACED};
    case EventResult::kNotNewer: return {Verdict::kStale, Reason::kOutOfOrderSeq, Ack::CONJ_NOT_NEWER};
    case EventResult::kTableFull: return {Verdict::kRejected, Reason::kTableFull, Ack::CONJ_TABLE_FULL};
    case EventResult::kAlreadyTracked:
      return {Verdict::kStale, Reason::kDuplicateSeq, Ack::CONJ_ALREADY_TRACKED, true};
    case EventResult::kBadEvent: break;
  }
  const Reason why = p == EventProblem::kNotFinite ? Reason::kNotFinite : Reason::kOutOfRange;
  return {Verdict::kRejected, why, problem_detail(p)};
}

CommandOutcome decision_outcome(DecisionResult r) noexcept {
  const auto detail = static_cast<std::int16_t>(r);
  if (r == DecisionResult::kApplied) return {Verdict::kConsumed, Reason::kOk, detail};
  if (r == DecisionResult::kAlreadyApplied) return {Verdict::kStale, Reason::kDuplicateSeq, detail, true};
  if (r == DecisionResult::kBadDecision) return {Verdict::kRejected, Reason::kOutOfRange, detail};
  return {Verdict::kRejected, Reason::kNotApplicable, detail};
}

}  // namespace evade::guidance_lcm
