// Authentication benchmarks (docs/PERFORMANCE.md "Authentication", docs/SECURITY.md AUTH-6).
//  BM_MacVerifyPlan: auth::mac_valid on a signed evade_burn_plan_t (629 B): the HMAC-SHA-256
//    the node computes for every message on a channel that must be signed (a forged plan costs
//    exactly this before it is refused).
//  BM_MacVerifySensor: the same on a signed evade_angles_t (the largest sensor message).
//  BM_KeyRingCheckPlan: auth::KeyRing::check on the same plan, the node's whole receive rule
//    (trailer, key lookup, MAC, state, role, ARSN compared): what the node pays per message.
//  BM_SignAck: signing one evade_cmd_ack_t with the telemetry key (encode_signed).
//  BM_NodeCycleAuth/0, /1 and /2: one node cycle on memq:// with nav + angles, as
//    BM_NodeCycleMemq (node_bench.cpp), with the sensors unsigned and not required (0), signed
//    and required (1), or signed and required with the node holding a telemetry key, so that
//    its status is signed every cycle (2): the cycle's p50/p99/max. The messages are encoded
//    (and signed) before the timer starts: the sender's signing is not the node's cost.
//  Run: build/bench/auth_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <time.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "evade/auth/keyring.hpp"
#include "evade/auth/trailer.hpp"
#include "evade/evade_angles_t.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/evade_cmd_ack_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/guidance/los_geometry.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/guidance_node.hpp"
#include "evade/guidance_lcm/signed_encode.hpp"

namespace {

using namespace evade;
using namespace evade::guidance_lcm;

SigningKey bench_key(std::int32_t id) {
  SigningKey k;
  k.id = id;
  for (std::size_t i = 0; i < k.key.size(); ++i) k.key[i] = static_cast<std::uint8_t>(i * 13 + 1);
  return k;
}

template <typename Msg>
std::vector<std::uint8_t> signed_bytes(Msg m, const char* channel) {
  std::vector<std::uint8_t> b(static_cast<std::size_t>(m.getEncodedSize()));
  (void)encode_signed(&m, channel, bench_key(1), 1, b.data(), static_cast<int>(b.size()));
  return b;
}

void BM_MacVerifyPlan(benchmark::State& state) {
  evade_burn_plan_t m{};
  m.n_impulses = 1;
  const std::vector<std::uint8_t> b = signed_bytes(m, kChanPlan);
  const auth::KeyBytes key = bench_key(1).key;
  for (auto _ : state) {
    benchmark::DoNotOptimize(auth::mac_valid(key, kChanPlan, b.data(), b.size()));
  }
  state.counters["bytes"] = static_cast<double>(b.size());
}
BENCHMARK(BM_MacVerifyPlan)->Unit(benchmark::kMicrosecond);

void BM_MacVerifySensor(benchmark::State& state) {
  evade_angles_t m{};
  const std::vector<std::uint8_t> b = signed_bytes(m, kChanAngles);
  const auth::KeyBytes key = bench_key(1).key;
  for (auto _ : state) {
    benchmark::DoNotOptimize(auth::mac_valid(key, kChanAngles, b.data(), b.size()));
  }
  state.counters["bytes"] = static_cast<double>(b.size());
}
BENCHMARK(BM_MacVerifySensor)->Unit(benchmark::kMicrosecond);

void BM_KeyRingCheckPlan(benchmark::State& state) {
  evade_burn_plan_t m{};
  m.n_impulses = 1;
  const std::vector<std::uint8_t> b = signed_bytes(m, kChanPlan);
  auth::KeyRing ring;
  (void)ring.add(1, auth::KeyRole::kCommand, bench_key(1).key, auth::KeyState::kActive);
  for (auto _ : state) {
    benchmark::DoNotOptimize(ring.check(auth::ArsnSlot::kCommand, kChanPlan, b.data(), b.size()));
  }
  state.counters["bytes"] = static_cast<double>(b.size());
}
BENCHMARK(BM_KeyRingCheckPlan)->Unit(benchmark::kMicrosecond);

void BM_SignAck(benchmark::State& state) {
  evade_cmd_ack_t a{};
  std::uint8_t buf[512];
  const SigningKey key = bench_key(3);
  std::int64_t arsn = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(encode_signed(&a, kChanCmdAck, key, ++arsn, buf, sizeof(buf)));
  }
  state.counters["bytes"] = static_cast<double>(a.getEncodedSize());
}
BENCHMARK(BM_SignAck)->Unit(benchmark::kMicrosecond);

