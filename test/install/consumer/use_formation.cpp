// evade::formation: the tangential burn for a 100 m raise of a 7000 km circular orbit.
#include <cmath>
#include <cstdio>

#include <evade/core/elements.hpp>
#include <evade/formation/burn_propagation.hpp>

int main() {
  const double mu = 3.986004418e14;
  const evade::StateEci s = evade::state_from_elements({7.0e6, 0.0, 0.9, 0.0, 0.0, 0.0}, mu);
  const double dv = evade::formation::tangential_dv_for_delta_a(s, 100.0, mu);
  if (!(dv > 0.05 && dv < 0.06)) return 1;
  std::printf("formation ok\n");
  return 0;
}
