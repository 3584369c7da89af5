// The node's answer to one uplinked conjunction (docs/AUTONOMY.md AUT-6): the whole onboard
// assessment of an event as one pure function, which the node's planning worker runs beside
// the guidance cycle (never inside it), in this order:
//   1. the uplinked own state against the node's navigation propagated to TCA (AUT-2): beyond
//      nav_mismatch_sigma the event is refused (nav_mismatch); without navigation the ground
//      must decide (no_nav);
//   2. the 2D assessment at TCA (AUT-4, assessment::assess_encounter_2d, evade assess's code):
//      where CARA's extended, offset or short-term check fails, the 2D Pc does not hold and the
//      node names the outcome needs_ground (2d_not_valid) rather than guess (a repaired
//      covariance alone, npd, is reported and not a reason: CARA remediates it the same way);
//   3. at or below the red threshold: no action;
//   4. above it, the smallest burn at each candidate time of the window (AUT-5, plan_burn_at),
//      the window starting decision_lead_s after the veto deadline so that the ground's veto
//      always comes before the burn; each burn checked against every other tracked event
//      (check_other_event); the smallest burn that keeps every other event at or below its red
//      threshold is proposed. None reaching the target: needs_ground (no_feasible_burn); every
//      one raising another event: needs_ground (raises_other).
// Flight code: no allocation, no exceptions, loops bounded by the options' counts and
// kMaxEvents. The codes are evade_cam_proposal_t's (lcm_types/), value for value.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "evade/assessment/assess_params.hpp"
#include "evade/assessment/encounter_2d.hpp"
#include "evade/autonomy/conjunction_event.hpp"
#include "evade/autonomy/event_table.hpp"
#include "evade/autonomy/onboard_cam.hpp"
#include "evade/core/param.hpp"

namespace evade::autonomy {

/// The node's policy (evade_cam_decision_t.AUTONOMY_*).
enum class Policy : std::uint8_t {
  kOff = 0,      ///< assess and report only: never burn
  kVeto = 1,     ///< burn unless the ground vetoes before the deadline (the default)
  kApprove = 2,  ///< burn only when the ground approves before the deadline
};
const char* policy_name(Policy p) noexcept;
/// "off", "veto", "approve" into *out; false for anything else.
bool parse_policy(const char* text, Policy* out) noexcept;

/// evade_cam_proposal_t.STATE_*.
enum class ResponseState : std::uint8_t {
  kAssessing = 1, kNoAction = 2, kProposed = 3, kScheduled = 4, kExecuted = 5, kVetoed = 6,
  kNeedsGround = 7, kRefused = 8, kSuperseded = 9, kExpired = 10, kReportOnly = 11,
};
const char* response_state_name(ResponseState s) noexcept;

/// evade_cam_proposal_t.REASON_*.
enum class ResponseReason : std::uint16_t {
  kNone = 0, kNavMismatch = 1, k2dNotValid = 2, kNoFeasibleBurn = 3, kRaisesOther = 4,
  kWindowPassed = 5, kNotApproved = 6, kBadEvent = 7, kNoNav = 8, kTableFull = 9,
  kPlanRejected = 10,  ///< the plan executor refused the burn (its reason is counted there)
  kExecutorBusy = 11,  ///< another plan is active in the executor at the deadline
  kBurnAbandoned = 12, ///< the executor ended the burn before it was delivered
  kDeadlinePassed = 13, ///< the proposal was ready only after the veto deadline
};
const char* response_reason_name(ResponseReason r) noexcept;

/// The settings of the onboard response (key prefix "node.autonomy."; responder_params).
struct ResponderConfig {
  double nav_mismatch_sigma = 5.0;  ///< refuse an event whose own state is further from nav [-]
  double decision_lead_s = 60.0;    ///< no burn sooner than this after the veto deadline [s]
  OnboardCamOptions cam;            ///< the burn search (its step is the nav check's too)
  /// From the assessment.* table (encounter_2d_config); its defaults unless set.
  assessment::Encounter2dConfig encounter = assessment::encounter_2d_config(assessment::AssessConfig{});
};

ParamTable<ResponderConfig> responder_params() noexcept;
/// The range check of every field ("" when valid, else the parameter's error text).
std::string validate_responder_config(const ResponderConfig& c);

/// One planning job: the event and the other live events as they were when it was handed out.
struct PlanningJob {
  std::size_t slot = kMaxEvents;
  std::uint32_t generation = 0;    ///< the slot's generation then (a result of an older one is stale)
  ConjunctionEvent event{};
  std::array<ConjunctionEvent, kMaxEvents - 1> others{};
  std::size_t n_others = 0;
  std::int64_t now_us = 0;         ///< when the job was handed out
  bool nav_valid = false;          ///< the node's navigation at now_us
  Vec6 x_nav_eci = Vec6::Zero();
};

/// What the assessment found (the fields of evade_cam_proposal_t it fills).
struct Assessment {
  std::int64_t event_id = 0;
  std::int32_t version = 0;
  ResponseState state = ResponseState::kNeedsGround;  ///< kRefused, kNeedsGround, kNoAction or kProposed
  ResponseReason reason = ResponseReason::kNone;
  double nav_mismatch_sigma = 0.0;
  double miss_m = 0.0;
  double pc = 0.0;
  std::uint16_t usage_failed = 0;  ///< assessment::Usage2dBit (= evade_cam_proposal_t.USAGE_*)
  std::int64_t burn_us = 0;        ///< kProposed: the burn's centre
  Vec3 dv_eci_mps = Vec3::Zero();
  Vec3 dv_rsw_mps = Vec3::Zero();
  double post_pc = 0.0;
  double post_miss_m = 0.0;
  double other_events_max_post_pc = 0.0;
};

/// Steps 1 to 4 of the file comment for job; *out is every field.
void assess_event(const PlanningJob& job, const ResponderConfig& cfg, const EarthModel& earth,
                  CamWorkspace* ws, Assessment* out) noexcept;

}  // namespace evade::autonomy
