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
//   bus_attacker flood URL RATE_HZ SECONDS [CHANNEL]
//       forged messages (the ground's key id, or the sensor's, a wrong MAC, ARSN = INT64_MAX)
//       at RATE_HZ for SECONDS, paced by CLOCK_MONOTONIC, on CHANNEL: plan (default), arm,
//       key_cmd, nav, angles, clock, or all (the six in turn); prints {"sent": N,
//       "achieved_hz": R}.
//   bus_attacker burst URL COUNT CHANNEL
//       COUNT forged messages on CHANNEL at once (no pacing); prints {"sent": N}.
//   bus_attacker forge-telemetry URL SECONDS
//       for SECONDS: answers every command it sees on the bus with forged acknowledgements
//       naming that very command (its key id, ARSN and MAC copied), one unsigned and one
//       signed with a key of its own, claiming it accepted and claiming it refused
//       (PLAN_REJECT_OVER_BUDGET); and publishes a forged status every 10 ms claiming the plan
//       accepted, armed, and every key's ARSN at INT64_MAX. Prints {"forged_acks": N,
//       "forged_status": M}.
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
#include "evade/auth/trailer.hpp"
#include "evade/evade_cmd_ack_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/evade_sim_clock_t.hpp"
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

// A forger's key: the given key id (the ground's 1, or a sensor's), not its key.
SigningKey forger_key(std::int32_t id) {
  SigningKey forged;
  forged.id = id;
  for (std::size_t i = 0; i < forged.key.size(); ++i) forged.key[i] = static_cast<std::uint8_t>(i * 7 + 3);
  return forged;
}

struct Forgery {
  const char* channel;
  std::vector<std::uint8_t> bytes;
};

// One forged message per channel: commands under the ground's key id, sensors under key id 2.
std::vector<Forgery> forgeries(const std::string& which) {
  const std::int64_t max = std::numeric_limits<std::int64_t>::max();
  const SigningKey cmd = forger_key(1);
  const SigningKey sensor = forger_key(2);
  std::vector<Forgery> all;
  evade_arm_t arm{};
  arm.utime = realtime_us();
  arm.armed = 0;
  evade_key_cmd_t kc{};
  kc.op = 2;
  kc.key_id = 1;
  evade_nav_state_t nav{};
  evade_angles_t ang{};
  evade_sim_clock_t tick{};
  if (which == "plan" || which == "all") all.push_back({kChanPlan, bytes_of(plan(max), kChanPlan, &cmd, max)});
  if (which == "arm" || which == "all") all.push_back({kChanArm, bytes_of(arm, kChanArm, &cmd, max)});
  if (which == "key_cmd" || which == "all") all.push_back({kChanKeyCmd, bytes_of(kc, kChanKeyCmd, &cmd, max)});
  if (which == "nav" || which == "all") all.push_back({kChanNav, bytes_of(nav, kChanNav, &sensor, max)});
  if (which == "angles" || which == "all") all.push_back({kChanAngles, bytes_of(ang, kChanAngles, &sensor, max)});
  if (which == "clock" || which == "all") all.push_back({kChanClock, bytes_of(tick, kChanClock, &sensor, max)});
  return all;
}

int flood(lcm_t* lcm, double rate_hz, double seconds, const std::string& which) {
  std::vector<Forgery> f = forgeries(which);
  if (f.empty() || !(rate_hz > 0.0)) return 2;
  const double t0 = mono_s();
  long n = 0;
  while (mono_s() - t0 < seconds) {
    const double due = t0 + static_cast<double>(n) / rate_hz;
    const double now = mono_s();
    if (due > now) sleep_s(due - now);
    Forgery& g = f[static_cast<std::size_t>(n) % f.size()];
    g.bytes[g.bytes.size() - 1] = static_cast<std::uint8_t>(n);  // a different MAC each time
    if (lcm_publish(lcm, g.channel, g.bytes.data(), static_cast<unsigned>(g.bytes.size())) != 0) return 1;
    ++n;
  }
  (void)std::printf("{\"sent\": %ld, \"achieved_hz\": %.1f}\n", n,
                    static_cast<double>(n) / (mono_s() - t0));
  return 0;
}

int burst(lcm_t* lcm, long count, const std::string& which) {
  std::vector<Forgery> f = forgeries(which);
  if (f.empty() || count < 0) return 2;
  for (long n = 0; n < count; ++n) {
    Forgery& g = f[static_cast<std::size_t>(n) % f.size()];
    g.bytes[g.bytes.size() - 1] = static_cast<std::uint8_t>(n);
    if (lcm_publish(lcm, g.channel, g.bytes.data(), static_cast<unsigned>(g.bytes.size())) != 0) return 1;
  }
  (void)std::printf("{\"sent\": %ld}\n", count);
  return 0;
}

// The forger of telemetry: it sees every command on the bus (no confidentiality) and answers it.
struct TelemetryForger {
  lcm_t* lcm;
  SigningKey own = forger_key(3);  // the node's telemetry key id, not its key
  long acks = 0;

