// evade::dynamics: one Kepler period returns to the start.
#include <cstdio>

#include <evade/core/elements.hpp>
#include <evade/dynamics/kepler_propagator.hpp>

int main() {
  const double mu = 3.986004418e14;
  const evade::StateEci s0 = evade::state_from_elements({7.0e6, 0.01, 0.9, 0.1, 0.2, 0.3}, mu);
  const evade::StateEci s1 = evade::propagate_kepler(s0, evade::orbital_period_s(7.0e6, mu), mu);
  if (!((s1.r_eci_m - s0.r_eci_m).norm() < 1e-3)) return 1;
  std::printf("dynamics ok\n");
  return 0;
}
