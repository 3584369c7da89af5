// evade::sim: the median (percentile 50) of the Monte Carlo summary.
#include <cstdio>

#include <evade/sim/monte_carlo.hpp>

int main() {
  if (evade::sim::percentile({1.0, 2.0, 3.0}, 50.0) != 2.0) return 1;
  std::printf("sim ok\n");
  return 0;
}
