// The workload of bench/count_target_instructions.sh (docs/PERFORMANCE.md "Instructions on
// the flight CPUs"): N guidance steps, or N authenticated node cycles, with every input made
// before the counted part, so that the instructions of two runs (N1 and N2) differ only by
// N2 - N1 steps or cycles: the difference divided by N2 - N1 is the cost of one, whatever the
// program's start-up costs on the target. Built for the host and every cross target.
//   cross_instruction_harness step N        GuidanceLaw::step, bench/guidance_bench's feed
//   cross_instruction_harness cycle AUTH N   GuidanceNode drain + run_cycle on memq:// after
//       publishing that cycle's nav and angles, as bench/auth_bench's BM_NodeCycleAuth/AUTH:
//       0 unsigned sensors, 1 signed and required, 2 that and the status signed
// N is 0..kMaxRuns. Prints a checksum of the outputs on stderr (nothing on stdout). Exit 2 on
// bad arguments.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include <lcm/lcm.h>

#include "evade/evade_angles_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/guidance/guidance_law.hpp"
#include "evade/guidance/los_geometry.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/guidance_node.hpp"
#include "evade/guidance_lcm/signed_encode.hpp"

namespace {

using namespace evade;
constexpr int kMaxRuns = 400;

// bench/guidance_bench.cpp's StepFeed, every input made in advance.
std::vector<guidance::GuidanceInput> step_inputs() {
  std::mt19937_64 rng{1};
  std::normal_distribution<double> noise{0.0, 1.0};
  std::vector<guidance::GuidanceInput> v(kMaxRuns);
  for (int k = 0; k < kMaxRuns; ++k) {
    guidance::GuidanceInput& in = v[static_cast<std::size_t>(k)];
    const std::int64_t now = 1'000'000 + 20'000LL * k;
    const double t = 0.02 * static_cast<double>(k);
    const Vec3 u = Vec3(std::cos(1e-3 * t), std::sin(1e-3 * t), 0.1).normalized();
    const guidance::LosAngles a = guidance::los_angles_from_unit(u);
    in.armed = true;
    in.nav.valid = true;
    in.nav.r_eci_m = Vec3(6.8e6, 0, 0);
    in.nav.v_eci_mps = Vec3(0, 7500, 0);
    in.nav.utime_us = now;
    in.has_measurement = true;
    in.meas.utime_us = now;
    in.meas.valid = true;
    in.meas.elevation_rad = a.elevation_rad + 50e-6 * noise(rng);
    in.meas.azimuth_rad = a.azimuth_rad + 50e-6 * noise(rng);
    in.meas.sigma_angle_rad = 50e-6;
    in.meas.has_rates = (k % 2 == 0);
    in.meas.azimuth_rate_radps = 1e-3;
    in.meas.sigma_rate_radps = 1e-5;
  }
  return v;
}

double run_steps(int n) {
  const std::vector<guidance::GuidanceInput> in = step_inputs();
  guidance::GuidanceConfig c;  // bench/guidance_bench.cpp's bench_config()
  c.dv_budget_mps = 1e4;
  c.max_burn_s = 1e5;
  guidance::GuidanceLaw law(c);
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const guidance::GuidanceInput& x = in[static_cast<std::size_t>(k)];
    sum += law.step(x, x.nav.utime_us).accel_mps2;
  }
  return sum;
}

guidance_lcm::SigningKey bench_key(std::int32_t id) {  // bench/auth_bench.cpp's
  guidance_lcm::SigningKey k;
  k.id = id;
  for (std::size_t i = 0; i < k.key.size(); ++i) k.key[i] = static_cast<std::uint8_t>(i * 13 + 1);
  return k;
}

// bench/auth_bench.cpp's inputs_at: the closing encounter; the law tracks and evades.
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

struct Wire {
  std::vector<std::uint8_t> bytes;
};

double run_cycles(int auth, int n) {
  const bool signed_in = auth != 0;
  const guidance_lcm::SigningKey key = bench_key(2);
  std::vector<Wire> nav(kMaxRuns), ang(kMaxRuns);
  for (int k = 0; k < kMaxRuns; ++k) {
    evade_nav_state_t m{};
    evade_angles_t a{};
    inputs_at(1000000 + 20000LL * k, k + 1, &m, &a);
    std::uint8_t b[512];
    const int nn = signed_in ? guidance_lcm::encode_signed(&m, guidance_lcm::kChanNav, key, k + 1,
                                                           b, sizeof b)
                             : m.encode(b, 0, sizeof b);
    nav[static_cast<std::size_t>(k)].bytes.assign(b, b + nn);
    const int na = signed_in ? guidance_lcm::encode_signed(&a, guidance_lcm::kChanAngles, key,
                                                           k + 1, b, sizeof b)
                             : a.encode(b, 0, sizeof b);
    ang[static_cast<std::size_t>(k)].bytes.assign(b, b + na);
  }
  lcm_t* lcm = lcm_create("memq://");
  guidance_lcm::NodeConfig cfg;
  cfg.guidance.stale_limit_s = 60.0;
  cfg.auth.nav_required = cfg.auth.angles_required = signed_in;
  guidance_lcm::NodeSecurity sec;
  (void)sec.keys.add(2, auth::KeyRole::kSensor, key.key, auth::KeyState::kActive);
  if (auth == 2)
    (void)sec.keys.add(3, auth::KeyRole::kTelemetry, bench_key(3).key, auth::KeyState::kActive);
  double sum = 0.0;
  {
    guidance_lcm::GuidanceNode node(lcm, cfg, nullptr, sec);
    for (int k = 0; k < n; ++k) {
      const Wire& w1 = nav[static_cast<std::size_t>(k)];
      const Wire& w2 = ang[static_cast<std::size_t>(k)];
      (void)lcm_publish(lcm, guidance_lcm::kChanNav, w1.bytes.data(),
                        static_cast<unsigned>(w1.bytes.size()));
      (void)lcm_publish(lcm, guidance_lcm::kChanAngles, w2.bytes.data(),
                        static_cast<unsigned>(w2.bytes.size()));
      (void)node.drain();
      sum += node.run_cycle(1000000 + 20000LL * k).accel_mps2;
    }
    sum += static_cast<double>(node.counts().consumed);
  }
  lcm_destroy(lcm);
  return sum;
}

bool parse_int(const char* s, int lo, int hi, int* out) {
  char* end = nullptr;
  const long v = std::strtol(s, &end, 10);
  if (end == s || *end != '\0' || v < lo || v > hi) return false;
  *out = static_cast<int>(v);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 0, auth = 0;
  double sum = 0.0;
  if (argc == 3 && std::strcmp(argv[1], "step") == 0 && parse_int(argv[2], 0, kMaxRuns, &n)) {
    sum = run_steps(n);
  } else if (argc == 4 && std::strcmp(argv[1], "cycle") == 0 &&
             parse_int(argv[2], 0, 2, &auth) && parse_int(argv[3], 0, kMaxRuns, &n)) {
    sum = run_cycles(auth, n);
  } else {
    (void)std::fprintf(stderr, "usage: cross_instruction_harness step N | cycle 0|1|2 N "
                               "(N in 0..%d)\n", kMaxRuns);
    return 2;
  }
  (void)std::fprintf(stderr, "checksum %.17g\n", sum);
  return 0;
}
