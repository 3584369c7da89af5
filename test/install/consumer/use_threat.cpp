// evade::threat: the geometry parameter table.
#include <cstdio>

#include <evade/threat/threat_params.hpp>

int main() {
  if (evade::threat::threat_geometry_params().size() == 0) return 1;
  std::printf("threat ok\n");
  return 0;
}
