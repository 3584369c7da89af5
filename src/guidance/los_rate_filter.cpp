// Kalman filter on the unit LOS vector and its rate (paper 000 sec. 3, eq. 13–18: e_θ from
// filtered angle measurements). Model, measurement, gating and gap handling are described in
// include/evade/guidance/los_rate_filter.hpp. Fixed-size Eigen only: no heap allocation.
#include "evade/guidance/los_rate_filter.hpp"

#include <algorithm>
#include <cmath>

#include "evade/guidance/los_geometry.hpp"

namespace evade::guidance {

namespace {

using Mat26 = Eigen::Matrix<double, 2, 6>;
using Mat46 = Eigen::Matrix<double, 4, 6>;

// Orthonormal basis (t1, t2) of the plane perpendicular to the unit vector u.
void tangent_basis(const Vec3& u, Vec3* t1, Vec3* t2) noexcept {
  // Cross with the coordinate axis least aligned with u: well conditioned everywhere.
  const Vec3 a = u.cwiseAbs();
  Vec3 axis = Vec3::UnitX();
  if (a.y() <= a.x() && a.y() <= a.z()) {
    axis = Vec3::UnitY();
  } else if (a.z() <= a.x() && a.z() <= a.y()) {
    axis = Vec3::UnitZ();
  }
  *t1 = u.cross(axis).normalized();
  *t2 = u.cross(*t1);
}

Mat3 tangent_projector(const Vec3& u) noexcept { return Mat3::Identity() - u * u.transpose(); }

// P ← T P Tᵀ, T = diag(Π, Π): removes the along-u components (fixed by the constraints).
void project_covariance(const Vec3& u, Mat6* P) noexcept {
  Mat6 T = Mat6::Zero();
  const Mat3 pi = tangent_projector(u);
  T.topLeftCorner<3, 3>() = pi;
  T.bottomRightCorner<3, 3>() = pi;
  const Mat6 tmp = T * (*P) * T.transpose();
  *P = 0.5 * (tmp + tmp.transpose());
}

// Kalman update with N measurement rows; returns false (no change) if gated out.
template <int N>
bool kalman_update(const Eigen::Matrix<double, N, 6>& H, const Eigen::Matrix<double, N, 1>& y,
                   const Eigen::Matrix<double, N, N>& R, double gate, Vec6* x, Mat6* P,
                   double* nis) noexcept {
  using MatN = Eigen::Matrix<double, N, N>;
  const MatN S = H * (*P) * H.transpose() + R;
  const Eigen::LDLT<MatN> ldlt(S);
  if (ldlt.info() != Eigen::Success) {
    *nis = INFINITY;
    return false;
  }
  *nis = y.dot(ldlt.solve(y));
  if (!(*nis <= gate)) return false;
  // K = P Hᵀ S⁻¹ (computed as (S⁻¹ H P)ᵀ, S symmetric).
  const Eigen::Matrix<double, 6, N> K = ldlt.solve(H * (*P)).transpose();
  *x += K * y;
  const Mat6 ikh = Mat6::Identity() - K * H;
  const Mat6 joseph = ikh * (*P) * ikh.transpose() + K * R * K.transpose();
  *P = 0.5 * (joseph + joseph.transpose());
  return true;
}

}  // namespace

void LosRateFilter::reset() noexcept {
  const LosFilterConfig cfg = cfg_;
  *this = LosRateFilter(cfg);
}

void LosRateFilter::initialize(const LosMeasurement& m) noexcept {
  u_ = los_unit_from_angles(m.elevation_rad, m.azimuth_rad);
  const Mat3 pi = tangent_projector(u_);
  const double sa = std::max(m.sigma_rad, cfg_.angle_sigma_floor_rad);
  double sr = cfg_.init_rate_sigma_radps;
  if (m.has_rates) {
    u_dot_ = pi * los_unit_rate_from_angle_rates(m.elevation_rad, m.azimuth_rad,
                                                 m.elevation_rate_radps, m.azimuth_rate_radps);
    sr = std::max(m.rate_sigma_radps, cfg_.rate_sigma_floor_radps);
  } else {
    u_dot_ = Vec3::Zero();
  }
  P_ = Mat6::Zero();
  P_.topLeftCorner<3, 3>() = sa * sa * pi;
  P_.bottomRightCorner<3, 3>() = sr * sr * pi;
  if (initialized_) ++reinits_;
  initialized_ = true;
  t_s_ = m.t_s;
  t_last_update_s_ = m.t_s;
  updates_since_init_ = 1;
  consecutive_rejects_ = 0;
  last_nis_ = 0.0;
  last_dof_ = 0;
}

void LosRateFilter::propagate_mean(const Vec3& u, const Vec3& u_dot, double dt_s, Vec3* u_out,
                                   Vec3* u_dot_out) noexcept {
  const double w = u_dot.norm();
  const double phi = w * dt_s;
  if (!(phi > 1e-9)) {  // (near) zero rotation: first order is exact to rounding
    const Vec3 un = (u + u_dot * dt_s).normalized();
    *u_out = un;
    *u_dot_out = u_dot - un.dot(u_dot) * un;
    return;
  }
  // Constant-rate great-circle motion: rotation by φ = ω_s Δt in the plane of u and u̇.
  const double c = std::cos(phi);
  const double s = std::sin(phi);
  *u_out = c * u + (s / w) * u_dot;
  *u_dot_out = c * u_dot - (s * w) * u;
}

void LosRateFilter::propagate_cov(const Vec3& u_new, double dt_s, Mat6* cov) const noexcept {
  Mat6 F = Mat6::Identity();
  F.topRightCorner<3, 3>() = dt_s * Mat3::Identity();
  const double q = cfg_.process_noise_radps2 * cfg_.process_noise_radps2;
  Mat6 Q = Mat6::Zero();
  Q.topLeftCorner<3, 3>() = (q * dt_s * dt_s * dt_s / 3.0) * Mat3::Identity();
  Q.topRightCorner<3, 3>() = (q * dt_s * dt_s / 2.0) * Mat3::Identity();
  Q.bottomLeftCorner<3, 3>() = (q * dt_s * dt_s / 2.0) * Mat3::Identity();
  Q.bottomRightCorner<3, 3>() = (q * dt_s) * Mat3::Identity();
  *cov = F * P_ * F.transpose() + Q;
  project_covariance(u_new, cov);
}

void LosRateFilter::predict_to(double t_s, Vec3* u_eci, Vec3* u_dot_eci_ps,
                               Mat6* cov) const noexcept {
  const double dt = (t_s > t_s_) ? (t_s - t_s_) : 0.0;
  Vec3 u;
  Vec3 ud;
  propagate_mean(u_, u_dot_, dt, &u, &ud);
  if (cov != nullptr) propagate_cov(u, dt, cov);
  if (u_eci != nullptr) *u_eci = u;
  if (u_dot_eci_ps != nullptr) *u_dot_eci_ps = ud;
}

LosUpdateResult LosRateFilter::update(const LosMeasurement& m) noexcept {
  if (!initialized_) {
    initialize(m);
    return LosUpdateResult::kInitialized;
  }
  if (m.t_s < t_s_) return LosUpdateResult::kOutOfOrder;
  if (m.t_s - t_last_update_s_ > cfg_.reinit_gap_s) {  // too long without an update
    initialize(m);
    return LosUpdateResult::kInitialized;
  }
  Vec3 u;
  Vec3 ud;
  Mat6 P;
  predict_to(m.t_s, &u, &ud, &P);
  Vec3 t1;
  Vec3 t2;
  tangent_basis(u, &t1, &t2);
  const Vec3 z = los_unit_from_angles(m.elevation_rad, m.azimuth_rad);
  const double sa = std::max(m.sigma_rad, cfg_.angle_sigma_floor_rad);
  Vec6 x;
  x << u, ud;
  bool ok = false;
  if (z.dot(u) > 0.0) {  // a measurement more than 90° off is an outlier whatever P says
    if (m.has_rates) {
      const Vec3 ud_m = los_unit_rate_from_angle_rates(m.elevation_rad, m.azimuth_rad,
                                                       m.elevation_rate_radps,
                                                       m.azimuth_rate_radps);
      const double sr = std::max(m.rate_sigma_radps, cfg_.rate_sigma_floor_radps);
      Mat46 H = Mat46::Zero();
      H.block<1, 3>(0, 0) = t1.transpose();
      H.block<1, 3>(1, 0) = t2.transpose();
      H.block<1, 3>(2, 3) = t1.transpose();
      H.block<1, 3>(3, 3) = t2.transpose();
      Eigen::Matrix<double, 4, 1> y;
      y << t1.dot(z), t2.dot(z), t1.dot(ud_m - ud), t2.dot(ud_m - ud);
      Eigen::Matrix4d R = Eigen::Matrix4d::Zero();
      R(0, 0) = R(1, 1) = sa * sa;
      R(2, 2) = R(3, 3) = sr * sr;
      ok = kalman_update<4>(H, y, R, cfg_.gate_chi2_4dof, &x, &P, &last_nis_);
      last_dof_ = 4;
    } else {
      Mat26 H = Mat26::Zero();
      H.block<1, 3>(0, 0) = t1.transpose();
      H.block<1, 3>(1, 0) = t2.transpose();
      Eigen::Vector2d y(t1.dot(z), t2.dot(z));
      const Eigen::Matrix2d R = sa * sa * Eigen::Matrix2d::Identity();
      ok = kalman_update<2>(H, y, R, cfg_.gate_chi2_2dof, &x, &P, &last_nis_);
      last_dof_ = 2;
    }
  } else {
    last_nis_ = INFINITY;
    last_dof_ = m.has_rates ? 4 : 2;
  }
  if (!ok) {
    ++rejected_;
    ++consecutive_rejects_;
    if (consecutive_rejects_ >= cfg_.max_consecutive_rejects) {
      // The track no longer explains the data (typically the LOS accelerating at the
      // encounter faster than the constant-rate model allows): restart from this measurement.
      // Without measured rates, keep the predicted rate as the prior (a rate is known to
      // exist; zero would be worse) with a 1σ as large as the rate itself.
      initialize(m);
      if (!m.has_rates) {
        const Mat3 pi = tangent_projector(u_);
        u_dot_ = pi * ud;
        const double sr = std::max(cfg_.init_rate_sigma_radps, u_dot_.norm());
        P_.bottomRightCorner<3, 3>() = sr * sr * pi;
      }
      return LosUpdateResult::kInitialized;
    }
    return LosUpdateResult::kRejected;
  }
  u_ = x.head<3>().normalized();
  u_dot_ = x.tail<3>() - u_.dot(x.tail<3>()) * u_;
  P_ = P;
  project_covariance(u_, &P_);
  t_s_ = m.t_s;
  t_last_update_s_ = m.t_s;
  ++accepted_;
  ++updates_since_init_;
  consecutive_rejects_ = 0;
  return LosUpdateResult::kAccepted;
}

double LosRateFilter::los_rate_radps() const noexcept { return u_dot_.norm(); }

double LosRateFilter::los_rate_variance() const noexcept {
  const double w = u_dot_.norm();
  const Mat3 Pr = P_.bottomRightCorner<3, 3>();
  if (!(w > 0.0)) return 0.5 * Pr.trace();  // mean variance per tangent axis
  const Vec3 e = u_dot_ / w;
  return e.dot(Pr * e);
}

Mat3 LosRateFilter::e_theta_covariance() const noexcept {
  const double w = u_dot_.norm();
  if (!(w > 0.0)) return Mat3::Zero();
  const Vec3 e = u_dot_ / w;
  const Mat3 J = (Mat3::Identity() - e * e.transpose()) / w;
  return J * P_.bottomRightCorner<3, 3>() * J.transpose();
}

}  // namespace evade::guidance
