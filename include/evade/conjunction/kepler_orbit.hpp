// Two-body orbit with its constants precomputed, for evaluating many objects at many times.
//
// Same f and g formulation as evade::propagate_kepler (Vallado 4th ed. sec. 2.3, Battin
// eq. 4.40-4.42): Kepler's equation written relative to the initial state,
//   n dt = dE - (e cos E0) sin dE + (e sin E0)(1 - cos dE),
// so circular and equatorial orbits need no special case. Everything that does not depend
// on dt (a, n, e cos E0, e sin E0, r0, r0.v0) is computed once; n dt is reduced modulo 2 pi
// before solving (f, g and r are 2 pi-periodic in dE), which keeps multi-day spans exact.
#pragma once

#include "evade/core/state.hpp"

namespace evade::conjunction {

class KeplerOrbit {
 public:
  /// Throws std::invalid_argument for a non-finite state, mu <= 0 or e >= 1.
  KeplerOrbit(const StateEci& s0, double mu_m3ps2);
  /// State dt_s after the initial state (any sign).
  StateEci state_at(double dt_s) const;
  double a_m() const { return a_; }
  double e() const { return e_; }
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

}  // namespace evade::conjunction
