// Classical orbital elements <-> Cartesian ECI state, and the Kepler equation.
//
// Reference: Vallado, "Fundamentals of Astrodynamics and Applications", 4th ed., algorithms
// 9 (RV2COE) and 10 (COE2RV); Kepler solver after Markley (1995) start + Newton/Halley.
//
// Singular cases are given defined, finite values instead of NaN:
//  * circular (e < kCircularTolerance): argp_rad = 0 and true_anomaly_rad is the argument of
//    latitude u measured from the ascending node;
//  * equatorial (sin i < kEquatorialTolerance, i = 0 or 180 deg): raan_rad = 0 and argp_rad
//    is measured from the ECI x axis (longitude of periapsis, sign following the motion);
//  * circular and equatorial: raan_rad = argp_rad = 0 and true_anomaly_rad is the true
//    longitude.
// Hyperbolic and parabolic orbits (e >= 1) are rejected: evade works with bound orbits.
#pragma once

#include "evade/core/state.hpp"

namespace evade {

inline constexpr double kCircularTolerance = 1e-11;
inline constexpr double kEquatorialTolerance = 1e-11;

struct OrbitalElements {
  double a_m = 0.0;               ///< semi-major axis [m]
  double e = 0.0;                 ///< eccentricity [-], 0 <= e < 1
  double i_rad = 0.0;             ///< inclination [rad], 0..pi
  double raan_rad = 0.0;          ///< right ascension of the ascending node [rad], 0..2pi
  double argp_rad = 0.0;          ///< argument of periapsis [rad], 0..2pi
  double true_anomaly_rad = 0.0;  ///< true anomaly [rad], 0..2pi
};

/// Wraps an angle to [0, 2pi).
double wrap_two_pi(double angle_rad);
/// Wraps an angle to [-pi, pi).
double wrap_pi(double angle_rad);

/// Solves Kepler's equation M = E - e sin E for E (elliptic, 0 <= e < 1). Converges to
/// machine precision in at most a few iterations for every e < 1 (bounded loop).
double eccentric_from_mean_anomaly(double mean_anomaly_rad, double e);
double true_from_eccentric_anomaly(double eccentric_anomaly_rad, double e);
double eccentric_from_true_anomaly(double true_anomaly_rad, double e);
double mean_from_true_anomaly(double true_anomaly_rad, double e);
double true_from_mean_anomaly(double mean_anomaly_rad, double e);

/// Mean motion sqrt(mu/a^3) [rad/s] and period [s].
double mean_motion_radps(double a_m, double mu_m3ps2);
double orbital_period_s(double a_m, double mu_m3ps2);
/// Two-body period of the orbit through state s (vis-viva semi-major axis) [s]; +infinity for
/// an unbound (parabolic or hyperbolic) state.
double orbital_period_s(const StateEci& s, double mu_m3ps2);

/// Elements -> ECI state. Throws std::invalid_argument for a <= 0, e outside [0,1), NaN.
StateEci state_from_elements(const OrbitalElements& oe, double mu_m3ps2);
/// ECI state -> elements (see the conventions above). Throws std::invalid_argument for a
/// non-finite state, zero position, or an unbound (e >= 1) orbit.
OrbitalElements elements_from_state(const StateEci& s, double mu_m3ps2);

}  // namespace evade
