// Kalman filter estimating the LOS direction and its rate from angle measurements
// (paper 000 sec. 3: "after continuous angle measurements, e_θ is obtained by filtering and
// algebra", eq. 15–18).
//
// State x = [u; u̇] (6), u the unit LOS vector and u̇ its rate, in the satellite-centred
// ECI-parallel frame of eq. 13 (see los_geometry.hpp). Working on u instead of (ε, β) keeps
// the filter regular at ε = ±90°.
// Process model: constant LOS rate. The mean is propagated exactly as a rotation of u and u̇
// about u × u̇ by ω_s Δt (keeps |u| = 1 and u·u̇ = 0); the covariance with the linear
// F = [[I, Δt I], [0, I]] and white LOS-acceleration noise of spectral density q
// (Q = q [[Δt³/3 I, Δt²/2 I], [Δt²/2 I, Δt I]]). After each step the covariance is projected
// on the tangent plane of u (the along-u components are fixed by |u| = 1, u·u̇ = 0).
// Measurement: the measured unit vector z (from ε, β) expressed in a tangent basis (t1, t2)
// of the predicted u: y = [t1·z, t2·z] ≈ angle residuals [rad], R = σ² I₂ (isotropic angle
// noise; an (ε, β) sensor with σ on each angle has ≤ σ across-track, so this is conservative).
// When the message carries angle rates, u̇_m = ε̇ y_s − β̇ cos ε z_s is added as two more rows
// y = [t1·(u̇_m − u̇), t2·(u̇_m − u̇)], R = σ_rate² I₂.
// Gating: the normalised innovation squared d² = yᵀ S⁻¹ y is compared with the chi-square
// gate for its 2 or 4 degrees of freedom; a measurement beyond it is rejected and counted.
// Gaps: without updates the covariance grows through Q; if the time since the last accepted
// update exceeds reinit_gap_s the filter re-initialises from the next measurement.
// Initialisation: u from the first measurement, u̇ from its rates if given (else 0) with
// variance init_rate_sigma_radps² per tangent axis.
//
// No heap allocation, no exceptions: fixed-size Eigen types only.
#pragma once

#include <cstdint>

#include "evade/core/state.hpp"
#include "evade/guidance/angles_measurement.hpp"

namespace evade::guidance {

struct LosFilterConfig {
  double process_noise_radps2 = 1e-2;  ///< sqrt of q, LOS-acceleration PSD [rad/s^2/sqrt(Hz)]
  double init_rate_sigma_radps = 0.05;  ///< initial 1σ of each tangent rate component [rad/s]
  double angle_sigma_floor_rad = 1e-9;  ///< lower bound on a message's angle σ [rad]
  double rate_sigma_floor_radps = 1e-10;  ///< lower bound on a message's rate σ [rad/s]
  double gate_chi2_2dof = 13.82;  ///< gate for angles only (chi-square 2 dof, p = 0.999)
  double gate_chi2_4dof = 18.47;  ///< gate for angles + rates (chi-square 4 dof, p = 0.999)
  double reinit_gap_s = 2.0;       ///< re-initialise after this long without an update [s]
  int max_consecutive_rejects = 5;  ///< re-initialise after this many rejections in a row
};

enum class LosUpdateResult : std::uint8_t {
  kInitialized = 0,  ///< first measurement (or after a re-initialisation)
  kAccepted = 1,
  kRejected = 2,     ///< beyond the chi-square gate
  kOutOfOrder = 3,   ///< older than the current estimate: ignored
};

class LosRateFilter {
 public:
  explicit LosRateFilter(const LosFilterConfig& cfg = {}) noexcept : cfg_(cfg) {}

