// The own spacecraft beside an SGP4 catalog (include/evade/conjunction/own_orbit_motion.hpp).
#include "evade/conjunction/own_orbit_motion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "evade/dynamics/orbit_propagator.hpp"
#include "evade/sgp4/teme_to_j2000.hpp"

namespace evade::conjunction {
namespace {

// The own velocity is the integrator's (AdaptiveOptions::tight(): below 1 mm a day), the
// derivative of its position to far below this.
constexpr double kOwnVelocityErrorMps = 1e-6;

}  // namespace

OwnOrbitMotion::OwnOrbitMotion(const StateEci& own_j2000, double start_j2000_s, double span_s,
                               const EarthModel& earth, std::shared_ptr<const Sgp4Motion> catalog,
                               const Sgp4MotionOptions& envelope)
    : catalog_(std::move(catalog)), earth_(earth), span_s_(span_s) {
  if (catalog_ == nullptr) throw std::invalid_argument("OwnOrbitMotion: no catalog motion");
  if (!(span_s > 0.0 && std::isfinite(span_s)))
    throw std::invalid_argument("OwnOrbitMotion: the span must be a finite number > 0 s");
  if (!own_j2000.r_eci_m.allFinite() || !own_j2000.v_eci_mps.allFinite() ||
      !(own_j2000.r_eci_m.norm() > earth.re_m))
    throw std::invalid_argument("OwnOrbitMotion: the own state must be finite and above the Earth's radius");
  const std::size_t n = static_cast<std::size_t>(std::ceil(span_s / kNodeStep_s)) + 2;
  std::vector<double> offsets(n);
  for (std::size_t k = 0; k < n; ++k) offsets[k] = static_cast<double>(k) * kNodeStep_s;
  nodes_ = propagate_orbit_samples(own_j2000, offsets, GravityModel::kTwoBodyJ2, earth_,
                                   AdaptiveOptions::tight());
  rot_.resize(n);
  for (std::size_t k = 0; k < n; ++k) rot_[k] = sgp4::teme_to_j2000_matrix(start_j2000_s + offsets[k]);
  sample_envelope(envelope);
}

StateEci OwnOrbitMotion::own_j2000_at(double t_s) const {
  if (!(t_s >= -1e-9 && t_s <= span_s_ + kNodeStep_s))
    throw std::runtime_error("own spacecraft: t = " + std::to_string(t_s) + " s is outside the span");
  const double kf = std::floor(std::max(t_s, 0.0) / kNodeStep_s);
  const std::size_t k = std::min(static_cast<std::size_t>(kf), nodes_.size() - 1);
  const double dt = t_s - static_cast<double>(k) * kNodeStep_s;
  if (dt == 0.0) return nodes_[k];
  return propagate_orbit(nodes_[k], dt, GravityModel::kTwoBodyJ2, earth_, AdaptiveOptions::tight());
}

void OwnOrbitMotion::rotation_at(double t_s, Eigen::Matrix3d* m, Eigen::Matrix3d* m_dot) const {
  const double kf = std::floor(std::max(t_s, 0.0) / kNodeStep_s);
  const std::size_t k = std::min(static_cast<std::size_t>(kf), rot_.size() - 2);
  const double f = (t_s - static_cast<double>(k) * kNodeStep_s) / kNodeStep_s;
  *m = (1.0 - f) * rot_[k] + f * rot_[k + 1];
  *m_dot = (rot_[k + 1] - rot_[k]) / kNodeStep_s;
}

StateEci OwnOrbitMotion::state_at(std::size_t i, double t_s) const {
  if (i > 0) return catalog_->state_at(i - 1, t_s);
  const StateEci j = own_j2000_at(t_s);
  Eigen::Matrix3d m, m_dot;
  rotation_at(t_s, &m, &m_dot);
  // r_T = M^T r_J, so r_T' = M'^T r_J + M^T v_J: the derivative of the position returned.
  return {m.transpose() * j.r_eci_m, m_dot.transpose() * j.r_eci_m + m.transpose() * j.v_eci_mps};
}

PerturbationBound OwnOrbitMotion::perturbation(std::size_t i) const {
  return i > 0 ? catalog_->perturbation(i - 1) : bound_;
}

double OwnOrbitMotion::velocity_error_mps(std::size_t i) const {
  return i > 0 ? catalog_->velocity_error_mps(i - 1) : kOwnVelocityErrorMps;
}

StateEci OwnOrbitMotion::grid_state_at(std::size_t i, double t_s) const {
  return i > 0 ? catalog_->grid_state_at(i - 1, t_s) : state_at(0, t_s);
}

void OwnOrbitMotion::grid_states_at(double t_s, std::size_t begin, std::size_t end,
                                    StateEci* out) const {
  if (begin == 0 && end > 0) {
    out[0] = state_at(0, t_s);
    begin = 1;
  }
  if (begin < end) catalog_->grid_states_at(t_s, begin - 1, end - 1, out + 1);
}

double OwnOrbitMotion::grid_velocity_error_mps(std::size_t i) const {
  return i > 0 ? catalog_->grid_velocity_error_mps(i - 1) : kOwnVelocityErrorMps;
}

double OwnOrbitMotion::grid_position_error_m(std::size_t i) const {
  return i > 0 ? catalog_->grid_position_error_m(i - 1) : 0.0;
}

bool OwnOrbitMotion::acceleration_at(std::size_t i, double t_s, Vec3& a_mps2, double& error_mps2) const {
  if (i > 0) return catalog_->acceleration_at(i - 1, t_s, a_mps2, error_mps2);
  return false;
}

// p = r_T'' - a_ref(r_T), r_T'' = M^T a(r_J) + 2 M'^T v_J (M'' = 0 between the nodes), at the
// times Sgp4Motion samples an orbit of the own orbit's period and eccentricity.
void OwnOrbitMotion::sample_envelope(const Sgp4MotionOptions& envelope) {
  const StateEci& s0 = nodes_.front();
  const double mu = earth_.mu_m3ps2;
  const double r = s0.r_eci_m.norm(), v2 = s0.v_eci_mps.squaredNorm();
  const double a = 1.0 / (2.0 / r - v2 / mu);
  if (!(a > 0.0)) throw std::invalid_argument("OwnOrbitMotion: the own orbit is not bound");
  const Vec3 e_vec = ((v2 - mu / r) * s0.r_eci_m - s0.r_eci_m.dot(s0.v_eci_mps) * s0.v_eci_mps) / mu;
  const double e = e_vec.norm();
  const double period_s = 2.0 * kPi * std::sqrt(a * a * a / mu);
  Sgp4MotionOptions opt = envelope;
  opt.span_s = span_s_;
  const EarthModel ref = catalog_->reference_earth();
  for (const double t : envelope_sample_times(period_s, e, opt)) {
    const StateEci j = own_j2000_at(t);
    Eigen::Matrix3d m, m_dot;
    rotation_at(t, &m, &m_dot);
    const Vec3 acc_t = m.transpose() * accel_eci_mps2(j.r_eci_m, GravityModel::kTwoBodyJ2, earth_) +
                       2.0 * m_dot.transpose() * j.v_eci_mps;
    const Vec3 p = acc_t - accel_eci_mps2(m.transpose() * j.r_eci_m, GravityModel::kTwoBodyJ2, ref);
    sampled_mps2_ = std::max(sampled_mps2_, p.norm());
  }
  const double n_max = (2.0 * kPi / period_s) * (1.0 + e) * (1.0 + e) / std::pow(1.0 - e * e, 1.5);
  bound_.accel_mps2 = opt.envelope_factor * sampled_mps2_ + opt.envelope_floor_mps2;
  bound_.rate_mps3 = 4.0 * n_max * bound_.accel_mps2;
}

}  // namespace evade::conjunction