std::int64_t now_ns() {
  timespec ts{};
  (void)clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// The closing encounter of node_bench.cpp: the law tracks and evades every cycle.
void inputs_at(std::int64_t t_us, std::int64_t seq, evade_nav_state_t* nav, evade_angles_t* a) {
  const double t = 1e-6 * static_cast<double>(t_us % 5000000);
  const Vec3 rel = Vec3(0.0, 10000.0, 2000.0) + Vec3(0.0, -1000.0, -150.0) * t;
  const guidance::LosAngles ang = guidance::los_angles_from_unit(rel.normalized());
  *nav = evade_nav_state_t{};
  nav->utime = t_us;
  nav->seq = seq;
  nav->valid = 1;
  nav->r_eci_m[0] = 7.0e6;
  nav->r_eci_m[1] = 7546.0 * t;
  nav->v_eci_mps[1] = 7546.0;
  *a = evade_angles_t{};
  a->utime = t_us;
  a->seq = seq;
  a->valid = 1;
  a->elevation_rad = ang.elevation_rad;
  a->azimuth_rad = ang.azimuth_rad;
  a->sigma_angle_rad = 1e-4;
}

void BM_NodeCycleAuth(benchmark::State& state) {
  const bool auth_on = state.range(0) != 0;
  lcm_t* lcm = lcm_create("memq://");
  NodeConfig cfg;
  cfg.guidance.stale_limit_s = 60.0;
  cfg.auth.nav_required = cfg.auth.angles_required = auth_on;
  NodeSecurity sec;
  (void)sec.keys.add(2, auth::KeyRole::kSensor, bench_key(2).key, auth::KeyState::kActive);
  if (state.range(0) == 2) {
    (void)sec.keys.add(3, auth::KeyRole::kTelemetry, bench_key(3).key, auth::KeyState::kActive);
  }
  auto node = std::make_unique<GuidanceNode>(lcm, cfg, nullptr, sec);  // dies before lcm
  std::uint8_t nav_buf[512];
  std::uint8_t ang_buf[512];
  std::vector<double> lat;
  lat.reserve(1 << 20);
  std::int64_t t = 1000000;
  std::int64_t seq = 0;
  const SigningKey key = bench_key(2);
  for (auto _ : state) {
    state.PauseTiming();
    evade_nav_state_t nav{};
    evade_angles_t a{};
    inputs_at(t, ++seq, &nav, &a);
    const int nn = auth_on ? encode_signed(&nav, kChanNav, key, seq, nav_buf, sizeof(nav_buf))
                           : nav.encode(nav_buf, 0, sizeof(nav_buf));
    const int na = auth_on ? encode_signed(&a, kChanAngles, key, seq, ang_buf, sizeof(ang_buf))
                           : a.encode(ang_buf, 0, sizeof(ang_buf));
    state.ResumeTiming();
    const std::int64_t t0 = now_ns();
    (void)lcm_publish(lcm, kChanNav, nav_buf, static_cast<unsigned>(nn));
    (void)lcm_publish(lcm, kChanAngles, ang_buf, static_cast<unsigned>(na));
    (void)node->drain();
    (void)node->run_cycle(t);
    const std::int64_t t1 = now_ns();
    if (lat.size() < lat.capacity()) lat.push_back(1e-3 * static_cast<double>(t1 - t0));
    t += 20000;
  }
  if (node->counts().consumed < 2 * static_cast<std::int64_t>(lat.size())) {
    state.SkipWithError("the node did not consume every input: the benchmark measures nothing");
  }
  std::sort(lat.begin(), lat.end());
  auto q = [&](double p) { return lat[static_cast<std::size_t>(p * static_cast<double>(lat.size() - 1))]; };
  if (!lat.empty()) {
    state.counters["p50_us"] = q(0.50);
    state.counters["p99_us"] = q(0.99);
    state.counters["max_us"] = lat.back();
  }
  node.reset();
  lcm_destroy(lcm);
}
BENCHMARK(BM_NodeCycleAuth)->Arg(0)->Arg(1)->Arg(2)->Iterations(20000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