  void reset() noexcept;
  /// Predicts to t_s (the measurement's time of validity in the filter's time base, if
  /// later) and updates with m's angles (and rates when m.has_rates; σ floored by the
  /// config). Re-initialises after a too-long gap. m must be well formed.
  LosUpdateResult update(const AnglesMeasurement& m, double t_s) noexcept;
  /// Predicted [u; u̇] and covariance at t_s (does not modify the filter). Requires
  /// initialized().
  void predict_to(double t_s, Vec3* u_eci, Vec3* u_dot_eci_ps, Mat6* cov) const noexcept;
  /// The same, with only the LOS-rate block of the covariance (3×3): what the guidance law
  /// needs each cycle, at a fraction of the cost of the full 6×6 prediction.
  void predict_rate_to(double t_s, Vec3* u_eci, Vec3* u_dot_eci_ps,
                       Mat3* rate_cov) const noexcept;

  bool initialized() const noexcept { return initialized_; }
  double time_s() const noexcept { return t_s_; }
  double last_update_s() const noexcept { return t_last_update_s_; }
  const Vec3& u_eci() const noexcept { return u_; }
  const Vec3& u_dot_eci_ps() const noexcept { return u_dot_; }
  const Mat6& covariance() const noexcept { return P_; }
  /// Normalised innovation squared of the last processed measurement.
  double last_nis() const noexcept { return last_nis_; }
  /// Unit LOS of the last measurement given to update() (whatever became of it).
  const Vec3& last_measured_u_eci() const noexcept { return z_; }
  std::int64_t accepted() const noexcept { return accepted_; }
  std::int64_t rejected() const noexcept { return rejected_; }
  std::int64_t reinitializations() const noexcept { return reinits_; }
  int updates_since_init() const noexcept { return updates_since_init_; }
  const LosFilterConfig& config() const noexcept { return cfg_; }

  /// LOS rate ω_s = |u̇| and its variance (first order: ê_θᵀ P_u̇u̇ ê_θ) [rad/s], [rad²/s²].
  double los_rate_radps() const noexcept;
  double los_rate_variance() const noexcept;
  /// Covariance of ê_θ = u̇/|u̇| (first order: J P_u̇u̇ Jᵀ, J = (I − ê_θ ê_θᵀ)/ω_s). Zero
  /// matrix if ω_s = 0.
  Mat3 e_theta_covariance() const noexcept;
  /// The same two for any (u̇, P_u̇u̇), e.g. a prediction (the members apply them to the
  /// filter's own state). With ω_s = 0 the variance is the mean per tangent axis.
  static double los_rate_variance(const Vec3& u_dot, const Mat3& rate_cov) noexcept;
  static Mat3 e_theta_covariance(const Vec3& u_dot, const Mat3& rate_cov) noexcept;

 private:
  void initialize(const AnglesMeasurement& m, double t_s) noexcept;
  bool correct(const AnglesMeasurement& m, const Vec3& u, const Vec3& ud, Vec6* x,
               Mat6* P) noexcept;
  LosUpdateResult on_rejected(const AnglesMeasurement& m, double t_s, const Vec3& ud) noexcept;
  static void propagate_mean(const Vec3& u, const Vec3& u_dot, double dt_s, Vec3* u_out,
                             Vec3* u_dot_out) noexcept;
  void propagate_cov(double dt_s, Mat6* cov) const noexcept;

  LosFilterConfig cfg_;
  bool initialized_ = false;
  double t_s_ = 0.0;
  double t_last_update_s_ = 0.0;
  Vec3 u_ = Vec3::UnitX();
  Vec3 u_dot_ = Vec3::Zero();
  Mat6 P_ = Mat6::Zero();
  double last_nis_ = 0.0;
  Vec3 z_ = Vec3::UnitX();  // unit LOS of the last measurement
  Vec3 zd_ = Vec3::Zero();  // its rate from the measured angle rates (when it has them)
  std::int64_t accepted_ = 0;
  std::int64_t rejected_ = 0;
  std::int64_t reinits_ = 0;
  int updates_since_init_ = 0;
  int consecutive_rejects_ = 0;
};

}  // namespace evade::guidance
