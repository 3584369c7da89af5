// evade::lcm_link: the exit code of an unacknowledged uplink.
#include <cstdio>

#include <evade/lcm_link/command_uplink.hpp>

int main() {
  if (evade::lcm_link::exit_code(evade::lcm_link::UplinkResult{}) != 4) return 1;
  std::printf("lcm_link ok\n");
  return 0;
}
