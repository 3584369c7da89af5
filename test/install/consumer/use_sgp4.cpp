// evade::sgp4: the WGS-72 constants SGP4 uses.
#include <cmath>
#include <cstdio>

#include <evade/sgp4/gravity_constants.hpp>

int main() {
  const evade::sgp4::GravityConstants g = evade::sgp4::gravity_constants(evade::sgp4::GravityModel::kWgs72);
  if (!(std::fabs(g.mu_km3ps2 - 398600.8) < 1e-6)) return 1;
  std::printf("sgp4 ok\n");
  return 0;
}
