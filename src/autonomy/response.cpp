// The onboard assessment of one uplinked conjunction (include/evade/autonomy/response.hpp
// gives the steps; docs/AUTONOMY.md AUT-6).
#include "evade/autonomy/response.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "evade/autonomy/nav_check.hpp"

namespace evade::autonomy {

const char* policy_name(Policy p) noexcept {
  switch (p) {
    case Policy::kOff: return "off";
    case Policy::kVeto: return "veto";
    case Policy::kApprove: return "approve";
  }
  return "unknown";
}

bool parse_policy(const char* text, Policy* out) noexcept {
  if (text == nullptr) return false;
  for (const Policy p : {Policy::kOff, Policy::kVeto, Policy::kApprove}) {
    if (std::strcmp(text, policy_name(p)) == 0) {
      *out = p;
      return true;
    }
  }
  return false;
}

const char* response_state_name(ResponseState s) noexcept {
  static constexpr const char* kNames[] = {"assessing", "no_action", "proposed", "scheduled",
                                           "executed", "vetoed", "needs_ground", "refused",
                                           "superseded", "expired", "report_only"};
  const auto i = static_cast<std::size_t>(s);
  return (i >= 1 && i <= 11) ? kNames[i - 1] : "unknown";
}

const char* response_reason_name(ResponseReason r) noexcept {
  static constexpr const char* kNames[] = {"none", "nav_mismatch", "2d_not_valid", "no_feasible_burn",
                                           "raises_other", "window_passed", "not_approved", "bad_event",
                                           "no_nav", "table_full", "plan_rejected", "executor_busy",
                                           "burn_abandoned", "deadline_passed"};
  const auto i = static_cast<std::size_t>(r);
  return i < sizeof(kNames) / sizeof(kNames[0]) ? kNames[i] : "unknown";
}

namespace {

// The failed checks that make the 2D Pc not hold (npd alone does not: see the header).
constexpr std::uint16_t kNotValidBits =
    assessment::kUsageExtended | assessment::kUsageOffset | assessment::kUsageShortTerm;

// Step 2: false when the outcome is already decided (refused or needs_ground).
bool assess_at_tca(const ConjunctionEvent& e, const ResponderConfig& cfg, const EarthModel& earth,
                   CamWorkspace* ws, Assessment* out) noexcept {
  assessment::Encounter2d enc;
  const StateEci s1{e.x1_eci.head<3>(), e.x1_eci.tail<3>()};
  const StateEci s2{e.x2_eci.head<3>(), e.x2_eci.tail<3>()};
  const assessment::Encounter2dStatus st = assessment::assess_encounter_2d(
      s1, e.cov1_eci, s2, e.cov2_eci, e.hbr_m, cfg.encounter, earth, &ws->pc, &enc);
  out->miss_m = (s2.r_eci_m - s1.r_eci_m).norm();
  if (st == assessment::Encounter2dStatus::kBadCovariance) {
    out->state = ResponseState::kRefused;
    out->reason = ResponseReason::kBadEvent;
    return false;
  }
  if (st != assessment::Encounter2dStatus::kOk) {
    out->state = ResponseState::kNeedsGround;
    out->reason = ResponseReason::k2dNotValid;
    return false;
  }
  out->pc = enc.pc.pc;
  out->usage_failed = enc.failed;
  if ((enc.failed & kNotValidBits) != 0) {
    out->state = ResponseState::kNeedsGround;
    out->reason = ResponseReason::k2dNotValid;
    return false;
  }
  return true;
}

// The largest post-burn Pc of the other events, and whether each stays within its red.
bool others_within_red(const PlanningJob& job, std::int64_t burn_us, const Vec3& dv_eci,
                       const ResponderConfig& cfg, const EarthModel& earth, CamWorkspace* ws,
                       double* max_pc) noexcept {
  *max_pc = 0.0;
  bool all_ok = true;
  for (std::size_t k = 0; k < job.n_others && k < job.others.size(); ++k) {
    BurnOutcome o;
    bool within = false;
    const CamStatus s = check_other_event(job.others[k], burn_us, dv_eci, cfg.cam, earth, ws, &o, &within);
    // An outcome that cannot be computed cannot show the burn is safe for that event.
    if (s != CamStatus::kOk) return false;
    *max_pc = std::max(*max_pc, o.pc);
    all_ok = all_ok && within;
  }
  return all_ok;
}

// Step 4: the smallest burn over the candidate times that keeps the others within red.
void propose_burn(const PlanningJob& job, const ResponderConfig& cfg, const EarthModel& earth,
                  CamWorkspace* ws, Assessment* out) noexcept {
  ConjunctionEvent e = job.event;
  const std::int64_t after_deadline_us =
      e.veto_deadline_us + static_cast<std::int64_t>(std::llround(1e6 * cfg.decision_lead_s));
  e.burn_start_us = std::max(e.burn_start_us, after_deadline_us);
  std::array<double, OnboardCamOptions::kMaxBurnTimes> taus{};
  const int n = candidate_burn_times(e, job.now_us, cfg.cam, taus.data());
  bool any_feasible = false;
  double best_dv = 0.0;
  for (int k = 0; k < n; ++k) {
    CamProposal p;
    if (plan_burn_at(e, taus[static_cast<std::size_t>(k)], cfg.cam, earth, ws, &p) != CamStatus::kOk) continue;
    any_feasible = true;
    const double dv = p.dv_eci_mps.norm();
    if (out->state == ResponseState::kProposed && dv >= best_dv) continue;
    const std::int64_t burn_us = e.tca_us + static_cast<std::int64_t>(std::llround(1e6 * p.burn_from_tca_s));
    double others_pc = 0.0;
    if (!others_within_red(job, burn_us, p.dv_eci_mps, cfg, earth, ws, &others_pc)) continue;
    best_dv = dv;
    out->state = ResponseState::kProposed;
    out->reason = ResponseReason::kNone;
    out->burn_us = burn_us;
    out->dv_eci_mps = p.dv_eci_mps;
    out->dv_rsw_mps = p.dv_rsw_mps;
    out->post_pc = p.after.pc;
    out->post_miss_m = p.after.miss_m;
    out->other_events_max_post_pc = others_pc;
  }
  if (out->state != ResponseState::kProposed) {
    out->state = ResponseState::kNeedsGround;
    out->reason = any_feasible ? ResponseReason::kRaisesOther : ResponseReason::kNoFeasibleBurn;
  }
}

}  // namespace

void assess_event(const PlanningJob& job, const ResponderConfig& cfg, const EarthModel& earth,
                  CamWorkspace* ws, Assessment* out) noexcept {
  *out = Assessment{};
  const ConjunctionEvent& e = job.event;
  out->event_id = e.event_id;
  out->version = e.version;
  out->state = ResponseState::kNeedsGround;
  if (!job.nav_valid) {
    out->reason = ResponseReason::kNoNav;
    return;
  }
  const NavCheck nav = check_own_state(e, job.x_nav_eci, job.now_us, cfg.cam.step_s, earth);
  out->nav_mismatch_sigma = nav.sigma;
  if (!nav.ok || !(nav.sigma <= cfg.nav_mismatch_sigma)) {
    out->state = ResponseState::kRefused;
    out->reason = nav.ok ? ResponseReason::kNavMismatch : ResponseReason::kBadEvent;
    return;
  }
  if (!assess_at_tca(e, cfg, earth, ws, out)) return;
  if (out->pc <= e.pc_red) {
    out->state = ResponseState::kNoAction;
    return;
  }
  propose_burn(job, cfg, earth, ws, out);
}

}  // namespace evade::autonomy
