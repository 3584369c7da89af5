// evade::lcm_types: an angles message encodes and decodes.
#include <cstdint>
#include <cstdio>

#include <evade/evade_angles_t.hpp>

int main() {
  evade::evade_angles_t a{};
  a.utime = 1;
  a.elevation_rad = 0.25;
  std::uint8_t buf[512];
  const int n = a.encode(buf, 0, sizeof(buf));
  evade::evade_angles_t b{};
  if (n <= 0 || b.decode(buf, 0, n) != n || b.elevation_rad != 0.25) return 1;
  std::printf("lcm_types ok\n");
  return 0;
}
