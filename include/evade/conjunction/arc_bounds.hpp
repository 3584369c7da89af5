// Proven bounds on one object's motion between two grid states under two-body or
// two-body + J2 gravity (issue 13; theorem and proofs in docs/VALIDATION.md, "Robust mode
// under J2: the no-miss bound").
//
// Gravity bounds at radius >= r (Vallado eq. 8-30 for the J2 term; J = J2 (Re/r)^2):
//   |a(x)|        <= G(r) = mu/r^2 (1 + 3 J)           (|a_J2| = 3/2 J mu/r^2 sqrt(1-2u+5u^2),
//                                                       u = z^2/r^2 <= 1)
//   ||Da(x)||     <= K(r) = 2 mu/r^3 (1 + 42 J)        (Leibniz on the three terms of a_J2)
//   ||D^2 a(x)||  <= L(r) = 24 mu/r^4 (1 + 40 J)       (idem, one derivative further)
// all decreasing in r (J = 0 for two-body, giving the two-body values).
// Arc lemma: for the exact solution r(t) of r'' = a(r) on [t_a, t_a + h] through the grid
// state (r_a, v_a), with d_tan the distance from the origin to the tangent segment
// r_a + v_a s, s in [0, h], and rho0 = d_tan / 2: if rho* = d_tan - G(rho0) h^2/2 > rho0,
// then |r(t)| >= rho* on the arc (first-passage argument with Taylor's remainder); hence
// |r''| <= G(rho*) and r(t) lies within G h^2/8 of the chord r_a -> r_b (interpolation
// remainder, Green's kernel (t-a)(b-t)/2), which gives r_lo, r_hi, g_max and v_max below.
#pragma once

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade::conjunction {

/// G(r): bound on |a| at every point of radius >= r_m [m/s^2].
double gravity_bound_mps2(double r_m, GravityModel model, const EarthModel& earth);
/// K(r): bound on the operator norm of the gravity gradient at radius >= r_m [1/s^2].
double gravity_gradient_bound_ps2(double r_m, GravityModel model, const EarthModel& earth);
/// L(r): bound on the norm of the second derivative of the acceleration [1/(m s^2)].
double gravity_hessian_bound(double r_m, GravityModel model, const EarthModel& earth);

/// What the arc lemma proves for one object on one grid step.
struct ArcBounds {
  double r_lo_m = 0.0;      ///< |r(t)| >= r_lo_m on the arc
  double r_hi_m = 0.0;      ///< |r(t)| <= r_hi_m on the arc
  double g_max_mps2 = 0.0;  ///< |r''(t)| <= g_max_mps2 on the arc
  double v_max_mps = 0.0;   ///< |r'(t)| <= v_max_mps on the arc
  double perturbation_mps2 = 0.0;       ///< |r'' - a(r)| <= this (0 for the field's motion)
  double perturbation_rate_mps3 = 0.0;  ///< |d/dt (r'' - a(r))| <= this
};

/// Bounds on the arc from state a (at t) to state b (at t + h_s). Throws std::runtime_error
/// when the lemma's condition fails (a step far too long for the orbit). perturbation_mps2:
/// a bound on |r'' - a(r)| of a motion that is not exactly the field's (SGP4 motion,
/// motion_source.hpp); the lemma then holds with G(r) + perturbation_mps2 in place of G(r).
/// velocity_error_mps: a bound on |v - r'| of the velocities of a and b (grid states with
/// SGP4's own velocity, MotionSource::grid_state_at): the tangent segment then departs from
/// the arc by a further velocity_error_mps x h_s, and v_max grows by it.
/// position_error_m: a bound on the distance of a's and b's positions from the exact ones
/// (MotionSource::grid_position_error_m): the tangent segment and the chord then lie within
/// it of the exact ones, so rho* and r_lo shrink by it and r_hi grows by it.
ArcBounds arc_bounds(const StateEci& a, const StateEci& b, double h_s, GravityModel model,
                     const EarthModel& earth, double perturbation_mps2 = 0.0,
                     double velocity_error_mps = 0.0, double position_error_m = 0.0);

}  // namespace evade::conjunction
