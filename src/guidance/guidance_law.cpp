// Close-range evasion guidance law of paper 000 (Yao & Wang 2012): thrust at the maximum
// acceleration along −e_θ (eq. 8–12, 19), e_θ from filtered angles (eq. 13–18) with the
// zenith convention; ZEM (eq. 7) and t_go (eq. 12) when the sensor gives range. Modes, limits
// and the EVADE trigger are documented in include/evade/guidance/guidance_law.hpp.
#include "evade/guidance/guidance_law.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "evade/core/constants.hpp"
#include "evade/guidance/los_geometry.hpp"

namespace evade::guidance {

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

namespace {

// Appends "GuidanceConfig.<key> = <v> outside <range>" if !ok.
void check(std::ostringstream& err, bool ok, const char* key, double v, const char* range) {
  if (ok || !err.str().empty()) return;  // report the first bad field
  err << "GuidanceConfig." << key << " = " << v << " outside " << range;
}

bool in(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }
bool in_open_lo(double v, double lo, double hi) { return std::isfinite(v) && v > lo && v <= hi; }

bool measurement_well_formed(const AnglesMeasurement& m) noexcept {
  constexpr double kHalfPi = 0.5 * kPi;
  if (!std::isfinite(m.elevation_rad) || std::abs(m.elevation_rad) > kHalfPi + 1e-9) return false;
  if (!std::isfinite(m.azimuth_rad) || std::abs(m.azimuth_rad) > 2.0 * kTwoPi) return false;
  if (!std::isfinite(m.sigma_rad) || m.sigma_rad < 0.0) return false;
  if (m.has_rates) {
    if (!std::isfinite(m.elevation_rate_radps) || !std::isfinite(m.azimuth_rate_radps)) {
      return false;
    }
    if (!std::isfinite(m.rate_sigma_radps) || m.rate_sigma_radps < 0.0) return false;
    // β̇ may be large near the pole, but β̇ cos ε (a LOS rate) must be finite and bounded.
    if (!std::isfinite(m.azimuth_rate_radps * std::cos(m.elevation_rad))) return false;
  }
  if (m.has_range) {
    if (!std::isfinite(m.range_m) || !(m.range_m > 0.0)) return false;
    if (!std::isfinite(m.range_rate_mps)) return false;
  }
  return true;
}

}  // namespace

std::string GuidanceConfig::validate() const {
  std::ostringstream err;
  check(err, in_open_lo(max_accel_mps2, 0.0, 100.0), "max_accel_mps2", max_accel_mps2,
        "(0, 100]");
  check(err, in_open_lo(dv_budget_mps, 0.0, 1e4), "dv_budget_mps", dv_budget_mps, "(0, 1e4]");
  check(err, in_open_lo(max_burn_s, 0.0, 1e5), "max_burn_s", max_burn_s, "(0, 1e5]");
  check(err, in_open_lo(stale_limit_s, 0.0, 60.0), "stale_limit_s", stale_limit_s, "(0, 60]");
  check(err, in_open_lo(nominal_cycle_s, 0.0, 10.0), "nominal_cycle_s", nominal_cycle_s,
        "(0, 10]");
  check(err, in(rate_noise_threshold_radps, 0.0, 1.0), "rate_noise_threshold_radps",
        rate_noise_threshold_radps, "[0, 1]");
  check(err, in(rate_noise_k_sigma, 0.0, 100.0), "rate_noise_k_sigma", rate_noise_k_sigma,
        "[0, 100]");
  check(err, in_open_lo(zem_trigger_m, 0.0, 1e8), "zem_trigger_m", zem_trigger_m, "(0, 1e8]");
  check(err, min_track_updates >= 1 && min_track_updates <= 1000, "min_track_updates",
        min_track_updates, "[1, 1000]");
  const LosFilterConfig& f = filter;
  check(err, in_open_lo(f.process_noise_radps2, 0.0, 1e3), "filter.process_noise_radps2",
        f.process_noise_radps2, "(0, 1e3]");
  check(err, in_open_lo(f.init_rate_sigma_radps, 0.0, 10.0), "filter.init_rate_sigma_radps",
        f.init_rate_sigma_radps, "(0, 10]");
  check(err, in_open_lo(f.angle_sigma_floor_rad, 0.0, 1.0), "filter.angle_sigma_floor_rad",
        f.angle_sigma_floor_rad, "(0, 1]");
  check(err, in_open_lo(f.rate_sigma_floor_radps, 0.0, 1.0), "filter.rate_sigma_floor_radps",
        f.rate_sigma_floor_radps, "(0, 1]");
  check(err, in_open_lo(f.gate_chi2_2dof, 0.0, 1e6), "filter.gate_chi2_2dof", f.gate_chi2_2dof,
        "(0, 1e6]");
  check(err, in_open_lo(f.gate_chi2_4dof, 0.0, 1e6), "filter.gate_chi2_4dof", f.gate_chi2_4dof,
        "(0, 1e6]");
  check(err, in_open_lo(f.reinit_gap_s, 0.0, 3600.0), "filter.reinit_gap_s", f.reinit_gap_s,
        "(0, 3600]");
  check(err, f.max_consecutive_rejects >= 1 && f.max_consecutive_rejects <= 100000,
        "filter.max_consecutive_rejects", f.max_consecutive_rejects, "[1, 100000]");
  return err.str();
}

GuidanceLaw::GuidanceLaw(const GuidanceConfig& cfg) : cfg_(cfg), filter_(cfg.filter) {
  const std::string err = cfg.validate();
  if (!err.empty()) throw std::invalid_argument(err);
}

void GuidanceLaw::reset() noexcept {
  const GuidanceConfig cfg = cfg_;
  filter_ = LosRateFilter(cfg.filter);
  status_ = GuidanceStatus{};
  have_prev_step_ = false;
  prev_step_us_ = 0;
  prev_accel_mps2_ = 0.0;
  have_time_origin_ = false;
  time_origin_us_ = 0;
  coast_latched_ = false;
  coast_reason_ = CommandReason::kPassedClosestApproach;
  evade_started_ = false;
  u_at_evade_start_eci_ = Vec3::Zero();
  have_range_ = false;
  range_utime_us_ = 0;
  range_m_ = 0.0;
  range_rate_mps_ = 0.0;
  was_closing_ = false;
  have_tca_estimate_ = false;
  tca_estimate_us_ = 0;
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

ThrustCommand GuidanceLaw::step(const GuidanceInput& in, std::int64_t now_us) noexcept {
  // Account for the command in force since the previous step (zero-order hold).
  if (have_prev_step_ && now_us > prev_step_us_) {
    const double dt = 1e-6 * static_cast<double>(now_us - prev_step_us_);
    if (prev_accel_mps2_ > 0.0) {
      status_.dv_used_mps += prev_accel_mps2_ * dt;
      status_.burn_s += dt;
    }
  }
  have_prev_step_ = true;
  prev_step_us_ = now_us;
  ++status_.cycles;
  status_.utime_us = now_us;
  if (!have_time_origin_) {
    have_time_origin_ = true;
    time_origin_us_ = now_us;
  }
  const std::int64_t stale_us = static_cast<std::int64_t>(cfg_.stale_limit_s * 1e6);

  // 1. Measurement: validate, then feed the filter.
  if (in.has_measurement) {
    const AnglesMeasurement& m = in.meas;
    if (!m.valid) {
      ++status_.meas_invalid;  // the sensor reports no detection
    } else if (!measurement_well_formed(m) || m.utime_us > now_us + stale_us) {
      ++status_.meas_invalid;
      return hold(GuidanceMode::kSafe, CommandReason::kMeasurementInvalid, now_us);
    } else if (now_us - m.utime_us > stale_us) {
      ++status_.meas_invalid;  // arrived too late to be useful: ignored
    } else {
      LosMeasurement lm;
      lm.t_s = to_s(m.utime_us);
      lm.elevation_rad = m.elevation_rad;
      lm.azimuth_rad = m.azimuth_rad;
      lm.sigma_rad = m.sigma_rad;
      lm.has_rates = m.has_rates;
      lm.elevation_rate_radps = m.elevation_rate_radps;
      lm.azimuth_rate_radps = m.azimuth_rate_radps;
      lm.rate_sigma_radps = m.rate_sigma_radps;
      const bool new_encounter =
          !filter_.initialized() || lm.t_s - filter_.last_update_s() > cfg_.filter.reinit_gap_s;
      if (new_encounter) {  // a new track: forget the previous encounter
        coast_latched_ = false;
        evade_started_ = false;
        have_tca_estimate_ = false;
        was_closing_ = false;
      }
      // Angles-only closest-approach test on the raw measurement (independent of the filter,
      // which may be gating measurements while the LOS whips round at the encounter): the
      // measured LOS has swung by more than 90° from its direction when EVADE began.
      if (evade_started_ && !coast_latched_ &&
          los_unit_from_angles(m.elevation_rad, m.azimuth_rad).dot(u_at_evade_start_eci_) < 0.0) {
        coast_latched_ = true;
        coast_reason_ = CommandReason::kPassedClosestApproach;
      }
      const LosUpdateResult r = filter_.update(lm);
      if (m.has_range && r != LosUpdateResult::kRejected && r != LosUpdateResult::kOutOfOrder) {
        have_range_ = true;
        range_utime_us_ = m.utime_us;
        range_m_ = m.range_m;
        range_rate_mps_ = m.range_rate_mps;
      }
    }
  }
  status_.meas_accepted = filter_.accepted();
  status_.meas_rejected = filter_.rejected();
  status_.filter_reinits = filter_.reinitializations();

  // 2. Navigation.
  const NavState& nav = in.nav;
  if (!nav.valid || !nav.r_eci_m.allFinite() || !nav.v_eci_mps.allFinite() ||
      !(nav.r_eci_m.norm() > 0.0)) {
    return hold(GuidanceMode::kSafe, CommandReason::kNavInvalid, now_us);
  }
  if (now_us - nav.utime_us > stale_us || nav.utime_us - now_us > stale_us) {
    return hold(GuidanceMode::kSafe, CommandReason::kNavStale, now_us);
  }

  // 3. Track.
  const bool tracked =
      filter_.initialized() && filter_.updates_since_init() >= cfg_.min_track_updates;
  status_.track_valid = tracked;
  if (!tracked) {
    status_.zem_valid = false;
    status_.tgo_valid = false;
    return hold(GuidanceMode::kStandby, CommandReason::kNoTrack, now_us);
  }
  const double now_s = to_s(now_us);
  if (!coast_latched_ && now_s - filter_.last_update_s() > cfg_.stale_limit_s) {
    return hold(GuidanceMode::kSafe, CommandReason::kMeasurementStale, now_us);
  }

  // 4. Estimate at now: LOS frame with the zenith convention, ω_s and its variance.
  Vec3 u;
  Vec3 ud;
  Mat6 P;
  filter_.predict_to(now_s, &u, &ud, &P);
  const double w = ud.norm();
  const Mat3 Pr = P.bottomRightCorner<3, 3>();
  const double w_var = (w > 0.0) ? (ud / w).dot(Pr * (ud / w)) : 0.5 * Pr.trace();
  const double min_rate = std::max(cfg_.rate_noise_threshold_radps,
                                   cfg_.rate_noise_k_sigma * std::sqrt(std::max(w_var, 0.0)));
  LosFrame frame;
  if (!los_frame(u, ud, nav.r_eci_m, nav.v_eci_mps, min_rate, &frame)) {
    return hold(GuidanceMode::kSafe, CommandReason::kNavInvalid, now_us);
  }
  status_.los_rate_radps = w;
  status_.los_rate_var_rad2ps2 = w_var;
  status_.los_unit_eci = frame.e_r_eci;
  status_.e_theta_eci = frame.e_theta_eci;
  if (w > 0.0) {
    const Vec3 e = ud / w;
    const Mat3 J = (Mat3::Identity() - e * e.transpose()) / w;
    status_.e_theta_cov = J * Pr * J.transpose();
  } else {
    status_.e_theta_cov = Mat3::Zero();
  }
  status_.zenith_flipped = frame.flipped;
  status_.fallback_direction = frame.fallback;

  // 5. Range information (eq. 7, 12), from a recent enough measurement.
  const bool range_fresh = have_range_ && now_us - range_utime_us_ <= stale_us;
  status_.zem_valid = false;
  status_.tgo_valid = false;
  if (range_fresh) {
    const double age_s = 1e-6 * static_cast<double>(now_us - range_utime_us_);
    const double range_now = std::max(range_m_ + range_rate_mps_ * age_s, 0.0);
    double zem = 0.0;
    double tgo = 0.0;
    if (zero_effort_miss_m(range_now, range_rate_mps_, w, &zem)) {
      status_.zem_valid = true;
      status_.zem_m = zem;
    }
    if (time_to_go_s(range_now, range_rate_mps_, &tgo)) {
      status_.tgo_valid = true;
      status_.tgo_s = tgo;
      have_tca_estimate_ = true;
      tca_estimate_us_ = now_us + static_cast<std::int64_t>(tgo * 1e6);
    }
    if (range_rate_mps_ < 0.0) was_closing_ = true;
    if (range_rate_mps_ >= 0.0 && !coast_latched_) {
      // Range rate changed sign (or the track began receding): closest approach passed.
      coast_latched_ = true;
      coast_reason_ = CommandReason::kPassedClosestApproach;
    }
  }
  if (!coast_latched_ && have_tca_estimate_ && !range_fresh && now_us > tca_estimate_us_) {
    coast_latched_ = true;  // t_go has elapsed
    coast_reason_ = CommandReason::kPassedClosestApproach;
  }
  if (!coast_latched_ && evade_started_ && frame.e_r_eci.dot(u_at_evade_start_eci_) < 0.0) {
    coast_latched_ = true;  // the LOS swung by more than 90°: the encounter is behind us
    coast_reason_ = CommandReason::kPassedClosestApproach;
  }

  // 6. Limits.
  const double dv_left = cfg_.dv_budget_mps - status_.dv_used_mps;
  const double burn_left = cfg_.max_burn_s - status_.burn_s;
  if (!coast_latched_ && dv_left <= 1e-9 * cfg_.dv_budget_mps) {
    coast_latched_ = true;
    coast_reason_ = CommandReason::kDvBudgetExhausted;
  }
  if (!coast_latched_ && burn_left < cfg_.nominal_cycle_s * (1.0 - 1e-6)) {
    coast_latched_ = true;
    coast_reason_ = CommandReason::kBurnTimeExhausted;
  }
  if (coast_latched_) return hold(GuidanceMode::kCoast, coast_reason_, now_us);

  // 7. Arm and trigger.
  if (!in.armed) return hold(GuidanceMode::kTracking, CommandReason::kDisarmed, now_us);
  if (status_.zem_valid && status_.zem_m >= cfg_.zem_trigger_m) {
    return hold(GuidanceMode::kTracking, CommandReason::kZemAboveTrigger, now_us);
  }

  // 8. EVADE: maximum acceleration along −e_θ (eq. 8–12), within the Δv budget.
  if (!evade_started_) {
    evade_started_ = true;
    u_at_evade_start_eci_ = frame.e_r_eci;
  }
  ThrustCommand cmd;
  cmd.utime_us = now_us;
  cmd.mode = GuidanceMode::kEvade;
  cmd.dir_eci = -frame.e_theta_eci;
  cmd.accel_mps2 = std::min(cfg_.max_accel_mps2, dv_left / cfg_.nominal_cycle_s);
  cmd.reason = frame.fallback ? CommandReason::kLowLosRate : CommandReason::kNone;
  status_.mode = cmd.mode;
  status_.reason = cmd.reason;
  prev_accel_mps2_ = cmd.accel_mps2;
  return cmd;
}

}  // namespace evade::guidance
