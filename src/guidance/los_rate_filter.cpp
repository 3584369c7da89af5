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

// Π A Π for Π = I − u uᵀ, as rank-one corrections (A − u bᵀ − a uᵀ + s u uᵀ with a = A u,
// b = Aᵀ u, s = uᵀ A u): the same matrix as the triple product at a tenth of the cost.
Mat3 project_block(const Vec3& u, const Mat3& A) noexcept {
  const Vec3 a = A * u;
  const Vec3 b = A.transpose() * u;
  const double s = u.dot(a);
  return A - u * b.transpose() - a * u.transpose() + (s * u) * u.transpose();
}

// P ← T P Tᵀ, T = diag(Π, Π): removes the along-u components (fixed by the constraints).
void project_covariance(const Vec3& u, Mat6* P) noexcept {
  const Mat3 paa = project_block(u, P->topLeftCorner<3, 3>());
  const Mat3 par = project_block(u, P->topRightCorner<3, 3>());
  const Mat3 prr = project_block(u, P->bottomRightCorner<3, 3>());
  P->topLeftCorner<3, 3>() = 0.5 * (paa + paa.transpose());
  P->topRightCorner<3, 3>() = par;
  P->bottomLeftCorner<3, 3>() = par.transpose();
  P->bottomRightCorner<3, 3>() = 0.5 * (prr + prr.transpose());
}

// Kalman update with N measurement rows; returns false (no change) if gated out.
template <int N>
bool kalman_update(const Eigen::Matrix<double, N, 6>& H, const Eigen::Matrix<double, N, 1>& y,
                   const Eigen::Matrix<double, N, N>& R, double gate, Vec6* x, Mat6* P,
                   double* nis) noexcept {
  using MatN = Eigen::Matrix<double, N, N>;
  const Eigen::Matrix<double, N, 6> hp = H * (*P);
  const MatN S = hp * H.transpose() + R;
  const Eigen::LDLT<MatN> ldlt(S);
  if (ldlt.info() != Eigen::Success) {
    *nis = INFINITY;
    return false;
  }
  *nis = y.dot(ldlt.solve(y));
  if (!(*nis <= gate)) return false;
  // K = P Hᵀ S⁻¹ = (S⁻¹ H P)ᵀ (S symmetric). Joseph form, expanded so that no 6×6×6
  // product is needed: (I − KH) P (I − KH)ᵀ + K R Kᵀ = P − K(HP) − (K(HP))ᵀ + K S Kᵀ (valid
  // for any gain, like the factored form).
  const Eigen::Matrix<double, 6, N> K = ldlt.solve(hp).transpose();
  *x += K * y;
  const Mat6 khp = K * hp;
  const Mat6 p_new = *P - khp - khp.transpose() + K * (S * K.transpose());
  *P = 0.5 * (p_new + p_new.transpose());
  return true;
}

}  // namespace

void LosRateFilter::reset() noexcept {
  const LosFilterConfig cfg = cfg_;
  *this = LosRateFilter(cfg);
}

