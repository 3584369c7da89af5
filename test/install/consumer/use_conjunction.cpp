// evade::conjunction: the two-body gravity bound at 7000 km is mu / r^2.
#include <cmath>
#include <cstdio>

#include <evade/conjunction/arc_bounds.hpp>

int main() {
  const evade::EarthModel earth;
  const double g = evade::conjunction::gravity_bound_mps2(7.0e6, evade::GravityModel::kTwoBody, earth);
  if (!(g >= earth.mu_m3ps2 / 4.9e13 * (1.0 - 1e-12))) return 1;
  std::printf("conjunction ok\n");
  return 0;
}
