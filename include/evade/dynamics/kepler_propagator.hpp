// Analytic two-body propagation (Kepler's equation on the elements; bound orbits only).
#pragma once

#include "evade/core/state.hpp"

namespace evade {

/// Propagates an ECI state by dt_s (may be negative) on a two-body orbit.
/// Uses f and g functions in the eccentric anomaly, so circular and equatorial orbits
/// need no element singularity handling. Throws std::invalid_argument for e >= 1 or NaN.
StateEci propagate_kepler(const StateEci& s0, double dt_s, double mu_m3ps2);

}  // namespace evade