void LosRateFilter::initialize(const AnglesMeasurement& m, double t_s) noexcept {
  u_ = los_unit_from_angles(m.elevation_rad, m.azimuth_rad);
  const Mat3 pi = tangent_projector(u_);
  const double sa = std::max(m.sigma_angle_rad, cfg_.angle_sigma_floor_rad);
  double sr = cfg_.init_rate_sigma_radps;
  if (m.has_rates) {
    u_dot_ = pi * los_unit_rate_from_angle_rates(m.elevation_rad, m.azimuth_rad,
                                                 m.elevation_rate_radps, m.azimuth_rate_radps);
    sr = std::max(m.sigma_rate_radps, cfg_.rate_sigma_floor_radps);
  } else {
    u_dot_ = Vec3::Zero();
  }
  P_ = Mat6::Zero();
  P_.topLeftCorner<3, 3>() = sa * sa * pi;
  P_.bottomRightCorner<3, 3>() = sr * sr * pi;
  if (initialized_) ++reinits_;
  initialized_ = true;
  t_s_ = t_s;
  t_last_update_s_ = t_s;
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

// F P Fᵀ + Q with F = [[I, Δt I], [0, I]], by blocks (F's identity structure makes every
// block a sum of 3×3 terms), then projected on the tangent plane of u_new.
void LosRateFilter::propagate_cov(const Vec3& u_new, double dt_s, Mat6* cov) const noexcept {
  const double q = cfg_.process_noise_radps2 * cfg_.process_noise_radps2;
  const Mat3 paa = P_.topLeftCorner<3, 3>();
  const Mat3 par = P_.topRightCorner<3, 3>();
  const Mat3 prr = P_.bottomRightCorner<3, 3>();
  const Mat3 par_new = par + dt_s * prr;
  Mat3 paa_new = paa + dt_s * (par + par.transpose()) + (dt_s * dt_s) * prr;
  paa_new.diagonal().array() += q * dt_s * dt_s * dt_s / 3.0;
  Mat3 prr_new = prr;
  prr_new.diagonal().array() += q * dt_s;
  Mat3 par_q = par_new;
  par_q.diagonal().array() += q * dt_s * dt_s / 2.0;
  cov->topLeftCorner<3, 3>() = paa_new;
  cov->topRightCorner<3, 3>() = par_q;
  cov->bottomLeftCorner<3, 3>() = par_q.transpose();
  cov->bottomRightCorner<3, 3>() = prr_new;
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

void LosRateFilter::predict_rate_to(double t_s, Vec3* u_eci, Vec3* u_dot_eci_ps,
                                    Mat3* rate_cov) const noexcept {
  const double dt = (t_s > t_s_) ? (t_s - t_s_) : 0.0;
  propagate_mean(u_, u_dot_, dt, u_eci, u_dot_eci_ps);
  Mat3 prr = P_.bottomRightCorner<3, 3>();  // F leaves the rate block as it is
  prr.diagonal().array() += cfg_.process_noise_radps2 * cfg_.process_noise_radps2 * dt;
  const Mat3 p = project_block(*u_eci, prr);
  *rate_cov = 0.5 * (p + p.transpose());
}

// The Kalman correction of x = [u; u̇] (predicted at the measurement time) with the angles,
// and the rates when the message has them. False when gated out (x, P unchanged).
bool LosRateFilter::correct(const AnglesMeasurement& m, const Vec3& u, const Vec3& ud, Vec6* x,
                            Mat6* P) noexcept {
  const Vec3 z = los_unit_from_angles(m.elevation_rad, m.azimuth_rad);
  last_dof_ = m.has_rates ? 4 : 2;
  if (!(z.dot(u) > 0.0)) {  // a measurement more than 90° off is an outlier whatever P says
    last_nis_ = INFINITY;
    return false;
  }
  Vec3 t1;
  Vec3 t2;
  tangent_basis(u, &t1, &t2);
  const double sa = std::max(m.sigma_angle_rad, cfg_.angle_sigma_floor_rad);
  if (!m.has_rates) {
    Mat26 H = Mat26::Zero();
    H.block<1, 3>(0, 0) = t1.transpose();
    H.block<1, 3>(1, 0) = t2.transpose();
    const Eigen::Vector2d y(t1.dot(z), t2.dot(z));
    const Eigen::Matrix2d R = sa * sa * Eigen::Matrix2d::Identity();
    return kalman_update<2>(H, y, R, cfg_.gate_chi2_2dof, x, P, &last_nis_);
  }
  const Vec3 ud_m = los_unit_rate_from_angle_rates(m.elevation_rad, m.azimuth_rad,
                                                   m.elevation_rate_radps, m.azimuth_rate_radps);
  const double sr = std::max(m.sigma_rate_radps, cfg_.rate_sigma_floor_radps);
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
  return kalman_update<4>(H, y, R, cfg_.gate_chi2_4dof, x, P, &last_nis_);
}

LosUpdateResult LosRateFilter::on_rejected(const AnglesMeasurement& m, double t_s,
                                           const Vec3& ud) noexcept {
  ++rejected_;
  ++consecutive_rejects_;
  if (consecutive_rejects_ < cfg_.max_consecutive_rejects) return LosUpdateResult::kRejected;
  // The track no longer explains the data (typically the LOS accelerating at the encounter
  // faster than the constant-rate model allows): restart from this measurement. Without
  // measured rates, keep the predicted rate as the prior (a rate is known to exist; zero
  // would be worse) with a 1σ as large as the rate itself.
  initialize(m, t_s);
  if (!m.has_rates) {
    const Mat3 pi = tangent_projector(u_);
    u_dot_ = pi * ud;
    const double sr = std::max(cfg_.init_rate_sigma_radps, u_dot_.norm());
    P_.bottomRightCorner<3, 3>() = sr * sr * pi;
  }
  return LosUpdateResult::kInitialized;
}

LosUpdateResult LosRateFilter::update(const AnglesMeasurement& m, double t_s) noexcept {
  if (!initialized_ || t_s - t_last_update_s_ > cfg_.reinit_gap_s) {
    initialize(m, t_s);  // first measurement, or too long without an update
    return LosUpdateResult::kInitialized;
  }
  if (t_s < t_s_) return LosUpdateResult::kOutOfOrder;
  Vec3 u;
  Vec3 ud;
  Mat6 P;
  predict_to(t_s, &u, &ud, &P);
  Vec6 x;
  x << u, ud;
  if (!correct(m, u, ud, &x, &P)) return on_rejected(m, t_s, ud);
  u_ = x.head<3>().normalized();
  u_dot_ = x.tail<3>() - u_.dot(x.tail<3>()) * u_;
  P_ = P;
  project_covariance(u_, &P_);
  t_s_ = t_s;
  t_last_update_s_ = t_s;
  ++accepted_;
  ++updates_since_init_;
  consecutive_rejects_ = 0;
  return LosUpdateResult::kAccepted;
}

double LosRateFilter::los_rate_radps() const noexcept { return u_dot_.norm(); }

double LosRateFilter::los_rate_variance(const Vec3& u_dot, const Mat3& rate_cov) noexcept {
  const double w = u_dot.norm();
  if (!(w > 0.0)) return 0.5 * rate_cov.trace();  // mean variance per tangent axis
  const Vec3 e = u_dot / w;
  return e.dot(rate_cov * e);
}

Mat3 LosRateFilter::e_theta_covariance(const Vec3& u_dot, const Mat3& rate_cov) noexcept {
  const double w = u_dot.norm();
  if (!(w > 0.0)) return Mat3::Zero();
  const Vec3 e = u_dot / w;
  const Mat3 J = (Mat3::Identity() - e * e.transpose()) / w;
  return J * rate_cov * J.transpose();
}

double LosRateFilter::los_rate_variance() const noexcept {
  return los_rate_variance(u_dot_, P_.bottomRightCorner<3, 3>());
}

Mat3 LosRateFilter::e_theta_covariance() const noexcept {
  return e_theta_covariance(u_dot_, P_.bottomRightCorner<3, 3>());
}

}  // namespace evade::guidance
