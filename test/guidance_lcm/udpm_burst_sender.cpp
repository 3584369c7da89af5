// udpm_burst_sender: the outside sender of the receive-buffer regression test
// (recv_buffer_test.cpp, docs/GUIDANCE_NODE.md NODE-IN-6). Runs inside the test's private
// network namespace; never used elsewhere.
//   udpm_burst_sender wait-node URL TIMEOUT_S
//       exit 0 once the node's first evade_guidance_status_t arrives (it is up and subscribed)
//   udpm_burst_sender burst URL N BIG_BYTES
//       publish N valid input messages as fast as possible, alternating evade_angles_t and
//       evade_nav_state_t (each channel's seq 1, 2, ...; stamped now), then, if BIG_BYTES > 0,
//       one message of BIG_BYTES bytes on EVADE_ANGLES (LCM fragments it); no subscription, so
//       this process has no receive socket of its own
//   udpm_burst_sender wait-received URL N TIMEOUT_S
//       exit 0 once the node's status reports n_received >= N; exit 1 when that does not
//       happen within TIMEOUT_S or n_received stops moving for 2 s; prints n_received
// Exit 1 on a timeout or an LCM failure, 2 on bad arguments.
#include <time.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <lcm/lcm.h>

#include "evade/evade_angles_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/guidance_lcm/channels.hpp"

namespace {

using namespace evade;
using namespace evade::guidance_lcm;

std::int64_t realtime_us() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

struct StatusWatch {
  bool seen = false;
  std::int64_t n_received = -1;
  static void on_status(const lcm_recv_buf_t* rbuf, const char*, void* user) {
    auto* self = static_cast<StatusWatch*>(user);
    evade_guidance_status_t m{};
    if (m.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) > 0) {
      self->seen = true;
      self->n_received = m.n_received;
    }
  }
};

// Waits up to timeout_s for a status with n_received >= want (want < 0: any status). Gives up
// early (exit 1) when n_received has not moved for kSettleUs: the node has drained all it got.
int wait_status(lcm_t* lcm, std::int64_t want, double timeout_s) {
  constexpr std::int64_t kSettleUs = 2000000;
  StatusWatch w;
  lcm_subscription_t* sub = lcm_subscribe(lcm, kChanStatus, &StatusWatch::on_status, &w);
  if (sub == nullptr) return 1;
  const std::int64_t end = realtime_us() + static_cast<std::int64_t>(timeout_s * 1e6);
  std::int64_t last_n = -1, last_change = realtime_us();
  while (realtime_us() < end) {
    if (lcm_handle_timeout(lcm, 100) < 0) break;
    if (w.seen && (want < 0 || w.n_received >= want)) {
      std::printf("%lld\n", static_cast<long long>(w.n_received));
      return 0;
    }
    if (w.n_received != last_n) {
      last_n = w.n_received;
      last_change = realtime_us();
    } else if (w.seen && realtime_us() - last_change > kSettleUs) {
      break;
    }
  }
  std::fprintf(stderr, "udpm_burst_sender: status %s, n_received %lld, wanted %lld\n",
               w.seen ? "seen" : "never seen", static_cast<long long>(w.n_received),
               static_cast<long long>(want));
  return 1;
}

void fill_angles(std::int64_t seq, evade_angles_t* a) {
  *a = evade_angles_t{};
  a->utime = realtime_us();
  a->seq = seq;
  a->valid = true;
  a->elevation_rad = 0.2;
  a->azimuth_rad = 1.0;
  a->sigma_angle_rad = 1e-4;
}

void fill_nav(std::int64_t seq, evade_nav_state_t* n) {
  *n = evade_nav_state_t{};
  n->utime = realtime_us();
  n->seq = seq;
  n->valid = true;
  n->r_eci_m[0] = 7.0e6;
  n->v_eci_mps[1] = 7546.0;
}

int burst(lcm_t* lcm, long n, long big_bytes) {
  std::vector<std::uint8_t> buf(512);
  for (long i = 0; i < n; ++i) {
    const std::int64_t seq = i / 2 + 1;
    int len = 0;
    const char* chan = nullptr;
    if (i % 2 == 0) {
      evade_angles_t a;
      fill_angles(seq, &a);
      len = a.encode(buf.data(), 0, static_cast<int>(buf.size()));
      chan = kChanAngles;
    } else {
      evade_nav_state_t nav;
      fill_nav(seq, &nav);
      len = nav.encode(buf.data(), 0, static_cast<int>(buf.size()));
      chan = kChanNav;
    }
    if (len <= 0 || lcm_publish(lcm, chan, buf.data(), static_cast<unsigned>(len)) != 0) {
      std::fprintf(stderr, "udpm_burst_sender: publish %ld of %ld failed\n", i + 1, n);
      return 1;
    }
  }
  if (big_bytes > 0) {
    std::vector<std::uint8_t> big(static_cast<std::size_t>(big_bytes), 0x5a);
    if (lcm_publish(lcm, kChanAngles, big.data(), static_cast<unsigned>(big.size())) != 0) {
      std::fprintf(stderr, "udpm_burst_sender: publish of the %ld B message failed\n", big_bytes);
      return 1;
    }
  }
  std::printf("%ld\n", n + (big_bytes > 0 ? 1 : 0));
  return 0;
}

bool to_long(const char* s, long lo, long hi, long* out) {
  char* end = nullptr;
  const long v = std::strtol(s, &end, 10);
  if (end == s || *end != '\0' || v < lo || v > hi) return false;
  *out = v;
  return true;
}

bool parse_args(const std::string& cmd, int argc, char** argv, long* a, long* b) {
  if (cmd == "wait-node") return argc == 4 && to_long(argv[3], 1, 600, a);
  if (cmd == "burst")
    return argc == 5 && to_long(argv[3], 0, 1000000, a) && to_long(argv[4], 0, 64L << 20, b);
  if (cmd == "wait-received")
    return argc == 5 && to_long(argv[3], 0, 100000000, a) && to_long(argv[4], 1, 600, b);
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string cmd = argc > 1 ? argv[1] : "";
  long a = 0, b = 0;
  if (!parse_args(cmd, argc, argv, &a, &b)) {
    std::fprintf(stderr, "usage: udpm_burst_sender wait-node URL TIMEOUT_S | burst URL N "
                         "BIG_BYTES | wait-received URL N TIMEOUT_S\n");
    return 2;
  }
  lcm_t* lcm = lcm_create(argv[2]);
  if (lcm == nullptr) {
    std::fprintf(stderr, "udpm_burst_sender: cannot open LCM URL '%s'\n", argv[2]);
    return 1;
  }
  int rc = 1;
  if (cmd == "wait-node") rc = wait_status(lcm, -1, static_cast<double>(a));
  if (cmd == "burst") rc = burst(lcm, a, b);
  if (cmd == "wait-received") rc = wait_status(lcm, a, static_cast<double>(b));
  lcm_destroy(lcm);
  return rc;
}
