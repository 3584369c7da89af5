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
#include "evade/guidance/angles_measurement.hpp"
#include "evade/guidance/los_geometry.hpp"
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

/// Satellite navigation state in ECI (J2000).
struct NavState {
  std::int64_t utime_us = 0;  ///< time of validity [µs]
  Vec3 r_eci_m = Vec3::Zero();
  Vec3 v_eci_mps = Vec3::Zero();
  bool valid = false;
};

/// The verdict of a watchdog outside the law (the node's input watchdog, or FDIR): the law
/// commands SAFE while it is not kAlive. The law keeps its own stale checks besides.
enum class WatchdogVerdict : std::uint8_t {
  kAlive = 0,        ///< inputs are arriving
  kInputSilent = 1,  ///< no valid measurement for longer than stale_limit_s
};

struct GuidanceInput {
  NavState nav;
  bool has_measurement = false;  ///< a new measurement arrived since the last step
  AnglesMeasurement meas;        ///< read only if has_measurement
  bool armed = false;            ///< operator/FDIR arm flag
  WatchdogVerdict watchdog = WatchdogVerdict::kAlive;
};

struct ThrustCommand {
  std::int64_t utime_us = 0;          ///< time the command was computed [µs]
  GuidanceMode mode = GuidanceMode::kStandby;
  Vec3 u_eci = Vec3::Zero();          ///< unit thrust direction (zero when accel is 0)
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
  Mat3 e_theta_cov_eci = Mat3::Zero(); ///< its covariance (first order)
  Vec3 los_unit_eci = Vec3::Zero();   ///< estimated LOS unit vector e_r
  bool zenith_flipped = false;
  bool fallback_direction = false;
  bool zem_valid = false;
  double zem_m = 0.0;                 ///< eq. 7, when range is known and closing
  bool t_go_valid = false;
  double t_go_s = 0.0;                ///< eq. 12, when range is known and closing
  double dv_used_mps = 0.0;
  double burn_s = 0.0;
  std::int64_t cycles = 0;
  std::int64_t meas_accepted = 0;
  std::int64_t meas_rejected = 0;     ///< beyond the chi-square gate
  std::int64_t meas_invalid = 0;      ///< flagged valid but malformed, or flagged invalid
  std::int64_t filter_reinits = 0;
  std::int64_t watchdog_cycles = 0;   ///< cycles held SAFE by the watchdog verdict
};

/// Defaults here; unit, range and meaning of every field in guidance_params.hpp (the one
/// table every reader uses).
struct GuidanceConfig {
  double max_accel_mps2 = 1.0;
  double dv_budget_mps = 100.0;
  double max_burn_s = 600.0;
  double stale_limit_s = 0.5;
  double rate_hz = 50.0;
  double rate_noise_threshold_radps = 0.0;
  double rate_noise_k_sigma = 3.0;
  double zem_trigger_m = 1000.0;
  int min_track_updates = 2;
  bool armed = true;  ///< initial arm state of a run (the operator's evade_arm_t changes it)
  LosFilterConfig filter;

  /// The guidance period 1 / rate_hz [s] (the Δv and burn-time limits plan one cycle ahead).
  double cycle_s() const noexcept { return 1.0 / rate_hz; }
  /// Empty when valid; otherwise the table's error text for the first bad field
  /// ("key 'guidance.max_accel_mps2' = '500' is invalid: expected a number in (0, 100] m/s^2").
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

 private:
  /// Encounter state: what the law remembers of the current threat between cycles.
  struct Encounter {
    bool coast_latched = false;
    CommandReason coast_reason = CommandReason::kPassedClosestApproach;
    bool evade_started = false;
    Vec3 u_at_evade_start_eci = Vec3::Zero();
    bool raw_los_swung = false;  // a raw measurement's LOS is > 90° from u_at_evade_start
    bool have_range = false;     // from the latest measurement carrying range
    std::int64_t range_utime_us = 0;
    double range_m = 0.0;
    double range_rate_mps = 0.0;
    bool have_tca_estimate = false;
    std::int64_t tca_estimate_us = 0;
  };
  /// The LOS estimate at the cycle time.
  struct LosEstimate {
    LosFrame frame;
    double rate_radps = 0.0;
    double rate_var_rad2ps2 = 0.0;
    Mat3 e_theta_cov_eci = Mat3::Zero();
  };

  double to_s(std::int64_t utime_us) const noexcept {
    return 1e-6 * static_cast<double>(utime_us - time_origin_us_);
  }
  bool is_stale(std::int64_t utime_us, std::int64_t now_us) const noexcept;
  void account_previous_command(std::int64_t now_us) noexcept;
  CommandReason accept_measurement(const GuidanceInput& in, std::int64_t now_us) noexcept;
  void feed_filter(const AnglesMeasurement& m) noexcept;
  CommandReason check_navigation(const NavState& nav, std::int64_t now_us) const noexcept;
  CommandReason check_track(std::int64_t now_us) noexcept;
  bool estimate_los(const NavState& nav, std::int64_t now_us, LosEstimate* est) noexcept;
  void update_range_estimates(double los_rate_radps, std::int64_t now_us) noexcept;
  CommandReason coast_trigger(const LosEstimate& est, std::int64_t now_us) const noexcept;
  ThrustCommand evade(const LosEstimate& est, std::int64_t now_us) noexcept;
  ThrustCommand hold(GuidanceMode mode, CommandReason reason, std::int64_t now_us) noexcept;

  GuidanceConfig cfg_;
  std::int64_t stale_us_ = 0;
  LosRateFilter filter_;
  GuidanceStatus status_;
  bool have_prev_step_ = false;
  std::int64_t prev_step_us_ = 0;
  double prev_accel_mps2_ = 0.0;
  bool have_time_origin_ = false;
  std::int64_t time_origin_us_ = 0;  // filter time 0 (keeps double time small and exact)
  Encounter enc_;
};

}  // namespace evade::guidance
