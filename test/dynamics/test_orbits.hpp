// Orbits shared by the dynamics tests, built from perifocal geometry (independent of the
// core element conversions).
#pragma once

#include <Eigen/Geometry>
#include <cmath>

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"

namespace evade::test {

/// State at true anomaly nu on the orbit (a, e, i, raan, argp).
inline StateEci orbit_state(double a_m, double e, double i_rad, double raan_rad, double argp_rad,
                            double nu_rad, double mu_m3ps2 = kEarthDefault.mu_m3ps2) {
  const double p = a_m * (1.0 - e * e);
  const double r = p / (1.0 + e * std::cos(nu_rad));
  const Vec3 r_pf(r * std::cos(nu_rad), r * std::sin(nu_rad), 0.0);
  const double k = std::sqrt(mu_m3ps2 / p);
  const Vec3 v_pf(-k * std::sin(nu_rad), k * (e + std::cos(nu_rad)), 0.0);
  const Mat3 rot = (Eigen::AngleAxisd(raan_rad, Vec3::UnitZ()) *
                    Eigen::AngleAxisd(i_rad, Vec3::UnitX()) *
                    Eigen::AngleAxisd(argp_rad, Vec3::UnitZ()))
                       .toRotationMatrix();
  return {rot * r_pf, rot * v_pf};
}

/// The e = 0.1, a = 7500 km LEO orbit of the accuracy requirement (perigee 6750 km).
inline StateEci leo_e01() {
  return orbit_state(7500e3, 0.1, 30.0 * kDegToRad, 40.0 * kDegToRad, 60.0 * kDegToRad, 0.3);
}

inline double specific_energy(const StateEci& s, double mu) {
  return 0.5 * s.v_eci_mps.squaredNorm() - mu / s.r_eci_m.norm();
}

}  // namespace evade::test
