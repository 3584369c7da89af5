// Gravity accelerations (two-body, J2) and the J2 secular rates of the mean elements.
//
// J2 acceleration: Vallado 4th ed. eq. 8-30 (zonal J2 in Cartesian ECI form).
// Secular rates: Vallado eq. 9-41 (RAAN), 9-42 (argument of perigee), mean anomaly
// n_bar = n (1 + 3/4 J2 (Re/p)^2 sqrt(1-e^2) (2 - 3 sin^2 i)).
#pragma once

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"

namespace evade {

enum class GravityModel { kTwoBody, kTwoBodyJ2 };

/// Point-mass acceleration -mu r / |r|^3 [m/s^2].
Vec3 accel_two_body_eci_mps2(const Vec3& r_eci_m, double mu_m3ps2);
/// The J2 perturbing acceleration only [m/s^2].
Vec3 accel_j2_eci_mps2(const Vec3& r_eci_m, const EarthModel& earth);
/// Total acceleration of the chosen model [m/s^2].
Vec3 accel_eci_mps2(const Vec3& r_eci_m, GravityModel model, const EarthModel& earth);
/// d/dt [r; v] = [v; a(r)] for the chosen model.
Vec6 orbit_derivative(const Vec6& x_eci, GravityModel model, const EarthModel& earth);

struct J2SecularRates {
  double raan_dot_radps = 0.0;           ///< dOmega/dt [rad/s]
  double argp_dot_radps = 0.0;           ///< domega/dt [rad/s]
  double mean_anomaly_dot_radps = 0.0;   ///< dM/dt including the J2 correction [rad/s]
  double arg_latitude_dot_radps = 0.0;   ///< d(omega+M)/dt [rad/s]
};
J2SecularRates j2_secular_rates(double a_m, double e, double i_rad, const EarthModel& earth);

}  // namespace evade
