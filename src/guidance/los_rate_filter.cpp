// Kalman filter on the unit LOS vector and its rate (paper 000 sec. 3, eq. 13–18: e_θ from
// filtered angle measurements). Model, measurement, gating and gap handling are described in
// include/evade/guidance/los_rate_filter.hpp. Fixed-size Eigen only: no heap allocation.
#include "evade/guidance/los_rate_filter.hpp"

#include <algorithm>
#include <cmath>

#include "evade/guidance/los_geometry.hpp"

namespace evade::guidance {

namespace {


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

// Π A Π for Π = I − u uᵀ (u a unit vector), as rank-one corrections: with a = A u,
// c = Aᵀ u − (uᵀ A u) u, Π A Π = A − a uᵀ − u cᵀ. The same matrix as the triple product at a
// tenth of the cost; written out element by element (3×3, fixed).
inline Mat3 project_block(const Vec3& u, const Mat3& A) noexcept {
  double a[3];
  double b[3];
  for (int i = 0; i < 3; ++i) {
    a[i] = A(i, 0) * u(0) + A(i, 1) * u(1) + A(i, 2) * u(2);
    b[i] = A(0, i) * u(0) + A(1, i) * u(1) + A(2, i) * u(2);
  }
  const double s = u(0) * a[0] + u(1) * a[1] + u(2) * a[2];
  Mat3 out;
  for (int j = 0; j < 3; ++j) {
    const double cj = b[j] - s * u(j);
    for (int i = 0; i < 3; ++i) out(i, j) = A(i, j) - a[i] * u(j) - u(i) * cj;
  }
  return out;
}

// cos φ and sin φ; below 0.01 rad by their Taylor series to φ⁸ / φ⁹ (truncation < 3e-21,
// far below double rounding), which avoids the library call on every guidance cycle.
void cos_sin(double phi, double* c, double* s) noexcept {
  if (std::abs(phi) >= 0.01) {
    *c = std::cos(phi);
    *s = std::sin(phi);
    return;
  }
  const double p2 = phi * phi;
  *c = 1.0 - p2 / 2.0 * (1.0 - p2 / 12.0 * (1.0 - p2 / 30.0 * (1.0 - p2 / 56.0)));
  *s = phi * (1.0 - p2 / 6.0 * (1.0 - p2 / 20.0 * (1.0 - p2 / 42.0 * (1.0 - p2 / 72.0))));
}

// The block of P at (r0, c0) ← Π block Π, in place (the same rank-one form as above).
void project_block_in_place(const Vec3& u, int r0, int c0, Mat6* P) noexcept {
  Mat6& p = *P;
  double a[3];
  double b[3];
  for (int i = 0; i < 3; ++i) {
    a[i] = p(r0 + i, c0) * u(0) + p(r0 + i, c0 + 1) * u(1) + p(r0 + i, c0 + 2) * u(2);
    b[i] = p(r0, c0 + i) * u(0) + p(r0 + 1, c0 + i) * u(1) + p(r0 + 2, c0 + i) * u(2);
  }
  const double s = u(0) * a[0] + u(1) * a[1] + u(2) * a[2];
  for (int j = 0; j < 3; ++j) {
    const double cj = b[j] - s * u(j);
    for (int i = 0; i < 3; ++i) p(r0 + i, c0 + j) -= a[i] * u(j) + u(i) * cj;
  }
}

// P ← T P Tᵀ, T = diag(Π, Π): removes the along-u components (fixed by the constraints),
// and makes P exactly symmetric.
void project_covariance(const Vec3& u, Mat6* P) noexcept {
  project_block_in_place(u, 0, 0, P);
  project_block_in_place(u, 0, 3, P);
  project_block_in_place(u, 3, 3, P);
  Mat6& p = *P;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) p(3 + i, j) = p(j, 3 + i);
    for (int j = i + 1; j < 3; ++j) {
      p(i, j) = p(j, i) = 0.5 * (p(i, j) + p(j, i));
      p(3 + i, 3 + j) = p(3 + j, 3 + i) = 0.5 * (p(3 + i, 3 + j) + p(3 + j, 3 + i));
    }
  }
}

// Kalman update with N (2 or 4) measurement rows; returns false (no change) if gated out.
// S is symmetric positive definite (R > 0 is added) and at most 4×4, so its inverse is
// formed directly (Eigen's closed form for N ≤ 4), which costs a fraction of a factorisation
// followed by six back-substitutions; a non-finite inverse rejects the measurement.
// H's rows are t1ᵀ, t2ᵀ on u (and, for N = 4, on u̇): HP and HPHᵀ are formed from those
// rows directly instead of multiplying through H's zeros.
template <int N>
bool kalman_update(const Vec3& t1, const Vec3& t2, const Eigen::Matrix<double, N, 1>& y,
                   const Eigen::Matrix<double, N, N>& R, double gate, Vec6* x, Mat6* P,
                   double* nis) noexcept {
  using MatN = Eigen::Matrix<double, N, N>;
  const Vec3* t[2] = {&t1, &t2};
  Eigen::Matrix<double, N, 6> hp;
  for (int i = 0; i < N; ++i) {
    const int block = 3 * (i / 2);  // rows 0, 1: angles on u; rows 2, 3: rates on u̇
    hp.row(i) = t[i % 2]->transpose() * P->template middleRows<3>(block);
  }
  MatN S = R;
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) S(i, j) += hp.row(i).template segment<3>(3 * (j / 2)).dot(*t[j % 2]);
  }
  const MatN s_inv = S.inverse();
  if (!s_inv.allFinite()) {
    *nis = INFINITY;
    return false;
  }
  *nis = y.dot(s_inv * y);
  if (!(*nis <= gate)) return false;
  // K = P Hᵀ S⁻¹ = (HP)ᵀ S⁻¹, and P⁺ = P − K(HP), symmetrised. With this (optimal) gain the
  // Joseph form (I − KH)P(I − KH)ᵀ + KRKᵀ expands to exactly P − K(HP) (its K S Kᵀ term
  // equals (K(HP))ᵀ); the caller projects P⁺ on the tangent plane, which keeps it positive
  // semi-definite there.
  const Eigen::Matrix<double, 6, N> K = hp.transpose() * s_inv;
  *x += K * y;
  const Mat6 p_new = *P - K * hp;
  *P = 0.5 * (p_new + p_new.transpose());
  return true;
}

}  // namespace

