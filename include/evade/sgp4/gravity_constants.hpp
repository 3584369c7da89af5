// SGP4 gravity constant sets, as defined by Vallado, Crawford, Hujsak & Kelso (2006),
// "Revisiting Spacetrack Report #3", AIAA 2006-6753, section "Gravitational constants"
// (their getgravconst): WGS-72 is the set two-line element sets are fitted with, WGS-72 "old"
// the original STR#3 xke, WGS-84 for comparison only. Units are the theory's own (km, min).
#pragma once

namespace evade::sgp4 {

enum class GravityModel { kWgs72Old, kWgs72, kWgs84 };

struct GravityConstants {
  double tumin_min = 0.0;      ///< minutes in one canonical time unit (1 / xke)
  double mu_km3ps2 = 0.0;      ///< Earth gravitational parameter
  double radius_km = 0.0;      ///< equatorial radius, the theory's distance unit
  double xke_per_min = 0.0;    ///< sqrt(mu / radius^3) in 1/min
  double j2 = 0.0;
  double j3 = 0.0;
  double j4 = 0.0;
  double j3oj2 = 0.0;
};

/// The constants of one set (WGS-72 is the one element sets are made with).
GravityConstants gravity_constants(GravityModel model) noexcept;

}  // namespace evade::sgp4
