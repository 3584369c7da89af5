// Hill–Clohessy–Wiltshire relative motion about a circular reference orbit.
//
// Frame: RSW of the reference (see evade/core/frames.hpp): x radial (outward), y along
// track, z orbit normal. State layout [x y z xdot ydot zdot] in m and m/s. Equations:
//     xddot = 3 n^2 x + 2 n ydot,   yddot = -2 n xdot,   zddot = -n^2 z.
// Phi(t) = [Phi_rr Phi_rv; Phi_vr Phi_vv] maps the state at 0 to the state at t
// (Vallado 4th ed. eq. 6-66; Clohessy & Wiltshire 1960).
#pragma once

#include "evade/core/state.hpp"

namespace evade {

struct HcwBlocks {
  Mat3 rr;  ///< d r(t) / d r(0)
  Mat3 rv;  ///< d r(t) / d v(0)  [s]
  Mat3 vr;  ///< d v(t) / d r(0)  [1/s]
  Mat3 vv;  ///< d v(t) / d v(0)
};

/// The four 3x3 blocks of Phi(t) for mean motion n [rad/s], time t [s] (t may be negative).
HcwBlocks hcw_stm_blocks(double n_radps, double t_s);
/// The full 6x6 state-transition matrix.
Mat6 hcw_stm(double n_radps, double t_s);
/// x(t) = Phi(t) x0.
Vec6 hcw_propagate(double n_radps, double t_s, const Vec6& x0_rsw);
/// [Phi_rv; Phi_vv]: the 6x3 map from an impulse applied at time 0 to the state change at t.
Eigen::Matrix<double, 6, 3> hcw_impulse_matrix(double n_radps, double t_s);
/// State change at t caused by an impulse dv applied at time 0: [Phi_rv; Phi_vv] dv.
Vec6 hcw_impulse_response(double n_radps, double t_s, const Vec3& dv_rsw_mps);
/// Right-hand side of the linear HCW equations (for numerical checks).
Vec6 hcw_derivative(double n_radps, const Vec6& x_rsw);

}  // namespace evade
