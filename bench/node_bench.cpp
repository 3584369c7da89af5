// Guidance node benchmarks (docs/PERFORMANCE.md).
//  BM_NodeCycleMemq: one full node cycle on memq:// with its inputs — publish nav + angles
//    (preallocated encode), drain, validate, step the paper-000 law, encode + publish command
//    and status, and the subscriber receiving the command: measurement -> command latency
//    in-process. Reports p50/p99 over the iterations as counters.
//  BM_MeasToCmdUdpm: measurement -> command round trip to a separate evade_guidance_node
//    process in lockstep over UDP multicast (publish nav + angles + tick, wait for the
//    command of that tick). Runs only when EVADE_BENCH_UDPM_URL is set, e.g. inside
//      unshare -rn sh -c 'ip link set lo up; ip link set lo multicast on;
//        ip route add 224.0.0.0/4 dev lo; URL="udpm://239.255.76.67:7667?ttl=0";
//        evade_guidance_node --lcm-url "$URL" --lockstep --quiet --stale-limit-s 60 &
//        EVADE_BENCH_UDPM_URL="$URL" node_bench --benchmark_filter=Udpm; kill %1'
//    prefixed with `chrt -f 50` (as root) both processes run SCHED_FIFO, which the namespace
//    alone refuses; docs/PERFORMANCE.md has both and udpm_latency_stages the stage split.
// Loop jitter (wake-up latency) and overruns at 50/200 Hz come from the node itself:
//   evade_guidance_node --lcm-url memq:// --rate-hz 200 --max-cycles 10000 --stats-json
#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include <lcm/lcm.h>

#include "evade/evade_angles_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/evade_sim_clock_t.hpp"
#include "evade/guidance/los_geometry.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/guidance_node.hpp"

namespace {

using namespace evade;
using namespace evade::guidance_lcm;

std::int64_t now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// A closing encounter (10 km, 1 km/s) so the law tracks and evades every cycle.
void inputs_at(std::int64_t t_us, std::int64_t seq, evade_nav_state_t* nav, evade_angles_t* a) {
  const double t = 1e-6 * static_cast<double>(t_us % 5000000);  // repeat every 5 s
  const Vec3 rel = Vec3(0.0, 10000.0, 2000.0) + Vec3(0.0, -1000.0, -150.0) * t;
  const guidance::LosAngles ang = guidance::los_angles_from_unit(rel.normalized());
  nav->utime = t_us;
  nav->seq = seq;
  nav->valid = true;
  nav->r_eci_m[0] = 7.0e6;
  nav->r_eci_m[1] = 7546.0 * t;
  nav->r_eci_m[2] = 0.0;
  nav->v_eci_mps[0] = 0.0;
  nav->v_eci_mps[1] = 7546.0;
  nav->v_eci_mps[2] = 0.0;
  std::memset(a, 0, sizeof(*a));
  a->utime = t_us;
  a->seq = seq;
  a->valid = true;
  a->elevation_rad = ang.elevation_rad;
  a->azimuth_rad = ang.azimuth_rad;
  a->sigma_angle_rad = 1e-4;
}

struct CmdWaiter {
  std::int64_t want_utime = -1;
  bool got = false;
  static void on_cmd(const lcm_recv_buf_t* rbuf, const char*, void* user) {
    auto* self = static_cast<CmdWaiter*>(user);
    evade_thrust_cmd_t m{};
    if (m.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) > 0 &&
        m.utime == self->want_utime)
      self->got = true;
  }
};

void report(benchmark::State& state, std::vector<double>& lat_us) {
  if (lat_us.empty()) return;
  std::sort(lat_us.begin(), lat_us.end());
  auto q = [&](double p) { return lat_us[static_cast<std::size_t>(p * (lat_us.size() - 1))]; };
  state.counters["p50_us"] = q(0.50);
  state.counters["p99_us"] = q(0.99);
  state.counters["max_us"] = lat_us.back();
}

