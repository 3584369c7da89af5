// Physical constants and the Earth model. SI units throughout.
//
// Defaults are WGS-84 / EGM-96 values (μ = 3.986004418e14 m³/s², J2 = 1.08262668e-3,
// Re = 6 378 137 m). Papers that use other values (paper 001: μ = 3.986005e14,
// Re = 6 371 110 m; paper 002: μ = 3.986005e14) pass their own EarthModel: nothing in
// evade reads a global constant where a model can be passed.
#pragma once

namespace evade {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;
inline constexpr double kDegToRad = kPi / 180.0;
inline constexpr double kRadToDeg = 180.0 / kPi;
inline constexpr double kSecondsPerDay = 86400.0;

/// Central-body gravity model: point mass plus the J2 zonal harmonic.
struct EarthModel {
  double mu_m3ps2 = 3.986004418e14;  ///< gravitational parameter [m^3/s^2]
  double j2 = 1.08262668e-3;         ///< second zonal harmonic [-]
  double re_m = 6378137.0;           ///< equatorial radius used with J2 [m]
};

/// WGS-84 / EGM-96 defaults.
inline constexpr EarthModel kEarthDefault{};

}  // namespace evade
