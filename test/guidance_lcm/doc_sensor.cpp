// doc_sensor: a sensor written from the message definitions alone, as a flight-software
// integrator would write one (docs/INTEGRATION.md "Connecting your own sensor"): it publishes
// evade_nav_state_t and evade_angles_t at RATE_HZ for SECONDS, each stamped as
// lcm_types/evade_angles_t.lcm says — utime = the time of validity in microseconds since the
// Unix epoch on CLOCK_REALTIME, seq +1 per message — with the security trailer left zero (the
// node's default policy does not require signed sensors). The geometry is a fixed LOS and a
// circular orbit; the test only asks whether the node uses what it is sent.
//   doc_sensor URL RATE_HZ SECONDS    prints {"published": N}
#include <time.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include <lcm/lcm.h>

#include "evade/evade_angles_t.hpp"
#include "evade/evade_nav_state_t.hpp"

namespace {

std::int64_t utime_now() {  // the time base of every utime (lcm_types/*.lcm)
  timespec ts{};
  (void)clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

template <typename Msg>
bool publish(lcm_t* lcm, const char* channel, const Msg& m) {
  std::uint8_t buf[512];
  const int n = m.encode(buf, 0, sizeof(buf));
  return n > 0 && lcm_publish(lcm, channel, buf, static_cast<unsigned>(n)) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    (void)std::fprintf(stderr, "usage: doc_sensor URL RATE_HZ SECONDS\n");
    return 2;
  }
  const double rate_hz = std::atof(argv[2]);
  const double seconds = std::atof(argv[3]);
  if (!(rate_hz > 0.0 && rate_hz <= 1000.0 && seconds > 0.0 && seconds <= 600.0)) return 2;
  lcm_t* lcm = lcm_create(argv[1]);
  if (lcm == nullptr) return 1;
  const long n = std::lround(rate_hz * seconds);
  long published = 0;
  for (long k = 1; k <= n; ++k) {
    evade::evade_nav_state_t nav{};
    nav.utime = utime_now();
    nav.seq = k;
    nav.valid = 1;
    nav.r_eci_m[0] = 7.0e6;
    nav.v_eci_mps[1] = 7546.0;
    evade::evade_angles_t a{};
    a.utime = nav.utime;
    a.seq = k;
    a.valid = 1;
    a.elevation_rad = 0.1;
    a.azimuth_rad = 1.0;
    a.sigma_angle_rad = 1e-4;
    published += publish(lcm, "EVADE_NAV", nav) ? 1 : 0;
    published += publish(lcm, "EVADE_ANGLES", a) ? 1 : 0;
    timespec d{};
    d.tv_nsec = static_cast<long>(1e9 / rate_hz);
    (void)nanosleep(&d, nullptr);
  }
  lcm_destroy(lcm);
  (void)std::printf("{\"published\": %ld}\n", published);
  return published == 2 * n ? 0 : 1;
}
