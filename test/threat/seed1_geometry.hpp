// The seed1 geometry of paper 001 for tests (same values as scenarios/seed1.yaml): spherical
// Earth μ = 3.986005e14 m³/s², Re = 6 371 110 m, target circular at 370 km, chaser 100 km
// behind on the same orbit (an HCW equilibrium), ΔV_max = 324 m/s, ΔT = 2200 s, 3 impulses.
#pragma once

#include <cmath>

#include "evade/threat/threat_area.hpp"

namespace evade::threat::testing {

inline ThreatGeometry seed1_geometry() {
  const double a_m = 6371110.0 + 370000.0;
  ThreatGeometry g;
  g.n_radps = std::sqrt(3.986005e14 / (a_m * a_m * a_m));
  g.chaser0_rsw << 0.0, -100000.0, 0.0, 0.0, 0.0, 0.0;
  return g;
}

inline ThreatOptions seed1_options() {
  ThreatOptions o;
  o.dv_max_mps = 324.0;
  o.transfer_s = 2200.0;
  o.impulses = 3;
  o.step_s = 5.0;
  return o;
}

}  // namespace evade::threat::testing
