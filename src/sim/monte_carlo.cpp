// Monte Carlo driver (see include/evade/sim/monte_carlo.hpp).
#include "evade/sim/monte_carlo.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

namespace evade::sim {

namespace {

std::uint64_t splitmix64(std::uint64_t seed, std::uint64_t i) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (i + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace

MonteCarloRunSeeds monte_carlo_run_seeds(std::uint64_t seed, std::uint64_t run) noexcept {
  return {splitmix64(seed, 2 * run), splitmix64(seed, 2 * run + 1)};
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) throw std::invalid_argument("percentile: no values");
  std::sort(values.begin(), values.end());
  const double pos = (p / 100.0) * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  const double frac = pos - static_cast<double>(lo);
  return values[lo] + frac * (values[hi] - values[lo]);
}

MonteCarloRuns run_monte_carlo_range(const SimConfig& base, int run_begin, int run_end,
                                     std::uint64_t seed, int threads,
                                     const std::function<void(int, int)>& on_done) {
  if (run_begin < 0 || run_end < run_begin) {
    throw std::invalid_argument("monte carlo: run range [" + std::to_string(run_begin) + ", " +
                                std::to_string(run_end) + ") is not a range of run indices");
  }
  base.validate();
  const int runs = run_end - run_begin;
  threads = std::max(1, std::min(threads, std::max(runs, 1)));
  MonteCarloRuns r;
  r.miss_m.assign(static_cast<std::size_t>(runs), 0.0);
  r.dv_mps.assign(static_cast<std::size_t>(runs), 0.0);
  std::atomic<int> next{0};
  std::mutex mu;
  int done = 0;
  std::exception_ptr error;
  auto worker = [&]() {
    for (;;) {
      const int k = next.fetch_add(1);
      if (k >= runs) return;
      try {
        const std::uint64_t i =  // the run index
            static_cast<std::uint64_t>(run_begin) + static_cast<std::uint64_t>(k);
        SimConfig c = base;
        const MonteCarloRunSeeds seeds = monte_carlo_run_seeds(seed, i);
        c.sensor.seed = seeds.sensor;
        c.actuator.seed = seeds.actuator;
        auto ep = make_in_process_endpoint(c.guidance, c.guidance.armed);
        const SimResult s = run_simulation(c, *ep);
        if (!s.closest_approach_found) throw std::runtime_error("no closest approach found");
        std::lock_guard<std::mutex> lock(mu);
        r.miss_m[static_cast<std::size_t>(k)] = s.miss_m;
        r.dv_mps[static_cast<std::size_t>(k)] = s.dv_mps;
        ++done;
        if (on_done) on_done(done, runs);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mu);
        if (!error) error = std::current_exception();
        next.store(runs);
        return;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return r;
}

MonteCarloResult summarize_monte_carlo(std::vector<double> miss_m, std::vector<double> dv_mps) {
  if (miss_m.empty() || miss_m.size() != dv_mps.size()) {
    throw std::invalid_argument("monte carlo: no runs to summarize");
  }
  MonteCarloResult r;
  r.miss_m = std::move(miss_m);
  r.dv_mps = std::move(dv_mps);
  r.miss_min_m = *std::min_element(r.miss_m.begin(), r.miss_m.end());
  r.miss_max_m = *std::max_element(r.miss_m.begin(), r.miss_m.end());
  r.miss_p5_m = percentile(r.miss_m, 5.0);
  r.miss_p50_m = percentile(r.miss_m, 50.0);
  r.miss_p95_m = percentile(r.miss_m, 95.0);
  double sum = 0.0;
  for (double m : r.miss_m) sum += m;
  r.miss_mean_m = sum / static_cast<double>(r.miss_m.size());
  return r;
}

MonteCarloResult run_monte_carlo(const SimConfig& base, int runs, std::uint64_t seed,
                                 int threads, const std::function<void(int, int)>& on_done) {
  if (runs < 1) throw std::invalid_argument("monte carlo: runs = " + std::to_string(runs) +
                                            " outside [1, inf)");
  MonteCarloRuns r = run_monte_carlo_range(base, 0, runs, seed, threads, on_done);
  return summarize_monte_carlo(std::move(r.miss_m), std::move(r.dv_mps));
}

}  // namespace evade::sim
