// Propagation through tangential burns (see burn_propagation.hpp).
#include "evade/formation/burn_propagation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "evade/core/elements.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade::formation {

double tangential_dv_for_delta_a(const StateEci& s, double delta_a_m, double mu) {
  const double r = s.r_eci_m.norm();
  const double v = s.v_eci_mps.norm();
  const double energy_term = 2.0 / r - v * v / mu;  // = 1/a
  if (!std::isfinite(delta_a_m) || !(energy_term > 0.0)) {
    throw std::invalid_argument("tangential_dv_for_delta_a: delta_a_m = " +
                                std::to_string(delta_a_m) + " on an unbound/invalid state");
  }
  const double a_new = 1.0 / energy_term + delta_a_m;
  const double v2 = mu * (2.0 / r - 1.0 / a_new);
  if (!(a_new > 0.0) || !(v2 > 0.0)) {
    throw std::invalid_argument("tangential_dv_for_delta_a: delta_a_m = " +
                                std::to_string(delta_a_m) + " gives no bound orbit");
  }
  return std::sqrt(v2) - v;
}

StateEci state_from_mean_elements(const MeanElements& m, const EarthModel& earth) {
  OrbitalElements oe;
  const double si = std::sin(m.i_rad);
  oe.a_m = m.a_m + 1.5 * earth.j2 * earth.re_m * earth.re_m / m.a_m * si * si *
                       std::cos(2.0 * m.arg_lat_rad);
  oe.e = m.e;
  oe.i_rad = m.i_rad;
  oe.raan_rad = wrap_two_pi(m.raan_rad);
  oe.argp_rad = 0.0;
  oe.true_anomaly_rad = wrap_two_pi(m.arg_lat_rad);
  return state_from_elements(oe, earth.mu_m3ps2);
}

MeanElements osculating_angles(const StateEci& s, double mu) {
  const Vec3& r = s.r_eci_m;
  const Vec3& v = s.v_eci_mps;
  const Vec3 h = r.cross(v);
  const double hn = h.norm();
  MeanElements m;
  m.a_m = 1.0 / (2.0 / r.norm() - v.squaredNorm() / mu);
  m.i_rad = std::acos(std::clamp(h.z() / hn, -1.0, 1.0));
  m.raan_rad = std::atan2(h.x(), -h.y());
  const Vec3 node(std::cos(m.raan_rad), std::sin(m.raan_rad), 0.0);
  const Vec3 in_plane = h.cross(node) / hn;  // 90 deg ahead of the node, in the orbit plane
  m.arg_lat_rad = std::atan2(r.dot(in_plane), r.dot(node));
  const Vec3 e_vec = v.cross(h) / mu - r / r.norm();
  m.e = e_vec.norm();
  return m;
}

namespace {

void check_sample_times(const std::vector<double>& t_s) {
  for (std::size_t k = 0; k < t_s.size(); ++k) {
    if (!std::isfinite(t_s[k]) || t_s[k] < 0.0 || (k > 0 && t_s[k] < t_s[k - 1])) {
      throw std::invalid_argument("propagate_with_burns: sample times must be finite, >= 0 and "
                                  "ascending (t_s[" + std::to_string(k) + "] = " +
                                  std::to_string(t_s[k]) + ")");
    }
  }
}

void check_burns(const std::vector<TangentialBurn>& burns) {
  for (std::size_t k = 0; k < burns.size(); ++k) {
    if (!std::isfinite(burns[k].t_s) || burns[k].t_s < 0.0 ||
        (k > 0 && burns[k].t_s <= burns[k - 1].t_s) || !std::isfinite(burns[k].delta_a_m)) {
      throw std::invalid_argument("propagate_with_burns: burns must have finite, >= 0, "
                                  "strictly ascending times (burn " + std::to_string(k) +
                                  " at t_s = " + std::to_string(burns[k].t_s) + ")");
    }
  }
}

// The samples of t_s, taken segment by segment: the current segment ends at t_end (at its
// burn), the last one takes every remaining sample. A sample belongs to a segment when it
// lies before that segment's burn (a sample at a burn time gets the post-burn state).
struct Sampler {
  const std::vector<double>& t_s;
  std::vector<StateEci> out;
  std::size_t next = 0;
  double t_end = 0.0;
  bool last = false;
  /// The next sample is due at time t and belongs to the current segment.
  bool due(double t) const {
    return next < t_s.size() && t_s[next] <= t && (last || t_s[next] < t_end);
  }
};

// Integrates from (t, x) to the segment's end, taking the samples passed on the way.
void integrate_segment(Dop853<Vec6>& integ, Sampler& s, double& t, Vec6& x) {
  integ.reset(t, x);
  while (integ.t_s() < s.t_end) {
    if (!integ.step(s.t_end)) {
      throw std::runtime_error("propagate_with_burns: " + integ.failure_reason());
    }
    while (s.due(integ.t_s())) {
      const double ts = s.t_s[s.next];
      s.out[s.next++] = StateEci::from_stacked(ts == integ.t_s() ? integ.x() : integ.dense(ts));
    }
  }
  x = integ.x();
  t = s.t_end;
}

// Adds the burn's tangential Δv (vis-viva) to x, and records it when asked.
void apply_burn(const TangentialBurn& burn, double mu, Vec6& x,
                std::vector<AppliedBurn>* applied) {
  const StateEci pre = StateEci::from_stacked(x);
  const double dv = tangential_dv_for_delta_a(pre, burn.delta_a_m, mu);
  if (applied != nullptr) {
    AppliedBurn ab;
    ab.t_s = burn.t_s;
    ab.delta_a_m = burn.delta_a_m;
    ab.dv_mps = dv;
    ab.a_before_m = 1.0 / (2.0 / pre.r_eci_m.norm() - pre.v_eci_mps.squaredNorm() / mu);
    ab.dv_approx_mps = 0.5 * std::sqrt(mu / std::pow(ab.a_before_m, 3)) * burn.delta_a_m;
    applied->push_back(ab);
  }
  x.tail<3>() += dv * pre.v_eci_mps.normalized();
}

}  // namespace

std::vector<StateEci> propagate_with_burns(const StateEci& s0, const std::vector<double>& t_s,
                                           const std::vector<TangentialBurn>& burns,
                                           const EarthModel& earth, const AdaptiveOptions& opt,
                                           std::vector<AppliedBurn>* applied) {
  check_sample_times(t_s);
  check_burns(burns);
  if (applied != nullptr) applied->clear();
  auto rhs = [&earth](double, const Vec6& x) {
    return orbit_derivative(x, GravityModel::kTwoBodyJ2, earth);
  };
  Sampler s{t_s, std::vector<StateEci>(t_s.size())};
  Dop853<Vec6> integ(rhs, opt);
  Vec6 x = s0.stacked();
  double t = 0.0;
  const std::size_t nb = burns.size();
  const double t_last = t_s.empty() ? 0.0 : t_s.back();
  // Segment seg runs from t to the burn seg (or to the last sample).
  for (std::size_t seg = 0; seg <= nb; ++seg) {
    s.last = seg == nb;
    s.t_end = s.last ? std::max(t_last, t) : burns[seg].t_s;
    while (s.due(t)) s.out[s.next++] = StateEci::from_stacked(x);
    if (s.t_end > t) integrate_segment(integ, s, t, x);
    if (!s.last) apply_burn(burns[seg], earth.mu_m3ps2, x, applied);
  }
  return std::move(s.out);
}

}  // namespace evade::formation
