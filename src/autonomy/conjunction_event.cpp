// The check of an uplinked conjunction (include/evade/autonomy/conjunction_event.hpp).
#include "evade/autonomy/conjunction_event.hpp"

#include <cmath>

namespace evade::autonomy {
namespace {

bool symmetric(const Mat6& c) noexcept {
  const double scale = c.cwiseAbs().maxCoeff();
  return (c - c.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * scale;
}

bool state_in_range(const Vec6& x) noexcept {
  return x.head<3>().norm() <= EventLimits::kMaxRadiusM &&
         x.tail<3>().norm() <= EventLimits::kMaxSpeedMps && x.head<3>().norm() > 0.0;
}

bool pc_in_range(double pc) noexcept { return pc >= EventLimits::kMinPc && pc <= 1.0; }

bool all_finite(const ConjunctionEvent& e) noexcept {
  return e.x1_eci.allFinite() && e.x2_eci.allFinite() && e.cov1_eci.allFinite() &&
         e.cov2_eci.allFinite() && std::isfinite(e.hbr_m) && std::isfinite(e.pc_red) &&
         std::isfinite(e.pc_target);
}

}  // namespace

const char* event_problem_name(EventProblem p) noexcept {
  switch (p) {
    case EventProblem::kNone: return "none";
    case EventProblem::kBadId: return "bad_id";
    case EventProblem::kNotFinite: return "not_finite";
    case EventProblem::kOutOfRange: return "out_of_range";
    case EventProblem::kAsymmetric: return "asymmetric_covariance";
    case EventProblem::kBadWindow: return "bad_window";
    case EventProblem::kTcaNotAhead: return "tca_not_ahead";
  }
  return "?";
}

namespace {

// Thresholds in (0, 1] with the post-burn target at or below the red one, and the radius.
bool limits_in_range(const ConjunctionEvent& e) noexcept {
  const bool thresholds = pc_in_range(e.pc_red) && pc_in_range(e.pc_target) &&
                          e.pc_target <= e.pc_red;
  return thresholds && e.hbr_m > 0.0 && e.hbr_m <= EventLimits::kMaxHbrM;
}

// The burn window ends at or before TCA and the veto deadline at or before its end.
bool window_ordered(const ConjunctionEvent& e) noexcept {
  return e.burn_start_us < e.burn_end_us && e.burn_end_us <= e.tca_us &&
         e.veto_deadline_us <= e.burn_end_us;
}

}  // namespace

bool same_event(const ConjunctionEvent& a, const ConjunctionEvent& b) noexcept {
  return a.event_id == b.event_id && a.version == b.version && a.tca_us == b.tca_us &&
         a.x1_eci == b.x1_eci && a.cov1_eci == b.cov1_eci && a.x2_eci == b.x2_eci &&
         a.cov2_eci == b.cov2_eci && a.hbr_m == b.hbr_m && a.pc_red == b.pc_red &&
         a.pc_target == b.pc_target && a.burn_start_us == b.burn_start_us &&
         a.burn_end_us == b.burn_end_us && a.veto_deadline_us == b.veto_deadline_us;
}

EventProblem check_event(const ConjunctionEvent& e, std::int64_t now_us) noexcept {
  if (e.event_id <= 0 || e.version <= 0) return EventProblem::kBadId;
  if (!all_finite(e)) return EventProblem::kNotFinite;
  if (!state_in_range(e.x1_eci) || !state_in_range(e.x2_eci) || !limits_in_range(e)) {
    return EventProblem::kOutOfRange;
  }
  if (!symmetric(e.cov1_eci) || !symmetric(e.cov2_eci)) return EventProblem::kAsymmetric;
  if (!window_ordered(e)) return EventProblem::kBadWindow;
  if (!(e.tca_us > now_us && e.tca_us - now_us <= EventLimits::kMaxLeadUs)) {
    return EventProblem::kTcaNotAhead;
  }
  return EventProblem::kNone;
}

}  // namespace evade::autonomy
