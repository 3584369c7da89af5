// Keplerian elements read from input: the one reader and its one set of limits.
//
// Every input that gives an orbit as classical elements (a scenario's `orbit.*` for `evade
// propagate`, a screening catalog's `objects.N.*` or CSV rows, a formation's
// `formation.groups.N.<role>.*`) is checked against the limits declared here, once:
//
//   a_m                   (0, 1e10] m      a bound orbit, from LEO out past the Moon
//   e                     [0, 1)           an elliptic (bound) orbit
//   i_deg                 [0, 180] deg
//   raan_deg, argp_deg,
//   true/mean_anomaly_deg,
//   arg_lat_deg           [-360, 360] deg
//   perigee radius a (1 - e) > re_m        the orbit clears the Earth's surface
//
// A caller whose model needs tighter limits (paper 003's linearized formation model needs a
// near-circular orbit) checks them afterwards with its own message naming the reason; the
// reader and these limits stay one. The element conventions are those of
// evade/core/elements.hpp (Vallado, "Fundamentals of Astrodynamics and Applications", 2013).
#pragma once

#include <cstdint>
#include <string>

#include "evade/config/scenario.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/elements.hpp"

namespace evade::config {

/// The allowed values of one element: an interval, closed or open at either end.
struct ElementLimit {
  double lo;
  double hi;
  bool lo_open;  ///< true: lo itself is not allowed
  bool hi_open;  ///< true: hi itself is not allowed
  const char* unit;  ///< "m", "deg", "-" (dimensionless)
};

inline constexpr ElementLimit kSemiMajorAxisLimit{0.0, 1e10, true, false, "m"};
inline constexpr ElementLimit kEccentricityLimit{0.0, 1.0, false, true, "-"};
inline constexpr ElementLimit kInclinationLimit{0.0, 180.0, false, false, "deg"};
/// RAAN, argument of periapsis, true or mean anomaly, argument of latitude.
inline constexpr ElementLimit kAngleLimit{-360.0, 360.0, false, false, "deg"};

/// True when v is finite and inside the limit.
bool element_value_ok(const ElementLimit& limit, double v) noexcept;
/// The interval with its unit: "[0, 1)", "(0, 10000000000] m", "[0, 180] deg".
std::string element_interval_text(const ElementLimit& limit);
/// True when the perigee radius a (1 - e) is above the Earth's surface (> earth.re_m).
bool perigee_above_surface(double a_m, double e, const EarthModel& earth) noexcept;

/// Which angles place the body on its orbit, under which keys.
enum class OrbitPhase : std::uint8_t {
  kTrueAnomaly,         ///< argp_deg, true_anomaly_deg
  kMeanAnomaly,         ///< argp_deg, mean_anomaly_deg (converted to the true anomaly)
  kArgumentOfLatitude,  ///< arg_lat_deg, u = argp + true anomaly of a near-circular orbit:
                        ///< returned as argp_rad = 0, true_anomaly_rad = u; e is optional
                        ///< there (default 0, a circular orbit)
};

/// The elements at prefix + "a_m", "e", "i_deg", "raan_deg" and the phase's keys, each checked
/// against its limit, then the perigee against earth.re_m. Angles are returned in radians
/// (deg * kDegToRad). Throws ConfigError naming the key, the value and the allowed interval
/// ("<source>: key 'orbit.e' = '1.5' is invalid: expected a number in [0, 1)").
OrbitalElements read_elements(const Scenario& sc, const std::string& prefix,
                              const EarthModel& earth,
                              OrbitPhase phase = OrbitPhase::kTrueAnomaly);

}  // namespace evade::config
