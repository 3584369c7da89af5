// Close-range evasion guidance law (paper 000, Yao & Wang 2012): continuous thrust at the
// maximum acceleration along −e_θ (eq. 8–12: this maximises the growth of V_θ and hence of
// ZEM = V_θ t_go), with e_θ estimated from angle measurements (eq. 13–18) by LosRateFilter
// and the zenith convention of los_geometry.hpp.
//
// Modes (GuidanceMode):
//   STANDBY  no LOS track (filter not initialised or re-initialising).
//   TRACKING track established (≥ min_track_updates accepted updates) but not evading:
//            disarmed, or range known and ZEM ≥ zem_trigger_m.
//   EVADE    armed + tracking + (no range information, or ZEM < zem_trigger_m): thrust
//            max_accel_mps2 along −e_θ. With angles only, ZEM cannot be computed, so a
//            tracked threat is always evaded (the paper's simulation: thrust from detection).
//   COAST    after the closest approach — range rate turned positive (range known), or the
//            LOS has swung by more than 90° from its direction when EVADE began (angles
//            only, tested on the filtered LOS and on each raw measurement; at a near-collision
//            the LOS flips at the encounter), or t_go has elapsed
//            — or when the Δv budget or the burn-time limit is used up. Zero thrust. Latched
//            until the track is lost/re-initialised or reset().
//   SAFE     invalid or stale inputs: navigation invalid, non-finite or older than
//            stale_limit_s; a measurement flagged valid but non-finite/out of range; no
//            accepted measurement for stale_limit_s while tracking. Zero thrust, with the
//            reason. Not latched: the law leaves SAFE as soon as its inputs are good again.
// Disarmed ⇒ zero thrust in every mode.
// Limits: |a| ≤ max_accel_mps2; Δv used ≤ dv_budget_mps (the last command is reduced so one
// nominal cycle cannot overshoot); burn time ≤ max_burn_s (no command whose nominal cycle
// would pass it). Δv and burn time are accounted from the commands actually issued and the
// time they were in force (now − previous step).
//
// step() is noexcept and allocation-free (fixed-size Eigen, bounded loops); the config is
// validated once in the constructor (std::invalid_argument naming the field).
#pragma once

#include <cstdint>
#include <string>

#include "evade/core/state.hpp"
#include "evade/guidance/los_rate_filter.hpp"

