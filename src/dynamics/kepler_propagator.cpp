// Analytic two-body propagation with Lagrange f and g functions in the eccentric anomaly.
//
// Reference: Vallado 4th ed. sec. 2.3 (f and g functions) and Battin, "An Introduction to
// the Mathematics and Methods of Astrodynamics", ch. 4 (f and g in the eccentric anomaly).
// The change of eccentric anomaly dE over dt solves Kepler's equation written relative to
// the initial state (no elements, so circular and equatorial orbits are not singular):
//   n dt = dE - (e cos E0) sin dE + (e sin E0)(1 - cos dE),                        (K)
//   e cos E0 = 1 - r0/a,   e sin E0 = (r0 . v0) / sqrt(mu a).
// Then, with r = a + (r0 - a) cos dE + (r0.v0) sqrt(a/mu) sin dE:
//   f = 1 - a/r0 (1 - cos dE),           g = r0 sqrt(a/mu) sin dE + (r0.v0) a/mu (1 - cos dE),
//   fdot = -sqrt(mu a) sin dE / (r r0),  gdot = 1 - a/r (1 - cos dE).
// (K) is monotonic in dE (its derivative is r/a > 0) and |dE - n dt| <= 2e, so a
// bracketed Newton iteration (bisection fallback, at most kMaxIterations) always converges.
#include "evade/dynamics/kepler_propagator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "evade/core/constants.hpp"

namespace evade {
namespace {

constexpr int kMaxIterations = 60;

}  // namespace

KeplerOrbit::KeplerOrbit(const StateEci& s0, double mu_m3ps2) : s0_(s0), mu_(mu_m3ps2) {
  if (!s0.r_eci_m.allFinite() || !s0.v_eci_mps.allFinite() || !std::isfinite(mu_m3ps2) ||
      !(mu_m3ps2 > 0.0)) {
    throw std::invalid_argument("propagate_kepler: non-finite state or mu (or mu <= 0)");
  }
  r0_ = s0.r_eci_m.norm();
  if (!(r0_ > 0.0)) throw std::invalid_argument("propagate_kepler: zero position vector");
  const double inv_a = 2.0 / r0_ - s0.v_eci_mps.squaredNorm() / mu_;  // vis-viva
  const double h2 = s0.r_eci_m.cross(s0.v_eci_mps).squaredNorm();
  // e^2 = 1 - h^2/(mu a); e >= 1 when 1/a <= 0 or h = 0 (rectilinear).
  const double one_minus_e2 = h2 * inv_a / mu_;
  if (!(inv_a > 0.0) || !(one_minus_e2 > 0.0)) {
    throw std::invalid_argument("propagate_kepler: orbit is not bound (e >= 1), 1/a = " +
                                std::to_string(inv_a) + " 1/m, 1-e^2 = " +
                                std::to_string(one_minus_e2));
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
  if (!std::isfinite(dt_s)) throw std::invalid_argument("propagate_kepler: non-finite dt");
  if (dt_s == 0.0) return s0_;
  // Reduce the mean-anomaly change to [-pi, pi] plus whole revolutions (which change nothing).
  const double m_full = n_ * dt_s;
  const double m = m_full - std::nearbyint(m_full / kTwoPi) * kTwoPi;
  // Bracketed Newton on F(x) = x - ec sin x + es (1 - cos x) - m, F' = 1 - ec cos x + es sin x
  // = r/a > 0, on [m - 2e, m + 2e]; bisection when Newton leaves the bracket. The start is one
  // fixed-point step from m.
  double lo = m - 2.0 * e_ - 1e-12;
  double hi = m + 2.0 * e_ + 1e-12;
  double x = m + (e_ > 0.0 ? ec_ * std::sin(m) - es_ * (1.0 - std::cos(m)) : 0.0);
  if (!(x > lo && x < hi)) x = m;
  // Newton converges quadratically: once a correction is below 1e-8 rad the next would be
  // below ~1e-16, so the last correction is applied to (sin, cos) to first order (error
  // dx^2/2 < 1e-16) instead of paying another sincos.
  double sd = 0.0;
  double cd = 1.0;
  for (int it = 0; it < kMaxIterations; ++it) {
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
  // 1 - cos dE: for small dE use 2 sin^2(dE/2), which does not cancel (short steps matter
  // for event location and the sim's 20 ms cycles).
  double omc = 1.0 - cd;
  if (std::abs(x) < 0.1) {
    const double h = std::sin(0.5 * x);
    omc = 2.0 * h * h;
  }
  const double r = a_ + (r0_ - a_) * (1.0 - omc) + rdotv_ * sqrt_a_over_mu_ * sd;
  const double f = 1.0 - a_ / r0_ * omc;
  // g = dt - (dE - sin dE)/n, rewritten with (K) so that no large terms cancel.
  const double g = r0_ * sqrt_a_over_mu_ * sd + rdotv_ * a_ / mu_ * omc;
  const double fdot = -sqrt_mu_a_ * sd / (r * r0_);
  const double gdot = 1.0 - a_ / r * omc;
  StateEci out;
  out.r_eci_m = f * s0_.r_eci_m + g * s0_.v_eci_mps;
  out.v_eci_mps = fdot * s0_.r_eci_m + gdot * s0_.v_eci_mps;
  return out;
}

StateEci propagate_kepler(const StateEci& s0, double dt_s, double mu_m3ps2) {
  if (!std::isfinite(dt_s)) throw std::invalid_argument("propagate_kepler: non-finite dt");
  return KeplerOrbit(s0, mu_m3ps2).state_at(dt_s);
}

}  // namespace evade
