// Gravity accelerations (two-body, J2) and the J2 secular rates of the mean elements.
//
// Reference: Vallado, "Fundamentals of Astrodynamics and Applications", 4th ed.
//  * two-body acceleration, eq. 1-14: a = -mu r / r^3;
//  * J2 acceleration in Cartesian ECI form, eq. 8-30;
//  * secular rates, eq. 9-41 (RAAN), 9-42 (argument of perigee) and the mean-anomaly rate
//    n_bar = n (1 + 3/4 J2 (Re/p)^2 sqrt(1-e^2) (2 - 3 sin^2 i)) (with
//    2 - 3 sin^2 i = (3 cos^2 i - 1)).
#include "evade/dynamics/gravity.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace evade {

Vec3 accel_two_body_eci_mps2(const Vec3& r_eci_m, double mu_m3ps2) {
  const double r2 = r_eci_m.squaredNorm();
  const double r = std::sqrt(r2);
  return (-mu_m3ps2 / (r2 * r)) * r_eci_m;  // Vallado eq. 1-14
}

Vec3 accel_j2_eci_mps2(const Vec3& r_eci_m, const EarthModel& earth) {
  const double r2 = r_eci_m.squaredNorm();
  const double r = std::sqrt(r2);
  const double z2_over_r2 = r_eci_m.z() * r_eci_m.z() / r2;
  // Vallado eq. 8-30: a_J2 = -3/2 J2 mu Re^2 / r^5 [x(1-5z^2/r^2), y(1-5z^2/r^2), z(3-5z^2/r^2)].
  const double k = -1.5 * earth.j2 * earth.mu_m3ps2 * earth.re_m * earth.re_m / (r2 * r2 * r);
  const double xy = 1.0 - 5.0 * z2_over_r2;
  return {k * r_eci_m.x() * xy, k * r_eci_m.y() * xy, k * r_eci_m.z() * (3.0 - 5.0 * z2_over_r2)};
}

Vec3 accel_eci_mps2(const Vec3& r_eci_m, GravityModel model, const EarthModel& earth) {
  Vec3 a = accel_two_body_eci_mps2(r_eci_m, earth.mu_m3ps2);
  if (model == GravityModel::kTwoBodyJ2) a += accel_j2_eci_mps2(r_eci_m, earth);
  return a;
}

Vec6 orbit_derivative(const Vec6& x_eci, GravityModel model, const EarthModel& earth) {
  Vec6 dx;
  dx << x_eci.tail<3>(), accel_eci_mps2(x_eci.head<3>(), model, earth);
  return dx;
}

J2SecularRates j2_secular_rates(double a_m, double e, double i_rad, const EarthModel& earth) {
  if (!(a_m > 0.0) || !(e >= 0.0 && e < 1.0) || !std::isfinite(i_rad)) {
    throw std::invalid_argument("j2_secular_rates: need a_m > 0 and 0 <= e < 1 (a_m=" +
                                std::to_string(a_m) + ", e=" + std::to_string(e) + ")");
  }
  const double n = std::sqrt(earth.mu_m3ps2 / (a_m * a_m * a_m));
  const double p = a_m * (1.0 - e * e);
  const double k = earth.j2 * (earth.re_m / p) * (earth.re_m / p);
  const double s2 = std::sin(i_rad) * std::sin(i_rad);
  J2SecularRates rates;
  rates.raan_dot_radps = -1.5 * n * k * std::cos(i_rad);                 // Vallado eq. 9-41
  rates.argp_dot_radps = 0.75 * n * k * (4.0 - 5.0 * s2);                // Vallado eq. 9-42
  rates.mean_anomaly_dot_radps =
      n * (1.0 + 0.75 * k * std::sqrt(1.0 - e * e) * (2.0 - 3.0 * s2));  // n_bar
  rates.arg_latitude_dot_radps = rates.argp_dot_radps + rates.mean_anomaly_dot_radps;
  return rates;
}

}  // namespace evade
