// Close-range evasion guidance law of paper 000 (Yao & Wang 2012): thrust at the maximum
// acceleration along −e_θ (eq. 8–12, 19), e_θ from filtered angles (eq. 13–18) with the
// zenith convention; ZEM (eq. 7) and t_go (eq. 12) when the sensor gives range. Modes, limits
// and the EVADE trigger are documented in include/evade/guidance/guidance_law.hpp.
#include "evade/guidance/guidance_law.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "evade/core/constants.hpp"
#include "evade/guidance/guidance_params.hpp"
#include "evade/guidance/los_geometry.hpp"

namespace evade::guidance {
namespace {

// Longest t_go [s] kept as a time of closest approach: 1e9 s (31.7 years). Cycle times are at
// most 1e18 µs (the node admits no later tick), so now + t_go stays far inside int64 µs.
constexpr double kMaxTcaHorizonS = 1e9;

}  // namespace

const char* mode_name(GuidanceMode m) noexcept {
  switch (m) {
    case GuidanceMode::kStandby: return "STANDBY";
    case GuidanceMode::kTracking: return "TRACKING";
    case GuidanceMode::kEvade: return "EVADE";
    case GuidanceMode::kCoast: return "COAST";
    case GuidanceMode::kSafe: return "SAFE";
  }
  return "UNKNOWN";
}

const char* reason_name(CommandReason r) noexcept {
  switch (r) {
    case CommandReason::kNone: return "none";
    case CommandReason::kNoTrack: return "no_track";
    case CommandReason::kDisarmed: return "disarmed";
    case CommandReason::kZemAboveTrigger: return "zem_above_trigger";
    case CommandReason::kPassedClosestApproach: return "passed_closest_approach";
    case CommandReason::kDvBudgetExhausted: return "dv_budget_exhausted";
    case CommandReason::kBurnTimeExhausted: return "burn_time_exhausted";
    case CommandReason::kNavInvalid: return "nav_invalid";
    case CommandReason::kNavStale: return "nav_stale";
    case CommandReason::kMeasurementInvalid: return "measurement_invalid";
    case CommandReason::kMeasurementStale: return "measurement_stale";
    case CommandReason::kLowLosRate: return "low_los_rate_fallback";
  }
  return "unknown";
}

std::string GuidanceConfig::validate() const {
  return validate_params(guidance_params(), *this, "guidance.");
}

GuidanceLaw::GuidanceLaw(const GuidanceConfig& cfg)
    : cfg_(cfg), stale_us_(std::llround(cfg.stale_limit_s * 1e6)), filter_(cfg.filter) {
  const std::string err = cfg.validate();
  if (!err.empty()) throw std::invalid_argument(err);
}

void GuidanceLaw::reset() noexcept {
  filter_ = LosRateFilter(cfg_.filter);
  status_ = GuidanceStatus{};
  have_prev_step_ = false;
  prev_step_us_ = 0;
  prev_accel_mps2_ = 0.0;
  have_time_origin_ = false;
  time_origin_us_ = 0;
  enc_ = Encounter{};
}

// The one staleness test (guidance.stale_limit_s), for nav, measurements and range: older
// than the limit, or further in the future than the limit.
bool GuidanceLaw::is_stale(std::int64_t utime_us, std::int64_t now_us) const noexcept {
  return now_us - utime_us > stale_us_ || utime_us - now_us > stale_us_;
}

ThrustCommand GuidanceLaw::hold(GuidanceMode mode, CommandReason reason,
                                std::int64_t now_us) noexcept {
  ThrustCommand cmd;
  cmd.utime_us = now_us;
  cmd.mode = mode;
  cmd.reason = reason;
  status_.mode = mode;
  status_.reason = reason;
  prev_accel_mps2_ = 0.0;
  return cmd;
}

// Stage 0: Δv and burn time of the command in force since the previous step (zero-order
// hold), the cycle count and the filter's time origin.
void GuidanceLaw::account_previous_command(std::int64_t now_us) noexcept {
  if (have_prev_step_ && now_us > prev_step_us_ && prev_accel_mps2_ > 0.0) {
    const double dt = 1e-6 * static_cast<double>(now_us - prev_step_us_);
    status_.dv_used_mps += prev_accel_mps2_ * dt;
    status_.burn_s += dt;
  }
  have_prev_step_ = true;
  prev_step_us_ = now_us;
  ++status_.cycles;
  status_.utime_us = now_us;
  if (!have_time_origin_) {
    have_time_origin_ = true;
    time_origin_us_ = now_us;
  }
}

// Stage 1: accept the measurement. kMeasurementInvalid (SAFE) for a detection that is not
// well formed or is from the future; a no-detection or a late one is counted and ignored.
CommandReason GuidanceLaw::accept_measurement(const GuidanceInput& in,
                                              std::int64_t now_us) noexcept {
  if (!in.has_measurement) return CommandReason::kNone;
  const AnglesMeasurement& m = in.meas;
  if (!m.valid) {
    ++status_.meas_invalid;  // the sensor reports no detection
    return CommandReason::kNone;
  }
  if (!measurement_well_formed(m) || m.utime_us - now_us > stale_us_) {
    ++status_.meas_invalid;
    return CommandReason::kMeasurementInvalid;
  }
  if (is_stale(m.utime_us, now_us)) {
    ++status_.meas_invalid;  // arrived too late to be useful: ignored
    return CommandReason::kNone;
  }
  feed_filter(m);
  return CommandReason::kNone;
}

// A well-formed, timely measurement: a new encounter resets the encounter state; the raw
// LOS is tested for the angles-only closest approach (independent of the filter, which may
// be gating measurements while the LOS whips round at the encounter); then the filter.
void GuidanceLaw::feed_filter(const AnglesMeasurement& m) noexcept {
  const double t_s = to_s(m.utime_us);
  if (!filter_.initialized() || t_s - filter_.last_update_s() > cfg_.filter.reinit_gap_s) {
    enc_ = Encounter{};  // a new track: forget the previous encounter
  }
  const LosUpdateResult r = filter_.update(m, t_s);
  if (enc_.evade_started &&
      filter_.last_measured_u_eci().dot(enc_.u_at_evade_start_eci) < 0.0) {
    enc_.raw_los_swung = true;
  }
  if (m.has_range && r != LosUpdateResult::kRejected && r != LosUpdateResult::kOutOfOrder) {
    enc_.have_range = true;
    enc_.range_utime_us = m.utime_us;
    enc_.range_m = m.range_m;
    enc_.range_rate_mps = m.range_rate_mps;
  }
}

// Stage 2: navigation valid, finite, non-zero and fresh.
CommandReason GuidanceLaw::check_navigation(const NavState& nav,
                                            std::int64_t now_us) const noexcept {
  if (!nav.valid || !nav.r_eci_m.allFinite() || !nav.v_eci_mps.allFinite() ||
      !(nav.r_eci_m.norm() > 0.0)) {
    return CommandReason::kNavInvalid;
  }
  return is_stale(nav.utime_us, now_us) ? CommandReason::kNavStale : CommandReason::kNone;
}

// Stage 3: a track established (else STANDBY) and, unless coasting (or about to: the raw
// LOS has swung past 90°), fed recently.
CommandReason GuidanceLaw::check_track(std::int64_t now_us) noexcept {
  status_.track_valid =
      filter_.initialized() && filter_.updates_since_init() >= cfg_.min_track_updates;
  if (!status_.track_valid) {
    status_.zem_valid = false;
    status_.t_go_valid = false;
    return CommandReason::kNoTrack;
  }
  const bool coasting = enc_.coast_latched || enc_.raw_los_swung;
  if (!coasting && to_s(now_us) - filter_.last_update_s() > cfg_.stale_limit_s) {
    return CommandReason::kMeasurementStale;
  }
  return CommandReason::kNone;
}

// Stage 4: the LOS frame at now with the zenith convention, ω_s, its variance and the e_θ
// covariance, all from the filter's rate-block prediction and its own methods.
bool GuidanceLaw::estimate_los(const NavState& nav, std::int64_t now_us,
                               LosEstimate* est) noexcept {
  Vec3 u;
  Vec3 ud;
  Mat3 rate_cov;
  filter_.predict_rate_to(to_s(now_us), &u, &ud, &rate_cov);
  est->rate_radps = ud.norm();
  est->rate_var_rad2ps2 = LosRateFilter::los_rate_variance(ud, rate_cov);
  const double min_rate =
      std::max(cfg_.rate_noise_threshold_radps,
               cfg_.rate_noise_k_sigma * std::sqrt(std::max(est->rate_var_rad2ps2, 0.0)));
  if (!los_frame(u, ud, nav.r_eci_m, nav.v_eci_mps, min_rate, &est->frame)) return false;
  est->e_theta_cov_eci = LosRateFilter::e_theta_covariance(ud, rate_cov);
  status_.los_rate_radps = est->rate_radps;
  status_.los_rate_var_rad2ps2 = est->rate_var_rad2ps2;
  status_.los_unit_eci = est->frame.e_r_eci;
  status_.e_theta_eci = est->frame.e_theta_eci;
  status_.e_theta_cov_eci = est->e_theta_cov_eci;
  status_.zenith_flipped = est->frame.flipped;
  status_.fallback_direction = est->frame.fallback;
  return true;
}

// Stage 5a: ZEM (eq. 7) and t_go (eq. 12) from a recent range measurement, and the time of
// closest approach it predicts.
void GuidanceLaw::update_range_estimates(double los_rate_radps, std::int64_t now_us) noexcept {
  status_.zem_valid = false;
  status_.t_go_valid = false;
  if (!enc_.have_range || now_us - enc_.range_utime_us > stale_us_) return;
  const double age_s = 1e-6 * static_cast<double>(now_us - enc_.range_utime_us);
  const double range_now = std::max(enc_.range_m + enc_.range_rate_mps * age_s, 0.0);
  double zem = 0.0;
  double t_go = 0.0;
  if (zero_effort_miss_m(range_now, enc_.range_rate_mps, los_rate_radps, &zem)) {
    status_.zem_valid = true;
    status_.zem_m = zem;
  }
  if (time_to_go_s(range_now, enc_.range_rate_mps, &t_go)) {
    status_.t_go_valid = true;
    status_.t_go_s = t_go;
    // A t_go beyond kMaxTcaHorizonS (a nearly zero closing rate) predicts no closest approach
    // this loop will fly to, and has no µs time: no estimate (fuzz finding 10).
    enc_.have_tca_estimate = t_go <= kMaxTcaHorizonS;
    if (enc_.have_tca_estimate)
      enc_.tca_estimate_us = now_us + static_cast<std::int64_t>(t_go * 1e6);
  }
}

// Stage 5b: the one place that decides the coast latch. The first trigger that applies:
// the closest approach is behind us (range rate ≥ 0; t_go elapsed without fresh range; the
// LOS, filtered or raw, swung by more than 90° since EVADE began), then the Δv budget,
// then the burn time. kNone: no trigger.
CommandReason GuidanceLaw::coast_trigger(const LosEstimate& est,
                                         std::int64_t now_us) const noexcept {
  const bool range_fresh = enc_.have_range && now_us - enc_.range_utime_us <= stale_us_;
  const bool receding = range_fresh && enc_.range_rate_mps >= 0.0;
  const bool t_go_elapsed = enc_.have_tca_estimate && !range_fresh && now_us > enc_.tca_estimate_us;
  const bool los_swung =
      enc_.evade_started &&
      (enc_.raw_los_swung || est.frame.e_r_eci.dot(enc_.u_at_evade_start_eci) < 0.0);
  if (receding || t_go_elapsed || los_swung) return CommandReason::kPassedClosestApproach;
  if (cfg_.dv_budget_mps - status_.dv_used_mps <= 1e-9 * cfg_.dv_budget_mps) {
    return CommandReason::kDvBudgetExhausted;
  }
  if (cfg_.max_burn_s - status_.burn_s < cfg_.cycle_s() * (1.0 - 1e-6)) {
    return CommandReason::kBurnTimeExhausted;
  }
  return CommandReason::kNone;
}

// Stage 7: EVADE, maximum acceleration along −e_θ (eq. 8–12), the last command reduced so
// that one cycle cannot overshoot the Δv budget.
ThrustCommand GuidanceLaw::evade(const LosEstimate& est, std::int64_t now_us) noexcept {
  if (!enc_.evade_started) {
    enc_.evade_started = true;
    enc_.u_at_evade_start_eci = est.frame.e_r_eci;
  }
  const double dv_left_mps = cfg_.dv_budget_mps - status_.dv_used_mps;
  ThrustCommand cmd;
  cmd.utime_us = now_us;
  cmd.mode = GuidanceMode::kEvade;
  cmd.u_eci = -est.frame.e_theta_eci;
  cmd.accel_mps2 = std::min(cfg_.max_accel_mps2, dv_left_mps / cfg_.cycle_s());
  cmd.reason = est.frame.fallback ? CommandReason::kLowLosRate : CommandReason::kNone;
  status_.mode = cmd.mode;
  status_.reason = cmd.reason;
  prev_accel_mps2_ = cmd.accel_mps2;
  return cmd;
}

ThrustCommand GuidanceLaw::step(const GuidanceInput& in, std::int64_t now_us) noexcept {
  account_previous_command(now_us);
  const CommandReason meas = accept_measurement(in, now_us);
  status_.meas_accepted = filter_.accepted();
  status_.meas_rejected = filter_.rejected();
  status_.filter_reinits = filter_.reinitializations();
  if (meas != CommandReason::kNone) return hold(GuidanceMode::kSafe, meas, now_us);
  if (in.watchdog != WatchdogVerdict::kAlive) {
    ++status_.watchdog_cycles;
    return hold(GuidanceMode::kSafe, CommandReason::kMeasurementStale, now_us);
  }
  const CommandReason nav = check_navigation(in.nav, now_us);
  if (nav != CommandReason::kNone) return hold(GuidanceMode::kSafe, nav, now_us);
  const CommandReason track = check_track(now_us);
  if (track == CommandReason::kNoTrack) return hold(GuidanceMode::kStandby, track, now_us);
  if (track != CommandReason::kNone) return hold(GuidanceMode::kSafe, track, now_us);
  LosEstimate est;
  if (!estimate_los(in.nav, now_us, &est)) {
    return hold(GuidanceMode::kSafe, CommandReason::kNavInvalid, now_us);
  }
  update_range_estimates(est.rate_radps, now_us);
  if (!enc_.coast_latched) {
    const CommandReason trigger = coast_trigger(est, now_us);
    enc_.coast_latched = trigger != CommandReason::kNone;
    if (enc_.coast_latched) enc_.coast_reason = trigger;
  }
  if (enc_.coast_latched) return hold(GuidanceMode::kCoast, enc_.coast_reason, now_us);
  if (!in.armed) return hold(GuidanceMode::kTracking, CommandReason::kDisarmed, now_us);
  if (status_.zem_valid && status_.zem_m >= cfg_.zem_trigger_m) {
    return hold(GuidanceMode::kTracking, CommandReason::kZemAboveTrigger, now_us);
  }
  return evade(est, now_us);
}

}  // namespace evade::guidance
