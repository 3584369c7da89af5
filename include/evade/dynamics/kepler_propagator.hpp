// Analytic two-body propagation with Lagrange f and g functions in the eccentric anomaly
// (bound orbits only). See kepler_propagator.cpp for the equations.
#pragma once

#include "evade/core/state.hpp"

namespace evade {

/// A two-body orbit from an initial ECI state, with everything that does not depend on the
/// time offset (a, n, e cos E0, e sin E0, |r0|, r0.v0) computed once, for evaluating one
/// object at many times (conjunction screening, ephemerides). Circular and equatorial
/// orbits need no special case: no elements are formed.
class KeplerOrbit {
 public:
  /// Throws std::invalid_argument for a non-finite state, mu <= 0 or e >= 1.
  KeplerOrbit(const StateEci& s0, double mu_m3ps2);
  /// State dt_s after the initial state (any sign, any length: n dt is reduced modulo 2 pi).
  /// Throws std::invalid_argument for a non-finite dt_s.
  StateEci state_at(double dt_s) const;
  double mean_motion_radps() const { return n_; }

 private:
  StateEci s0_;
  double mu_ = 0.0;
  double a_ = 0.0;
  double e_ = 0.0;
  double n_ = 0.0;
  double r0_ = 0.0;
  double rdotv_ = 0.0;
  double ec_ = 0.0;  // e cos E0
  double es_ = 0.0;  // e sin E0
  double sqrt_a_over_mu_ = 0.0;
  double sqrt_mu_a_ = 0.0;
};

/// Propagates an ECI state by dt_s (may be negative) on a two-body orbit:
/// KeplerOrbit(s0, mu).state_at(dt_s). Throws std::invalid_argument for e >= 1 or NaN.
StateEci propagate_kepler(const StateEci& s0, double dt_s, double mu_m3ps2);

}  // namespace evade
