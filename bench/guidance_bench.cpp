// Speed of the paper-000 guidance: GuidanceLaw::step (flight code, target p99 ≤ 5 µs) and one
// full `evade sim` of seed0 (truth two-body + J2, 500 cycles at 50 Hz).
//
//   ninja -C build bench/guidance_bench && build/bench/guidance_bench
//
// BM_GuidanceStepPercentiles times each of 20 000 steps with std::chrono::steady_clock
// (noisy angles, rates on every other sample, armed, evading) and reports p50/p99/max as
// counters (ns); the Google Benchmark mean of BM_GuidanceStep is the cross-check.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "evade/config/scenario.hpp"
#include "evade/guidance/guidance_law.hpp"
#include "evade/guidance/los_geometry.hpp"
#include "evade/commands/sim_scenario.hpp"
#include "evade/sim/simulator.hpp"

namespace {

using evade::Vec3;
using namespace evade::guidance;

struct StepFeed {
  std::mt19937_64 rng{1};
  std::normal_distribution<double> n{0.0, 1.0};
  GuidanceInput in;
  StepFeed() {
    in.armed = true;
    in.nav.valid = true;
    in.nav.r_eci_m = Vec3(6.8e6, 0, 0);
    in.nav.v_eci_mps = Vec3(0, 7500, 0);
  }
  std::int64_t fill(long k) {
    const std::int64_t now = 1'000'000 + 20'000LL * k;
    const double t = 0.02 * static_cast<double>(k % 100000);
    const Vec3 u = Vec3(std::cos(1e-3 * t), std::sin(1e-3 * t), 0.1).normalized();
    const LosAngles a = los_angles_from_unit(u);
    in.nav.utime_us = now;
    in.has_measurement = true;
    in.meas.utime_us = now;
    in.meas.valid = true;
    in.meas.elevation_rad = a.elevation_rad + 50e-6 * n(rng);
    in.meas.azimuth_rad = a.azimuth_rad + 50e-6 * n(rng);
    in.meas.sigma_angle_rad = 50e-6;
    in.meas.has_rates = (k % 2 == 0);
    in.meas.elevation_rate_radps = 0.0;
    in.meas.azimuth_rate_radps = 1e-3;
    in.meas.sigma_rate_radps = 1e-5;
    return now;
  }
};

GuidanceConfig bench_config() {
  GuidanceConfig c;
  c.dv_budget_mps = 1e4;
  c.max_burn_s = 1e5;
  return c;
}

void BM_GuidanceStep(benchmark::State& state) {
  GuidanceLaw law(bench_config());
  StepFeed feed;
  long k = 0;
  for (auto _ : state) {
    const std::int64_t now = feed.fill(k++);
    benchmark::DoNotOptimize(law.step(feed.in, now));
  }
}
BENCHMARK(BM_GuidanceStep);

void BM_GuidanceStepPercentiles(benchmark::State& state) {
  constexpr int kSteps = 20000;
  std::vector<double> ns(kSteps);
  for (auto _ : state) {
    GuidanceLaw law(bench_config());
    StepFeed feed;
    for (int k = 0; k < kSteps; ++k) {
      const std::int64_t now = feed.fill(k);
      const auto t0 = std::chrono::steady_clock::now();
      const ThrustCommand c = law.step(feed.in, now);
      const auto t1 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(c);
      ns[static_cast<std::size_t>(k)] = std::chrono::duration<double, std::nano>(t1 - t0).count();
    }
  }
  std::vector<double> s = ns;
  std::sort(s.begin(), s.end());
  state.counters["p50_ns"] = s[s.size() / 2];
  state.counters["p99_ns"] = s[s.size() * 99 / 100];
  state.counters["max_ns"] = s.back();
  state.counters["steps"] = kSteps;
}
BENCHMARK(BM_GuidanceStepPercentiles)->Iterations(3)->Unit(benchmark::kMillisecond);

void BM_SimSeed0(benchmark::State& state) {
  const evade::sim::SimConfig c =
      evade::commands::sim_config_from_scenario(evade::config::Scenario::load("seed0"));
  double miss = 0.0;
  for (auto _ : state) {
    auto ep = evade::sim::make_in_process_endpoint(c.guidance, true);
    const evade::sim::SimResult r = evade::sim::run_simulation(c, *ep);
    miss = r.miss_m;
    benchmark::ClobberMemory();
  }
  state.counters["miss_m"] = miss;
}
BENCHMARK(BM_SimSeed0)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
