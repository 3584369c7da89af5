// Orbit propagation entry points for the other modules.
//
// Two-body: analytic (propagate_kepler, f and g functions; Vallado 4th ed. sec. 2.3).
// Two-body + J2: numerical, DOP853 (HNW I sec. II.10) on d/dt [r; v] = [v; a(r)] with the
// J2 acceleration of Vallado eq. 8-30. Accuracy of the numerical path is set by the
// AdaptiveOptions (defaults: < 1 m over one day in LEO; AdaptiveOptions::tight(): < 1 mm).
#pragma once

#include <vector>

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"
#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade {

/// State after dt_s (may be negative). Two-body ignores opt (analytic, exact to rounding).
/// Throws std::invalid_argument for a non-finite state and std::runtime_error if the
/// numerical integration fails (e.g. the orbit hits the centre).
StateEci propagate_orbit(const StateEci& s0, double dt_s, GravityModel model,
                         const EarthModel& earth = kEarthDefault, const AdaptiveOptions& opt = {},
                         IntegrationStats* stats = nullptr);

/// States at the offsets dt_s[k] from s0 (any order, any sign), computed with one
/// integration per direction using the dense output (no step-size restarts at samples).
std::vector<StateEci> propagate_orbit_samples(const StateEci& s0, const std::vector<double>& dt_s,
                                              GravityModel model,
                                              const EarthModel& earth = kEarthDefault,
                                              const AdaptiveOptions& opt = {});

}  // namespace evade
