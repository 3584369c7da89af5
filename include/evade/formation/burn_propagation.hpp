// Numerical two-body + J2 propagation of one satellite through tangential semi-major-axis
// burns, with the state sampled on a time grid; helpers for the near-circular "angles" of an
// osculating state. Used by paper 003's verification (verification.hpp) and by the
// maneuver decision (decision.hpp).
//
// Burns are impulsive and tangential (along the velocity). The Δv for a target change Δa of
// the osculating semi-major axis is exact by vis-viva at the burn point:
//   v⁺ = sqrt(mu (2/r − 1/(a + Δa))),  Δv = v⁺ − v   (≈ n Δa / 2 on a circular orbit).
// Integration: DOP853 (evade::Dop853, HNW I sec. II.10) on orbit_derivative (Vallado eq. 8-30)
// with its dense output for the samples.
#pragma once

#include <vector>

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"
#include "evade/dynamics/dop853.hpp"
#include "evade/formation/formation_model.hpp"

namespace evade::formation {

struct TangentialBurn {
  double t_s = 0.0;        ///< burn time from the scenario epoch [s], >= 0
  double delta_a_m = 0.0;  ///< target change of the osculating semi-major axis [m]
};

struct AppliedBurn {
  double t_s = 0.0;
  double delta_a_m = 0.0;
  double dv_mps = 0.0;      ///< signed tangential Δv (vis-viva exact) [m/s]
  double dv_approx_mps = 0.0;  ///< n Δa / 2 (circular-orbit approximation) [m/s]
  double a_before_m = 0.0;  ///< osculating a before the burn [m]
};

/// Tangential Δv that changes the osculating a of `s` by delta_a_m (vis-viva). Throws
/// std::invalid_argument when the target orbit is not bound or not finite.
double tangential_dv_for_delta_a(const StateEci& s, double delta_a_m, double mu_m3ps2);

/// ECI state from mean elements (argument of periapsis 0, ν = u). The semi-major axis gets
/// its first-order J2 short-period term for a near-circular orbit (Brouwer 1959; Kozai 1959),
///   a_osc = a_mean + (3/2) J2 Re² / a · sin² i · cos 2u,
/// without which satellites at different u would have mean semi-major axes differing by up
/// to ~10 km at 7472 km (measured: 2.7e3 km of relative along-track drift in 3 days between
/// u = 0 and 45 deg; with the term, 7.5 km). The other elements are taken as osculating; the
/// remaining initialization drift is removed by the differencing of numerical_constraints.hpp.
StateEci state_from_mean_elements(const MeanElements& m, const EarthModel& earth);

/// Osculating a, i, Ω, u of a state (u measured from the ascending node; defined for
/// inclined orbits, robust at e → 0).
MeanElements osculating_angles(const StateEci& s, double mu_m3ps2);

/// States at the ascending sample times t_s (>= 0, from the epoch of s0), the burns applied
/// at their times (a sample at a burn time gets the post-burn state). Throws
/// std::invalid_argument on unsorted/negative times or burns, std::runtime_error when the
/// integration fails.
std::vector<StateEci> propagate_with_burns(const StateEci& s0, const std::vector<double>& t_s,
                                           const std::vector<TangentialBurn>& burns,
                                           const EarthModel& earth, const AdaptiveOptions& opt,
                                           std::vector<AppliedBurn>* applied = nullptr);

}  // namespace evade::formation
