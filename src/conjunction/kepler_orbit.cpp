// Two-body propagation with precomputed constants (see kepler_orbit.hpp; Vallado sec. 2.3).
#include "evade/conjunction/kepler_orbit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "evade/core/constants.hpp"

namespace evade::conjunction {

KeplerOrbit::KeplerOrbit(const StateEci& s0, double mu_m3ps2) : s0_(s0), mu_(mu_m3ps2) {
  if (!s0.r_eci_m.allFinite() || !s0.v_eci_mps.allFinite() || !(mu_m3ps2 > 0.0) ||
      !std::isfinite(mu_m3ps2)) {
    throw std::invalid_argument("KeplerOrbit: non-finite state or mu <= 0");
  }
  r0_ = s0.r_eci_m.norm();
  if (!(r0_ > 0.0)) throw std::invalid_argument("KeplerOrbit: zero position vector");
  const double inv_a = 2.0 / r0_ - s0.v_eci_mps.squaredNorm() / mu_;
  const double h2 = s0.r_eci_m.cross(s0.v_eci_mps).squaredNorm();
  const double one_minus_e2 = h2 * inv_a / mu_;
  if (!(inv_a > 0.0) || !(one_minus_e2 > 0.0)) {
    throw std::invalid_argument("KeplerOrbit: orbit is not bound (e >= 1)");
  }
  a_ = 1.0 / inv_a;
  n_ = std::sqrt(mu_ * inv_a * inv_a * inv_a);
  rdotv_ = s0.r_eci_m.dot(s0.v_eci_mps);
  ec_ = 1.0 - r0_ * inv_a;
  es_ = rdotv_ / std::sqrt(mu_ * a_);
  e_ = std::min(std::sqrt(ec_ * ec_ + es_ * es_), 1.0);
  sqrt_a_over_mu_ = std::sqrt(a_ / mu_);
  sqrt_mu_a_ = std::sqrt(mu_ * a_);
}

StateEci KeplerOrbit::state_at(double dt_s) const {
  if (dt_s == 0.0) return s0_;
  // Reduce n dt to [-pi, pi]: dE = M + 2 pi k solves (K) for M + 2 pi k.
  const double m_full = n_ * dt_s;
  const double turns = std::nearbyint(m_full / kTwoPi);
  const double m = m_full - turns * kTwoPi;
  // Newton on F(x) = x - ec sin x + es (1 - cos x) - m, F' = 1 - ec cos x + es sin x = r/a > 0,
  // bracketed in [m - 2e, m + 2e] with bisection fallback (same as propagate_kepler).
  double lo = m - 2.0 * e_ - 1e-12;
  double hi = m + 2.0 * e_ + 1e-12;
  double x = m + es_ * 0.0 + (e_ > 0.0 ? ec_ * std::sin(m) - es_ * (1.0 - std::cos(m)) : 0.0);
  if (!(x > lo && x < hi)) x = m;
  // Newton converges quadratically: once a correction is below 1e-8 rad the next would be
  // below ~1e-16, so the last correction is applied to (sin, cos) to first order (error
  // dx^2/2 < 1e-16) instead of paying another sincos.
  double sd = 0.0;
  double cd = 1.0;
  for (int it = 0; it < 60; ++it) {
    sd = std::sin(x);
    cd = std::cos(x);
    const double f = x - ec_ * sd + es_ * (1.0 - cd) - m;
    if (f > 0.0) hi = x; else lo = x;
    const double fp = 1.0 - ec_ * cd + es_ * sd;
    double xn = x - f / fp;
    const bool newton = xn >= lo && xn <= hi;  // else bisect (never taken as convergence)
    if (!newton) xn = 0.5 * (lo + hi);
    const double dx = xn - x;
    if (newton && std::abs(dx) < 1e-8) {
      const double s_new = sd + cd * dx;
      cd = cd - sd * dx;
      sd = s_new;
      x = xn;
      break;
    }
    x = xn;
  }
  const double one_minus_c = 1.0 - cd;
  const double r = a_ + (r0_ - a_) * cd + rdotv_ * sqrt_a_over_mu_ * sd;
  const double f = 1.0 - a_ / r0_ * one_minus_c;
  const double g = r0_ * sqrt_a_over_mu_ * sd + rdotv_ * a_ / mu_ * one_minus_c;
  const double fdot = -sqrt_mu_a_ * sd / (r * r0_);
  const double gdot = 1.0 - a_ / r * one_minus_c;
  StateEci out;
  out.r_eci_m = f * s0_.r_eci_m + g * s0_.v_eci_mps;
  out.v_eci_mps = fdot * s0_.r_eci_m + gdot * s0_.v_eci_mps;
  return out;
}

}  // namespace evade::conjunction
