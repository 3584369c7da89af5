// bus_attacker: an outside peer on the node's LCM bus, for the security probes over UDP
// multicast in a private network namespace (scripts/security_probes, docs/SECURITY.md
// "Probes"). Never used outside a private namespace.
//   bus_attacker attacks URL COMMAND_KEY_FILE RETIRED_KEY_FILE
//       one of each attack of docs/SECURITY.md "Probes", 50 ms apart: an unsigned plan; a plan
//       signed with an unknown key; a correctly signed plan (captured: signed with the ground's
//       key) and the same bytes again; a plan with the ARSN lowered; a plan signed for
//       EVADE_ARM sent on EVADE_BURN_PLAN; a plan signed with a retired key; a forged plan with
//       ARSN = INT64_MAX; an unsigned arm and an unsigned disarm; a spoofed nav (seq + 1, the
//       orbit rotated); a single unsigned angles message. Prints what it sent as JSON.
//   bus_attacker flood URL RATE_HZ SECONDS
//       forged plans (the ground's key id, a random MAC, ARSN = INT64_MAX) at RATE_HZ for
//       SECONDS, paced by CLOCK_MONOTONIC; prints {"sent": N, "achieved_hz": R}.
// Exit 1 on an LCM failure, 2 on bad arguments.
#include <time.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <lcm/lcm.h>

#include "evade/auth/key_file.hpp"
#include "evade/evade_angles_t.hpp"
#include "evade/evade_arm_t.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/signed_encode.hpp"

