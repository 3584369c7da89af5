// evade::guidance: the law's parameter table and a LOS angle.
#include <cmath>
#include <cstdio>

#include <evade/guidance/guidance_params.hpp>
#include <evade/guidance/los_geometry.hpp>

int main() {
  const evade::guidance::LosAngles a = evade::guidance::los_angles_from_unit(evade::Vec3(0.0, 0.0, 1.0));
  if (evade::guidance::guidance_params().size() == 0 || !(std::fabs(a.elevation_rad - M_PI / 2) < 1e-12)) return 1;
  std::printf("guidance ok\n");
  return 0;
}
