// TEME (SGP4's true-equator, mean-equinox frame) -> J2000 mean equator and equinox (the
// project's ECI axes; GCRF differs from it by the ~20 mas frame bias, not modelled), by the
// chain TEME -> TOD -> MOD -> J2000 of Vallado, Crawford, Hujsak & Kelso (2006), AIAA
// 2006-6753, sec. "TEME": r_tod = R3(-Eq_eq) r_teme with Eq_eq = dpsi cos(eps_mean) (the
// geometric equation of the equinoxes, no kinematic terms, as for TEME), r_mod = N^T r_tod
// (IAU-1980 nutation truncated to its 10 largest terms), r_j2000 = P^T r_mod (IAU-1976
// precession, zeta/theta/z). Accuracy and what is neglected: docs/ASSESSMENT.md.
#pragma once

#include <Eigen/Core>

namespace evade::sgp4 {

/// IAU-1980 nutation (truncated) at TT Julian centuries since J2000.
struct Nutation {
  double dpsi_rad = 0.0;      ///< nutation in longitude
  double deps_rad = 0.0;      ///< nutation in obliquity
  double eps_mean_rad = 0.0;  ///< IAU-1976 mean obliquity of date
};
Nutation nutation_iau80(double t_tt_centuries) noexcept;

/// The rotation r_j2000 = M r_teme at an instant (UTC seconds since J2000; UTC stands in for
/// TT here: the 69 s between them moves precession by 1e-4 arcsec, 3 mm at 7000 km).
Eigen::Matrix3d teme_to_j2000_matrix(double t_utc_s_since_j2000) noexcept;

/// Rotates a TEME state into J2000. The frames' relative rotation rate (precession and
/// nutation, ~1e-11 rad/s) is neglected in the velocity: below 1e-7 m/s at LEO.
void teme_to_j2000(double t_utc_s_since_j2000, const Eigen::Vector3d& r_teme_m,
                   const Eigen::Vector3d& v_teme_mps, Eigen::Vector3d& r_j2000_m,
                   Eigen::Vector3d& v_j2000_mps) noexcept;

}  // namespace evade::sgp4