namespace {

using namespace evade;
using namespace evade::guidance_lcm;

std::int64_t realtime_us() {
  timespec ts{};
  (void)clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}
double mono_s() {
  timespec ts{};
  (void)clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
void sleep_s(double s) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(s);
  ts.tv_nsec = static_cast<long>((s - static_cast<double>(ts.tv_sec)) * 1e9);
  (void)nanosleep(&ts, nullptr);
}

SigningKey key_from(const std::string& file) {
  const auth::KeyRecord r = auth::read_key_file(file).at(0);
  SigningKey k;
  k.id = r.id;
  k.key = r.key;
  return k;
}

// A plan of one 0.5 m/s along-track impulse 3 s from now (the first row).
evade_burn_plan_t plan(std::int64_t id) {
  BurnPlan p;
  p.plan_id = id;
  p.n_impulses = 1;
  p.impulses[0].t_s = 3.0;
  p.impulses[0].dv_rsw_mps = Vec3(0.0, 0.5, 0.0);
  evade_burn_plan_t m{};
  const std::int64_t now = realtime_us();
  to_lcm(p, now, id, now, guidance::PlanFrame::kRsw, &m);
  return m;
}

template <typename Msg>
std::vector<std::uint8_t> bytes_of(Msg m, const char* sign_channel, const SigningKey* key,
                                   std::int64_t arsn) {
  std::vector<std::uint8_t> b(static_cast<std::size_t>(m.getEncodedSize()));
  const int n = key != nullptr ? encode_signed(&m, sign_channel, *key, arsn, b.data(),
                                               static_cast<int>(b.size()))
                               : m.encode(b.data(), 0, static_cast<int>(b.size()));
  b.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  return b;
}

int g_sent = 0;
bool send(lcm_t* lcm, const char* channel, const std::vector<std::uint8_t>& b) {
  ++g_sent;
  const bool ok = lcm_publish(lcm, channel, b.data(), static_cast<unsigned>(b.size())) == 0;
  sleep_s(0.05);
  return ok;
}

int attacks(lcm_t* lcm, const std::string& key_file, const std::string& retired_file) {
  const SigningKey ground = key_from(key_file);
  const SigningKey retired = key_from(retired_file);
  SigningKey unknown = ground;
  unknown.id = 999;
  SigningKey wrong = ground;
  wrong.key[0] ^= 0xff;
  const std::int64_t arsn = realtime_us();
  bool ok = true;
  ok = ok && send(lcm, kChanPlan, bytes_of(plan(101), kChanPlan, nullptr, 0));
  ok = ok && send(lcm, kChanPlan, bytes_of(plan(102), kChanPlan, &unknown, arsn));
  const std::vector<std::uint8_t> captured = bytes_of(plan(103), kChanPlan, &ground, arsn);
  ok = ok && send(lcm, kChanPlan, captured) && send(lcm, kChanPlan, captured);
  ok = ok && send(lcm, kChanPlan, bytes_of(plan(104), kChanPlan, &ground, arsn - 1));
  ok = ok && send(lcm, kChanPlan, bytes_of(plan(105), kChanArm, &ground, arsn + 1));
  ok = ok && send(lcm, kChanPlan, bytes_of(plan(106), kChanPlan, &retired, arsn + 2));
  ok = ok && send(lcm, kChanPlan, bytes_of(plan(std::numeric_limits<std::int64_t>::max()), kChanPlan,
                                           &wrong, std::numeric_limits<std::int64_t>::max()));
  evade_arm_t arm{};
  arm.utime = realtime_us();
  arm.seq = 1000;
  arm.armed = 0;
  ok = ok && send(lcm, kChanArm, bytes_of(arm, kChanArm, nullptr, 0));
  arm.armed = 1;
  arm.seq = 1001;
  ok = ok && send(lcm, kChanArm, bytes_of(arm, kChanArm, nullptr, 0));
  evade_nav_state_t nav{};
  nav.utime = realtime_us();
  nav.seq = 1000000;
  nav.valid = 1;
  nav.r_eci_m[0] = -7.0e6;
  nav.v_eci_mps[2] = 7546.0;
  ok = ok && send(lcm, kChanNav, bytes_of(nav, kChanNav, nullptr, 0));
  evade_angles_t a{};
  a.utime = realtime_us();
  a.seq = 1000000;
  a.valid = 1;
  a.sigma_angle_rad = 1e-5;
  ok = ok && send(lcm, kChanAngles, bytes_of(a, kChanAngles, nullptr, 0));
  // What a node with commands and sensors required counts (the captured plan's first copy is
  // the ground's own transmission: accepted).
  (void)std::printf("{\"sent\": %d, \"expect\": {\"unsigned\": 5, \"unknown_key\": 1, "
                    "\"replayed_arsn\": 2, \"bad_mac\": 2, \"retired_key\": 1, "
                    "\"authentic_plans\": 1}}\n", g_sent);
  return ok ? 0 : 1;
}

int flood(lcm_t* lcm, double rate_hz, double seconds) {
  SigningKey forged;
  forged.id = 1;  // the ground's key id, not its key
  for (std::size_t i = 0; i < forged.key.size(); ++i) forged.key[i] = static_cast<std::uint8_t>(i * 7 + 3);
  evade_burn_plan_t m = plan(std::numeric_limits<std::int64_t>::max());
  std::vector<std::uint8_t> b = bytes_of(m, kChanPlan, &forged, std::numeric_limits<std::int64_t>::max());
  const double t0 = mono_s();
  long n = 0;
  while (mono_s() - t0 < seconds) {
    const double due = t0 + static_cast<double>(n) / rate_hz;
    const double now = mono_s();
    if (due > now) sleep_s(due - now);
    b[b.size() - 1] = static_cast<std::uint8_t>(n);  // a different MAC each time
    if (lcm_publish(lcm, kChanPlan, b.data(), static_cast<unsigned>(b.size())) != 0) return 1;
    ++n;
  }
  (void)std::printf("{\"sent\": %ld, \"achieved_hz\": %.1f}\n", n,
                    static_cast<double>(n) / (mono_s() - t0));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    (void)std::fprintf(stderr, "usage: bus_attacker attacks URL KEY RETIRED_KEY | flood URL RATE_HZ SECONDS\n");
    return 2;
  }
  const std::string mode = argv[1];
  lcm_t* lcm = lcm_create(argv[2]);
  if (lcm == nullptr) return 1;
  int rc = 2;
  try {
    if (mode == "attacks" && argc == 5) rc = attacks(lcm, argv[3], argv[4]);
    if (mode == "flood" && argc == 5) rc = flood(lcm, std::atof(argv[3]), std::atof(argv[4]));
  } catch (const std::exception& e) {
    (void)std::fprintf(stderr, "bus_attacker: %s\n", e.what());
    rc = 1;
  }
  lcm_destroy(lcm);
  return rc;
}
