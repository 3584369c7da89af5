// One uplinked conjunction as the onboard response sees it (docs/AUTONOMY.md AUT-1): both
// objects' states and 6x6 covariances at TCA (ECI, J2000 axes), the combined hard-body radius,
// the operator's red threshold and post-burn target, the burn window and the veto deadline,
// and its check at the edge (every field in range before anything uses it). The LCM message is
// evade_conjunction_t (lcm_types/); the node converts it (guidance_lcm). Flight code: no
// allocation, no exceptions.
#pragma once

#include <cstdint>

#include "evade/core/state.hpp"

namespace evade::autonomy {

struct ConjunctionEvent {
  std::int64_t event_id = 0;       ///< > 0
  std::int32_t version = 0;        ///< > 0: a higher one replaces the event's older one
  std::int64_t tca_us = 0;         ///< time of closest approach [us, the node's time base]
  Vec6 x1_eci = Vec6::Zero();      ///< own spacecraft at TCA [m, m/s]
  Mat6 cov1_eci = Mat6::Zero();    ///< its covariance [m^2, m^2/s, m^2/s^2]
  Vec6 x2_eci = Vec6::Zero();      ///< the other object at TCA
  Mat6 cov2_eci = Mat6::Zero();
  double hbr_m = 0.0;              ///< combined hard-body radius [m]
  double pc_red = 0.0;             ///< above it the event needs a burn [-]
  double pc_target = 0.0;          ///< the burn brings the Pc below it [-]
  std::int64_t burn_start_us = 0;  ///< the burn window [us]
  std::int64_t burn_end_us = 0;
  std::int64_t veto_deadline_us = 0;  ///< the ground's decision counts before it [us]
};

/// The limits of an event's fields (docs/AUTONOMY.md AUT-1).
struct EventLimits {
  static constexpr double kMinPc = 1e-7;        ///< thresholds are configurable down to this
  static constexpr double kMaxHbrM = 1000.0;    ///< a larger combined radius is not a conjunction
  static constexpr double kMaxRadiusM = 1e9;    ///< positions beyond it are garbage
  static constexpr double kMaxSpeedMps = 1e5;
  static constexpr std::int64_t kMaxLeadUs = 7LL * 86400 * 1000000;  ///< TCA at most 7 days ahead
};

enum class EventProblem : std::uint8_t {
  kNone = 0,
  kBadId,          ///< event id or version not positive
  kNotFinite,      ///< NaN or Inf in a state, a covariance or a threshold
  kOutOfRange,     ///< a state, the hard-body radius or a threshold outside its limits
  kAsymmetric,     ///< a covariance is not symmetric (to 1e-9 of its largest term)
  kBadWindow,      ///< not start < end <= TCA, or the veto deadline after the window's end
  kTcaNotAhead,    ///< TCA not after now, or more than EventLimits::kMaxLeadUs ahead
};
const char* event_problem_name(EventProblem p) noexcept;

/// True when every field of a equals b's (checked events: no NaN).
bool same_event(const ConjunctionEvent& a, const ConjunctionEvent& b) noexcept;

/// The first problem of e at now_us, kNone when every field is in range.
EventProblem check_event(const ConjunctionEvent& e, std::int64_t now_us) noexcept;

}  // namespace evade::autonomy
