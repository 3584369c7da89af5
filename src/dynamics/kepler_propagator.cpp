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

bool finite(const Vec3& v) { return v.allFinite(); }

}  // namespace

StateEci propagate_kepler(const StateEci& s0, double dt_s, double mu_m3ps2) {
  if (!finite(s0.r_eci_m) || !finite(s0.v_eci_mps) || !std::isfinite(dt_s) ||
      !std::isfinite(mu_m3ps2) || !(mu_m3ps2 > 0.0)) {
    throw std::invalid_argument("propagate_kepler: non-finite state, dt or mu (or mu <= 0)");
  }
  const Vec3& r0v = s0.r_eci_m;
  const Vec3& v0v = s0.v_eci_mps;
  const double r0 = r0v.norm();
  if (!(r0 > 0.0)) throw std::invalid_argument("propagate_kepler: zero position vector");
  const double v2 = v0v.squaredNorm();
  const double inv_a = 2.0 / r0 - v2 / mu_m3ps2;  // vis-viva
  const double h2 = r0v.cross(v0v).squaredNorm();
  // e^2 = 1 - h^2/(mu a); e >= 1 when 1/a <= 0 or h = 0 (rectilinear).
  const double one_minus_e2 = h2 * inv_a / mu_m3ps2;
  if (!(inv_a > 0.0) || !(one_minus_e2 > 0.0)) {
    throw std::invalid_argument("propagate_kepler: orbit is not bound (e >= 1), 1/a = " +
                                std::to_string(inv_a) + " 1/m, 1-e^2 = " +
                                std::to_string(one_minus_e2));
  }
  if (dt_s == 0.0) return s0;

  const double a = 1.0 / inv_a;
  const double sqrt_mu = std::sqrt(mu_m3ps2);
  const double n = sqrt_mu * std::sqrt(inv_a * inv_a * inv_a);
  const double rdotv = r0v.dot(v0v);
  const double ec = 1.0 - r0 * inv_a;               // e cos E0
  const double es = rdotv / (sqrt_mu * std::sqrt(a));  // e sin E0
  const double e = std::min(std::sqrt(ec * ec + es * es), 1.0);

  // Reduce the mean-anomaly change to [-pi, pi] plus whole revolutions (which change nothing).
  const double dm = n * dt_s;
  const double revs = std::nearbyint(dm / kTwoPi);
  const double m = dm - revs * kTwoPi;

  // Bracketed Newton on F(x) = x - ec sin x + es (1 - cos x) - m, F' = 1 - ec cos x + es sin x.
  double lo = m - 2.0 * e;
  double hi = m + 2.0 * e;
  double x = m;  // |dE - m| <= 2e, so m is a good start for small and moderate e
  for (int it = 0; it < kMaxIterations; ++it) {
    const double sx = std::sin(x);
    const double hx = std::sin(0.5 * x);
    const double f = x - ec * sx + es * 2.0 * hx * hx - m;
    if (f == 0.0) break;
    if (f > 0.0) hi = std::min(hi, x); else lo = std::max(lo, x);
    const double fp = 1.0 - ec * std::cos(x) + es * sx;
    double xn = x - f / fp;
    if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    const double dx = xn - x;
    x = xn;
    const double eps = 2.2e-16 * (1.0 + std::abs(x));
    if (std::abs(dx) <= 4.0 * eps || hi - lo <= eps) break;
  }

  const double sde = std::sin(x);
  const double hde = std::sin(0.5 * x);
  const double omc = 2.0 * hde * hde;  // 1 - cos dE without cancellation
  const double sqrt_a_over_mu = std::sqrt(a) / sqrt_mu;
  const double r = a + (r0 - a) * (1.0 - omc) + rdotv * sqrt_a_over_mu * sde;
  const double f = 1.0 - a / r0 * omc;
  // g = dt - (dE - sin dE)/n, rewritten with (K) so that no large terms cancel.
  const double g = r0 * sqrt_a_over_mu * sde + rdotv * a / mu_m3ps2 * omc;
  const double fdot = -std::sqrt(mu_m3ps2 * a) * sde / (r * r0);
  const double gdot = 1.0 - a / r * omc;

  StateEci s;
  s.r_eci_m = f * r0v + g * v0v;
  s.v_eci_mps = fdot * r0v + gdot * v0v;
  return s;
}

}  // namespace evade