void BM_NodeCycleMemq(benchmark::State& state) {
  lcm_t* lcm = lcm_create("memq://");
  NodeConfig cfg;
  cfg.guidance.stale_limit_s = 60.0;
  auto node_ptr = std::make_unique<GuidanceNode>(lcm, cfg);  // must die before lcm
  GuidanceNode& node = *node_ptr;
  CmdWaiter w;
  lcm_subscription_t* sub = lcm_subscribe(lcm, kChanCmd, &CmdWaiter::on_cmd, &w);
  std::uint8_t buf[512];
  std::vector<double> lat;
  lat.reserve(1 << 20);
  std::int64_t t = 1000000, seq = 0;
  for (auto _ : state) {
    evade_nav_state_t nav{};
    evade_angles_t a{};
    inputs_at(t, ++seq, &nav, &a);
    const std::int64_t t0 = now_ns();
    int n = nav.encode(buf, 0, sizeof(buf));
    lcm_publish(lcm, kChanNav, buf, static_cast<unsigned>(n));
    n = a.encode(buf, 0, sizeof(buf));
    lcm_publish(lcm, kChanAngles, buf, static_cast<unsigned>(n));
    node.drain();
    node.run_cycle(t);
    w.want_utime = t;
    w.got = false;
    while (!w.got && lcm_handle_timeout(lcm, 0) > 0) {
    }
    const std::int64_t t1 = now_ns();
    if (lat.size() < lat.capacity()) lat.push_back(1e-3 * static_cast<double>(t1 - t0));
    t += 20000;
  }
  report(state, lat);
  lcm_unsubscribe(lcm, sub);
  node_ptr.reset();
  lcm_destroy(lcm);
}
BENCHMARK(BM_NodeCycleMemq)->Iterations(10000)->Unit(benchmark::kMicrosecond);

void BM_MeasToCmdUdpm(benchmark::State& state) {
  const char* url = std::getenv("EVADE_BENCH_UDPM_URL");
  if (url == nullptr) {
    state.SkipWithError("set EVADE_BENCH_UDPM_URL and run a lockstep node (see file comment)");
    for (auto _ : state) {
    }
    return;
  }
  lcm_t* lcm = lcm_create(url);
  CmdWaiter w;
  lcm_subscription_t* sub = lcm_subscribe(lcm, kChanCmd, &CmdWaiter::on_cmd, &w);
  std::uint8_t buf[512];
  std::vector<double> lat;
  lat.reserve(1 << 20);
  std::int64_t t = 1000000, seq = 0;
  long timeouts = 0;
  for (auto _ : state) {
    evade_nav_state_t nav{};
    evade_angles_t a{};
    inputs_at(t, ++seq, &nav, &a);
    evade_sim_clock_t tick{};
    tick.utime = t;
    tick.seq = seq;
    const std::int64_t t0 = now_ns();
    int n = nav.encode(buf, 0, sizeof(buf));
    lcm_publish(lcm, kChanNav, buf, static_cast<unsigned>(n));
    n = a.encode(buf, 0, sizeof(buf));
    lcm_publish(lcm, kChanAngles, buf, static_cast<unsigned>(n));
    n = tick.encode(buf, 0, sizeof(buf));
    lcm_publish(lcm, kChanClock, buf, static_cast<unsigned>(n));
    w.want_utime = t;
    w.got = false;
    while (!w.got) {
      if (lcm_handle_timeout(lcm, 1000) <= 0) {
        ++timeouts;
        break;
      }
    }
    const std::int64_t t1 = now_ns();
    if (w.got && lat.size() < lat.capacity()) lat.push_back(1e-3 * static_cast<double>(t1 - t0));
    t += 20000;
  }
  report(state, lat);
  state.counters["timeouts"] = static_cast<double>(timeouts);
  lcm_unsubscribe(lcm, sub);
  lcm_destroy(lcm);
}
BENCHMARK(BM_MeasToCmdUdpm)->Iterations(10000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