namespace evade::guidance {

enum class GuidanceMode : std::uint8_t {
  kStandby = 0,
  kTracking = 1,
  kEvade = 2,
  kCoast = 3,
  kSafe = 4,
};

/// Why the command is what it is (one per cycle; the first that applies).
enum class CommandReason : std::uint8_t {
  kNone = 0,              ///< evading normally (EVADE) or nothing to report
  kNoTrack = 1,           ///< STANDBY: no LOS track yet
  kDisarmed = 2,          ///< tracking, not armed
  kZemAboveTrigger = 3,   ///< tracking, range known, ZEM ≥ zem_trigger_m
  kPassedClosestApproach = 4,
  kDvBudgetExhausted = 5,
  kBurnTimeExhausted = 6,
  kNavInvalid = 7,        ///< nav flagged invalid or not finite
  kNavStale = 8,          ///< nav older than stale_limit_s (or from the future)
  kMeasurementInvalid = 9,   ///< a measurement flagged valid has bad fields
  kMeasurementStale = 10,    ///< no accepted measurement for stale_limit_s
  kLowLosRate = 11,       ///< EVADE with the fallback direction (ω_s below its noise)
};

const char* mode_name(GuidanceMode m) noexcept;
const char* reason_name(CommandReason r) noexcept;

/// Angle measurement of the threat (satellite-centred ECI-parallel frame, eq. 13–14).
struct AnglesMeasurement {
  std::int64_t utime_us = 0;       ///< time of validity [µs]
  std::int64_t seq = 0;            ///< sensor sequence number
  double elevation_rad = 0.0;      ///< ε ∈ [-π/2, π/2]
  double azimuth_rad = 0.0;        ///< β ∈ [-2π, 2π] (wrapped internally)
  double sigma_rad = 0.0;          ///< 1σ angle noise [rad], ≥ 0
  bool has_rates = false;          ///< the sensor also gives ε̇, β̇ (rate-stabilised tracker)
  double elevation_rate_radps = 0.0;
  double azimuth_rate_radps = 0.0;
  double rate_sigma_radps = 0.0;   ///< 1σ of the rates [rad/s], ≥ 0
  bool has_range = false;          ///< range and range rate present (e.g. radar)
  double range_m = 0.0;            ///< > 0
  double range_rate_mps = 0.0;     ///< ṙ, negative when closing
  bool valid = false;              ///< the sensor has a detection
};

/// Satellite navigation state in ECI (J2000).
struct NavState {
  std::int64_t utime_us = 0;  ///< time of validity [µs]
  Vec3 r_eci_m = Vec3::Zero();
  Vec3 v_eci_mps = Vec3::Zero();
  bool valid = false;
};

struct GuidanceInput {
  NavState nav;
  bool has_measurement = false;  ///< a new measurement arrived since the last step
  AnglesMeasurement meas;        ///< read only if has_measurement
  bool armed = false;            ///< operator/FDIR arm flag
};

struct ThrustCommand {
  std::int64_t utime_us = 0;          ///< time the command was computed [µs]
  GuidanceMode mode = GuidanceMode::kStandby;
  Vec3 dir_eci = Vec3::Zero();        ///< unit thrust direction (zero when accel is 0)
  double accel_mps2 = 0.0;            ///< commanded acceleration magnitude [m/s^2], ≥ 0
  CommandReason reason = CommandReason::kNoTrack;
};

struct GuidanceStatus {
  std::int64_t utime_us = 0;
  GuidanceMode mode = GuidanceMode::kStandby;
  CommandReason reason = CommandReason::kNoTrack;
  bool track_valid = false;
  double los_rate_radps = 0.0;        ///< ω_s estimate
  double los_rate_var_rad2ps2 = 0.0;  ///< its variance
  Vec3 e_theta_eci = Vec3::Zero();    ///< e_θ estimate (after the zenith flip)
  Mat3 e_theta_cov = Mat3::Zero();    ///< its covariance (first order)
  Vec3 los_unit_eci = Vec3::Zero();   ///< estimated LOS unit vector e_r
  bool zenith_flipped = false;
  bool fallback_direction = false;
  bool zem_valid = false;
  double zem_m = 0.0;                 ///< eq. 7, when range is known and closing
  bool tgo_valid = false;
  double tgo_s = 0.0;                 ///< eq. 12, when range is known and closing
  double dv_used_mps = 0.0;
  double burn_s = 0.0;
  long cycles = 0;
  long meas_accepted = 0;
  long meas_rejected = 0;             ///< beyond the chi-square gate
  long meas_invalid = 0;              ///< flagged valid but malformed, or flagged invalid
  long filter_reinits = 0;
};

struct GuidanceConfig {
  double max_accel_mps2 = 1.0;        ///< (0, 100]
  double dv_budget_mps = 100.0;       ///< (0, 1e4]
  double max_burn_s = 600.0;          ///< (0, 1e5]
  double stale_limit_s = 0.5;         ///< nav / measurement age limit (0, 60]
  double nominal_cycle_s = 0.02;      ///< guidance period, for the budget limits (0, 10]
  double rate_noise_threshold_radps = 0.0;  ///< ω_s at or below it ⇒ fallback [0, 1]
  double rate_noise_k_sigma = 3.0;    ///< also fallback while ω_s ≤ k σ(ω_s)  [0, 100]
  double zem_trigger_m = 1000.0;      ///< EVADE when range is known and ZEM < this (0, 1e8]
  int min_track_updates = 2;          ///< accepted updates before TRACKING [1, 1000]
  LosFilterConfig filter;

  /// Empty when valid; otherwise "GuidanceConfig.<field> = <value> outside <range>".
  std::string validate() const;
};

class GuidanceLaw {
 public:
  /// Throws std::invalid_argument with cfg.validate()'s message if the config is bad.
  explicit GuidanceLaw(const GuidanceConfig& cfg);

  /// Back to STANDBY with zero Δv/burn used and no track.
  void reset() noexcept;
  /// One guidance cycle at now_us. Allocation-free, never throws.
  ThrustCommand step(const GuidanceInput& in, std::int64_t now_us) noexcept;

  const GuidanceStatus& status() const noexcept { return status_; }
  const GuidanceConfig& config() const noexcept { return cfg_; }
  const LosRateFilter& filter() const noexcept { return filter_; }

 private:
  double to_s(std::int64_t utime_us) const noexcept {
    return 1e-6 * static_cast<double>(utime_us - time_origin_us_);
  }
  ThrustCommand hold(GuidanceMode mode, CommandReason reason, std::int64_t now_us) noexcept;

  GuidanceConfig cfg_;
  LosRateFilter filter_;
  GuidanceStatus status_;
  bool have_prev_step_ = false;
  std::int64_t prev_step_us_ = 0;
  double prev_accel_mps2_ = 0.0;
  bool have_time_origin_ = false;
  std::int64_t time_origin_us_ = 0;  // filter time 0 (keeps double time small and exact)
  bool coast_latched_ = false;
  CommandReason coast_reason_ = CommandReason::kPassedClosestApproach;
  bool evade_started_ = false;
  Vec3 u_at_evade_start_eci_ = Vec3::Zero();
  bool have_range_ = false;  // from the latest measurement carrying range
  std::int64_t range_utime_us_ = 0;
  double range_m_ = 0.0;
  double range_rate_mps_ = 0.0;
  bool was_closing_ = false;
  bool have_tca_estimate_ = false;
  std::int64_t tca_estimate_us_ = 0;
};

}  // namespace evade::guidance
