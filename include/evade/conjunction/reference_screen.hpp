// Fine-sampling reference screening for validating the robust screener over long spans
// (issue 13): every pair's range rate f = rho.rho' is sampled every sample_step_s and each
// - to + sign change is refined by Brent's method (local refinement from the sample state,
// the same force model); a closest approach is kept when its miss is <= D_ij. It is the
// brute force of screen_brute_force made affordable for 7 days:
//  * propagation: one DOP853 integrator per object on its own steps, states at the samples
//    from its 7th-order dense output (HNW I sec. II.6);
//  * pair skipping: a pair at distance d > D_ij at sample k cannot come within D_ij before
//    t_k + (d - D_ij) / V, V = a bound on the relative speed, so its next sign test is
//    scheduled after that time. V = 2 max_i v_i with v_i^2 <= 2 E_i + 2 mu / Re + mu J2 / Re
//    (energy E_i with the J2 potential, conserved; radius >= Re, checked at every sample
//    with a 20 km margin), inflated by 1 % for the integrator's energy drift.
// It shares with the robust screener only the force model, the integrator and Brent's
// method, none of its bounds.
#pragma once

#include <vector>

#include "evade/conjunction/robust_screen.hpp"

namespace evade::conjunction {

/// Reference events over [0, span_s] (opt: threshold, warning radius, gravity, earth,
/// integ, tca_tol_s). Throws std::runtime_error if an object falls below Re + 20 km.
ScreenResult screen_reference(const std::vector<SpaceObject>& objects, double span_s,
                              double sample_step_s, const ScreenOptions& opt);

}  // namespace evade::conjunction