void LosRateFilter::reset() noexcept {
  const LosFilterConfig cfg = cfg_;
  *this = LosRateFilter(cfg);
}

void LosRateFilter::initialize(const AnglesMeasurement& m, double t_s) noexcept {
  u_ = z_;
  const Mat3 pi = tangent_projector(u_);
  const double sa = std::max(m.sigma_angle_rad, cfg_.angle_sigma_floor_rad);
  double sr = cfg_.init_rate_sigma_radps;
  if (m.has_rates) {
    u_dot_ = pi * zd_;
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
  double c = 0.0;
  double s = 0.0;
  cos_sin(phi, &c, &s);
  *u_out = c * u + (s / w) * u_dot;
  *u_dot_out = c * u_dot - (s * w) * u;
}

// F P Fᵀ + Q with F = [[I, Δt I], [0, I]], by blocks (F's identity structure makes every
// block a sum of 3×3 terms). Not yet projected on the tangent plane of the new u.
void LosRateFilter::propagate_cov(double dt_s, Mat6* cov) const noexcept {
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
}

void LosRateFilter::predict_to(double t_s, Vec3* u_eci, Vec3* u_dot_eci_ps,
                               Mat6* cov) const noexcept {
  const double dt = (t_s > t_s_) ? (t_s - t_s_) : 0.0;
  Vec3 u;
  Vec3 ud;
  propagate_mean(u_, u_dot_, dt, &u, &ud);
  if (cov != nullptr) {
    propagate_cov(dt, cov);
    project_covariance(u, cov);
  }
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
  const Vec3& z = z_;
  if (!(z.dot(u) > 0.0)) {  // a measurement more than 90° off is an outlier whatever P says
    last_nis_ = INFINITY;
    return false;
  }
  Vec3 t1;
  Vec3 t2;
  tangent_basis(u, &t1, &t2);
  const double sa = std::max(m.sigma_angle_rad, cfg_.angle_sigma_floor_rad);
  if (!m.has_rates) {
    const Eigen::Vector2d y(t1.dot(z), t2.dot(z));
    const Eigen::Matrix2d R = sa * sa * Eigen::Matrix2d::Identity();
    return kalman_update<2>(t1, t2, y, R, cfg_.gate_chi2_2dof, x, P, &last_nis_);
  }
  const Vec3& ud_m = zd_;
  const double sr = std::max(m.sigma_rate_radps, cfg_.rate_sigma_floor_radps);
  Eigen::Matrix<double, 4, 1> y;
  y << t1.dot(z), t2.dot(z), t1.dot(ud_m - ud), t2.dot(ud_m - ud);
  Eigen::Matrix4d R = Eigen::Matrix4d::Zero();
  R(0, 0) = R(1, 1) = sa * sa;
  R(2, 2) = R(3, 3) = sr * sr;
  return kalman_update<4>(t1, t2, y, R, cfg_.gate_chi2_4dof, x, P, &last_nis_);
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
  if (m.has_rates) {
    los_unit_and_rate_from_angles(m.elevation_rad, m.azimuth_rad, m.elevation_rate_radps,
                                  m.azimuth_rate_radps, &z_, &zd_);
  } else {
    z_ = los_unit_from_angles(m.elevation_rad, m.azimuth_rad);
  }
  if (!initialized_ || t_s - t_last_update_s_ > cfg_.reinit_gap_s) {
    initialize(m, t_s);  // first measurement, or too long without an update
    return LosUpdateResult::kInitialized;
  }
  if (t_s < t_s_) return LosUpdateResult::kOutOfOrder;
  // Prediction to t_s. The covariance is projected on the tangent plane once, after the
  // correction, not also before it: H's rows lie in the tangent plane, so S = HPHᵀ and the
  // tangent rows of K are the same either way; K's along-u rows only move x along u, which
  // the normalisation of u and the projection of u̇ below remove (to first order in the
  // innovation).
  Vec3 u;
  Vec3 ud;
  Mat6 P;
  propagate_mean(u_, u_dot_, t_s - t_s_, &u, &ud);
  propagate_cov(t_s - t_s_, &P);
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

// J P Jᵀ with J = (I − e eᵀ)/ω_s symmetric: the projection Π_e P Π_e divided by ω_s².
Mat3 LosRateFilter::e_theta_covariance(const Vec3& u_dot, const Mat3& rate_cov) noexcept {
  const double w = u_dot.norm();
  if (!(w > 0.0)) return Mat3::Zero();
  return project_block(u_dot / w, rate_cov) / (w * w);
}

double LosRateFilter::los_rate_variance() const noexcept {
  return los_rate_variance(u_dot_, P_.bottomRightCorner<3, 3>());
}

Mat3 LosRateFilter::e_theta_covariance() const noexcept {
  return e_theta_covariance(u_dot_, P_.bottomRightCorner<3, 3>());
}

}  // namespace evade::guidance
