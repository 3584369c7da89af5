// Equinoctial orbital elements of a two-body orbit, E = (n, af, ag, chi, psi, lambda_M), in
// the order and prograde form (retrograde factor +1) of Vallado & Alfano, "Updated analytical
// partials for covariance transformations and optimization", AAS 15-537, 2015:
//   n [rad/s] mean motion, (af, ag) the eccentricity vector in the equinoctial frame (f, g),
//   (chi, psi) = tan(i/2) (sin Omega, cos Omega) = (w_x, -w_y) / (1 + w_z) with w the orbit
//   normal, lambda_M [rad] the mean longitude. Singular only for i = 180 deg (w_z = -1) and e >= 1.
// Cartesian -> elements: Vallado & Alfano eq. (9). Elements -> Cartesian: the generalized
// Kepler equation lambda_M = F + ag cos F - af sin F (Broucke & Cefola, "On the equinoctial
// orbit elements", Celest. Mech. 5, 1972) solved by Newton's method. The Jacobian dX/dE at
// one time is the analytic one of Vallado & Alfano's appendix ("Equinoctial to Cartesian").
// Under two-body motion only lambda_M changes, lambda_M(t) = lambda_M(0) + n t, so
// dX(t)/dE(0) = [dX/dE](t) * Phi(t) with Phi = I except Phi(lambda_M, n) = t.
#pragma once

#include "evade/core/state.hpp"

namespace evade::assessment {

/// Equinoctial elements (n [rad/s], af, ag, chi, psi, lambda_M [rad]) of the Cartesian state
/// x = (r [m], v [m/s]); false (e untouched) for an unbound orbit (a <= 0 or e >= 1), a zero
/// angular momentum or an orbit within 1e-10 of i = 180 deg. lambda_M is in [0, 2 pi).
bool cartesian_to_equinoctial(const Vec6& x, double mu_m3ps2, Vec6* e);

/// The Cartesian state (r [m], v [m/s]) of equinoctial elements e (requires e < 1).
Vec6 equinoctial_to_cartesian(const Vec6& e, double mu_m3ps2);

/// dX/dE at one time, with x the Cartesian state of e (both at that time).
Mat6 jacobian_equinoctial_to_cartesian(const Vec6& e, const Vec6& x, double mu_m3ps2);

/// dX(t)/dE(0) for elements e0 at t = 0 propagated by two-body motion to dt_s; x_out (if not
/// null) receives X(t).
Mat6 jacobian_epoch_elements_to_cartesian(const Vec6& e0, double dt_s, double mu_m3ps2,
                                          Vec6* x_out);

}  // namespace evade::assessment
