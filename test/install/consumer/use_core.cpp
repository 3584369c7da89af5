// evade::core: elements -> state and the orbital period.
#include <cmath>
#include <cstdio>

#include <evade/core/elements.hpp>

int main() {
  const double mu = 3.986004418e14;
  const evade::StateEci s = evade::state_from_elements({7.0e6, 0.01, 0.9, 0.1, 0.2, 0.3}, mu);
  const double t = evade::orbital_period_s(7.0e6, mu);
  if (!(std::fabs(t - 5828.5) < 1.0) || !(s.r_eci_m.norm() > 6.9e6)) return 1;
  std::printf("core ok\n");
  return 0;
}
