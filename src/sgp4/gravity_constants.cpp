// SGP4 gravity constant sets: Vallado et al. (2006), AIAA 2006-6753, "Gravitational
// constants" (WGS-72 old / WGS-72 / WGS-84 as the reference implementation defines them).
#include "evade/sgp4/gravity_constants.hpp"

#include <cmath>

namespace evade::sgp4 {

GravityConstants gravity_constants(GravityModel model) noexcept {
  GravityConstants c;
  switch (model) {
    case GravityModel::kWgs72Old:
      c.mu_km3ps2 = 398600.79964;
      c.radius_km = 6378.135;
      c.xke_per_min = 0.0743669161;
      c.j2 = 0.001082616;
      c.j3 = -0.00000253881;
      c.j4 = -0.00000165597;
      break;
    case GravityModel::kWgs72:
      c.mu_km3ps2 = 398600.8;
      c.radius_km = 6378.135;
      c.xke_per_min = 60.0 / std::sqrt(c.radius_km * c.radius_km * c.radius_km / c.mu_km3ps2);
      c.j2 = 0.001082616;
      c.j3 = -0.00000253881;
      c.j4 = -0.00000165597;
      break;
    case GravityModel::kWgs84:
      c.mu_km3ps2 = 398600.5;
      c.radius_km = 6378.137;
      c.xke_per_min = 60.0 / std::sqrt(c.radius_km * c.radius_km * c.radius_km / c.mu_km3ps2);
      c.j2 = 0.00108262998905;
      c.j3 = -0.00000253215306;
      c.j4 = -0.00000161098761;
      break;
  }
  c.tumin_min = 1.0 / c.xke_per_min;
  c.j3oj2 = c.j3 / c.j2;
  return c;
}

}  // namespace evade::sgp4
