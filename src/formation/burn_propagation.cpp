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

std::vector<StateEci> propagate_with_burns(const StateEci& s0, const std::vector<double>& t_s,
                                           const std::vector<TangentialBurn>& burns,
                                           const EarthModel& earth, const AdaptiveOptions& opt,
                                           std::vector<AppliedBurn>* applied) {
  for (std::size_t k = 0; k < t_s.size(); ++k) {
    if (!std::isfinite(t_s[k]) || t_s[k] < 0.0 || (k > 0 && t_s[k] < t_s[k - 1])) {
      throw std::invalid_argument("propagate_with_burns: sample times must be finite, >= 0 and "
                                  "ascending (t_s[" + std::to_string(k) + "] = " +
                                  std::to_string(t_s[k]) + ")");
    }
  }
  for (std::size_t k = 0; k < burns.size(); ++k) {
    if (!std::isfinite(burns[k].t_s) || burns[k].t_s < 0.0 ||
        (k > 0 && burns[k].t_s <= burns[k - 1].t_s) || !std::isfinite(burns[k].delta_a_m)) {
      throw std::invalid_argument("propagate_with_burns: burns must have finite, >= 0, "
                                  "strictly ascending times (burn " + std::to_string(k) +
                                  " at t_s = " + std::to_string(burns[k].t_s) + ")");
    }
  }
  if (applied != nullptr) applied->clear();
  auto rhs = [&earth](double, const Vec6& x) {
    return orbit_derivative(x, GravityModel::kTwoBodyJ2, earth);
  };
  std::vector<StateEci> out(t_s.size());
  Dop853<Vec6> integ(rhs, opt);
  Vec6 x = s0.stacked();
  double t = 0.0;
  std::size_t next = 0;
  const std::size_t nb = burns.size();
  const double t_last = t_s.empty() ? 0.0 : t_s.back();
  // Segment seg runs from t to the burn seg (or to the last sample); a sample belongs to it
  // when it lies before that burn (a sample at a burn time gets the post-burn state).
  for (std::size_t seg = 0; seg <= nb; ++seg) {
    const double t_end_seg = (seg < nb) ? burns[seg].t_s : std::max(t_last, t);
    auto in_seg = [&](double ts) { return seg == nb || ts < t_end_seg; };
    while (next < t_s.size() && t_s[next] <= t && in_seg(t_s[next])) {
      out[next++] = StateEci::from_stacked(x);
    }
    if (t_end_seg > t) {
      integ.reset(t, x);
      while (integ.t_s() < t_end_seg) {
        if (!integ.step(t_end_seg)) {
          throw std::runtime_error("propagate_with_burns: " + integ.failure_reason());
        }
        while (next < t_s.size() && t_s[next] <= integ.t_s() && in_seg(t_s[next])) {
          const double ts = t_s[next];
          out[next++] = StateEci::from_stacked(ts == integ.t_s() ? integ.x() : integ.dense(ts));
        }
      }
      x = integ.x();
      t = t_end_seg;
    }
    if (seg < nb) {
      const StateEci pre = StateEci::from_stacked(x);
      const double dv = tangential_dv_for_delta_a(pre, burns[seg].delta_a_m, earth.mu_m3ps2);
      if (applied != nullptr) {
        AppliedBurn ab;
        ab.t_s = burns[seg].t_s;
        ab.delta_a_m = burns[seg].delta_a_m;
        ab.dv_mps = dv;
        ab.a_before_m =
            1.0 / (2.0 / pre.r_eci_m.norm() - pre.v_eci_mps.squaredNorm() / earth.mu_m3ps2);
        ab.dv_approx_mps =
            0.5 * std::sqrt(earth.mu_m3ps2 / std::pow(ab.a_before_m, 3)) * burns[seg].delta_a_m;
        applied->push_back(ab);
      }
      x.tail<3>() += dv * pre.v_eci_mps.normalized();
    }
  }
  return out;
}

}  // namespace evade::formation
