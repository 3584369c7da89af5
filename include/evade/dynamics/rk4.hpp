// Classical fixed-step fourth-order Runge–Kutta (header-only).
//
// Reference: Hairer, Nørsett & Wanner, "Solving Ordinary Differential Equations I", 2nd ed.,
// sec. II.1, Table 1.2 (the "classical" RK4 tableau). Global error O(h^4).
// Vector is any type with vector-space operations (Eigen column vectors, double).
// Rhs is any callable `Vector f(double t_s, const Vector& x)`.
#pragma once

#include <cmath>
#include <stdexcept>

namespace evade {

/// One RK4 step of size h_s (may be negative) from (t_s, x).
template <class Vector, class Rhs>
Vector rk4_step(const Rhs& f, double t_s, const Vector& x, double h_s) {
  const double half = 0.5 * h_s;
  const Vector k1 = f(t_s, x);
  const Vector k2 = f(t_s + half, Vector(x + half * k1));
  const Vector k3 = f(t_s + half, Vector(x + half * k2));
  const Vector k4 = f(t_s + h_s, Vector(x + h_s * k3));
  return Vector(x + (h_s / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4));
}

/// Integrates from t0_s to t1_s (either direction) with N = ceil(|t1-t0|/h_max_s) equal
/// steps. Throws std::invalid_argument if h_max_s <= 0 or a time is not finite.
template <class Vector, class Rhs>
Vector rk4_propagate(const Rhs& f, double t0_s, const Vector& x0, double t1_s, double h_max_s) {
  if (!(h_max_s > 0.0) || !std::isfinite(t0_s) || !std::isfinite(t1_s)) {
    throw std::invalid_argument("rk4_propagate: need finite t0_s, t1_s and h_max_s > 0");
  }
  const double span_s = t1_s - t0_s;
  const double steps_real = std::ceil(std::abs(span_s) / h_max_s);
  if (steps_real > 1e9) throw std::invalid_argument("rk4_propagate: more than 1e9 steps");
  const long steps = static_cast<long>(steps_real);
  Vector x = x0;
  if (steps == 0) return x;
  const double h_s = span_s / static_cast<double>(steps);
  for (long i = 0; i < steps; ++i) {
    x = rk4_step(f, t0_s + static_cast<double>(i) * h_s, x, h_s);
  }
  return x;
}

}  // namespace evade
