// evade::observability: an objective by name.
#include <cstdio>

#include <evade/observability/planner.hpp>

int main() {
  (void)evade::observability::parse_objective("paper");
  std::printf("observability ok\n");
  return 0;
}
