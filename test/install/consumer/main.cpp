// An outside project using the installed evade package.
#include <cmath>
#include <cstdio>

#include <evade/core/elements.hpp>
#include <evade/dynamics/kepler_propagator.hpp>

int main() {
  const double mu = 3.986004418e14;
  const evade::StateEci s0 = evade::state_from_elements({7.0e6, 0.01, 0.9, 0.1, 0.2, 0.3}, mu);
  const double period_s = evade::orbital_period_s(7.0e6, mu);
  const evade::StateEci s1 = evade::propagate_kepler(s0, period_s, mu);
  const double err_m = (s1.r_eci_m - s0.r_eci_m).norm();
  std::printf("one period later the position differs by %.3e m\n", err_m);
  if (!(err_m < 1e-3)) return 1;
  std::printf("consumer ok\n");
  return 0;
}