  void answer(const lcm_recv_buf_t* rbuf, std::int8_t command) {
    auth::TrailerView t;
    const auto* d = static_cast<const std::uint8_t*>(rbuf->data);
    if (!auth::read_trailer(d, rbuf->data_size, &t)) return;
    for (int v = 0; v < 4; ++v) {
      evade_cmd_ack_t a{};
      a.utime = realtime_us();
      a.command = command;
      a.cmd_key_id = t.key_id;
      a.cmd_arsn = t.arsn;
      for (std::size_t i = 0; i < auth::kMacBytes; ++i) a.cmd_mac[i] = static_cast<std::int8_t>(t.mac[i]);
      const bool refuse = v % 2 == 1;
      a.outcome = refuse ? evade_cmd_ack_t::OUTCOME_REFUSED : evade_cmd_ack_t::OUTCOME_ACCEPTED;
      a.reason = refuse ? evade_cmd_ack_t::REASON_OUT_OF_RANGE : evade_cmd_ack_t::REASON_OK;
      a.detail = refuse ? evade_guidance_status_t::PLAN_REJECT_OVER_BUDGET : 0;
      a.node_arsn = std::numeric_limits<std::int64_t>::max();
      const std::vector<std::uint8_t> b = bytes_of(a, kChanCmdAck, v < 2 ? nullptr : &own, t.arsn);
      if (lcm_publish(lcm, kChanCmdAck, b.data(), static_cast<unsigned>(b.size())) == 0) ++acks;
    }
  }
  static void on_plan(const lcm_recv_buf_t* r, const char*, void* u) {
    static_cast<TelemetryForger*>(u)->answer(r, evade_cmd_ack_t::COMMAND_PLAN);
  }
  static void on_arm(const lcm_recv_buf_t* r, const char*, void* u) {
    static_cast<TelemetryForger*>(u)->answer(r, evade_cmd_ack_t::COMMAND_ARM);
  }
  static void on_key(const lcm_recv_buf_t* r, const char*, void* u) {
    static_cast<TelemetryForger*>(u)->answer(r, evade_cmd_ack_t::COMMAND_KEY_CMD);
  }
};

// A status claiming every plan accepted (any id the ground may choose) and armed.
std::vector<std::uint8_t> forged_status(long n) {
  evade_guidance_status_t s{};
  s.utime = realtime_us();
  s.seq = n;
  s.armed = 1;
  s.plan_ack_id = n;
  s.plan_ack_result = 0;
  s.auth_n_keys = 8;
  for (int i = 0; i < 8; ++i) {
    s.auth_key_id[i] = i + 1;
    s.auth_key_arsn[i] = std::numeric_limits<std::int64_t>::max();
  }
  return bytes_of(s, kChanStatus, nullptr, 0);
}

int forge_telemetry(lcm_t* lcm, double seconds) {
  TelemetryForger f{lcm};
  lcm_subscription_t* subs[3] = {lcm_subscribe(lcm, kChanPlan, &TelemetryForger::on_plan, &f),
                                 lcm_subscribe(lcm, kChanArm, &TelemetryForger::on_arm, &f),
                                 lcm_subscribe(lcm, kChanKeyCmd, &TelemetryForger::on_key, &f)};
  long status = 0;
  const double t0 = mono_s();
  while (mono_s() - t0 < seconds) {
    const std::vector<std::uint8_t> b = forged_status(status);
    if (lcm_publish(lcm, kChanStatus, b.data(), static_cast<unsigned>(b.size())) == 0) ++status;
    if (lcm_handle_timeout(lcm, 10) < 0) return 1;
  }
  for (lcm_subscription_t* s : subs) {
    if (s != nullptr) (void)lcm_unsubscribe(lcm, s);
  }
  (void)std::printf("{\"forged_acks\": %ld, \"forged_status\": %ld}\n", f.acks, status);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    (void)std::fprintf(stderr, "usage: bus_attacker attacks URL KEY RETIRED_KEY | flood URL RATE_HZ "
                       "SECONDS [CHANNEL] | burst URL COUNT CHANNEL | forge-telemetry URL SECONDS\n");
    return 2;
  }
  const std::string mode = argv[1];
  lcm_t* lcm = lcm_create(argv[2]);
  if (lcm == nullptr) return 1;
  int rc = 2;
  try {
    if (mode == "attacks" && argc == 5) rc = attacks(lcm, argv[3], argv[4]);
    if (mode == "flood" && (argc == 5 || argc == 6)) {
      rc = flood(lcm, std::atof(argv[3]), std::atof(argv[4]), argc == 6 ? argv[5] : "plan");
    }
    if (mode == "burst" && argc == 5) rc = burst(lcm, std::atol(argv[3]), argv[4]);
    if (mode == "forge-telemetry" && argc == 4) rc = forge_telemetry(lcm, std::atof(argv[3]));
  } catch (const std::exception& e) {
    (void)std::fprintf(stderr, "bus_attacker: %s\n", e.what());
    rc = 1;
  }
  lcm_destroy(lcm);
  return rc;
}
