// Monte Carlo over sensor/actuator noise seeds for the paper-000 evasion simulation (the
// paper's sec. 5 asks for the effect of measurement errors). Runs are spread over threads;
// run i uses sensor seed splitmix64(seed, 2i) and actuator seed splitmix64(seed, 2i+1), so
// results do not depend on the thread count, and a range of run indices can be run alone
// (by another process: src/distributed/) and summarized with the others.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "evade/sim/simulator.hpp"

namespace evade::sim {

struct MonteCarloResult {
  std::vector<double> miss_m;  ///< per run, in run order
  std::vector<double> dv_mps;  ///< per run
  double miss_min_m = 0.0;
  double miss_p5_m = 0.0;
  double miss_p50_m = 0.0;
  double miss_p95_m = 0.0;
  double miss_max_m = 0.0;
  double miss_mean_m = 0.0;
};

/// Per-run results of a range of run indices, in run order.
struct MonteCarloRuns {
  std::vector<double> miss_m;
  std::vector<double> dv_mps;
};

/// The noise seeds of Monte Carlo run `run` (0-based) of a campaign seeded `seed`:
/// splitmix64(seed, 2 run) for the sensor and splitmix64(seed, 2 run + 1) for the actuator.
/// A single run with these seeds flies exactly that run of the campaign.
struct MonteCarloRunSeeds {
  std::uint64_t sensor = 0;
  std::uint64_t actuator = 0;
};
MonteCarloRunSeeds monte_carlo_run_seeds(std::uint64_t seed, std::uint64_t run) noexcept;

/// Percentile p ∈ [0, 100] with linear interpolation between order statistics (R type 7).
double percentile(std::vector<double> values, double p);

/// Runs `runs` simulations of `base` with the in-process guidance. `threads` ≥ 1.
/// on_done(i_done, runs) is called (from worker threads, serialized) after each run.
MonteCarloResult run_monte_carlo(const SimConfig& base, int runs, std::uint64_t seed,
                                 int threads,
                                 const std::function<void(int, int)>& on_done = {});

/// Runs run indices [run_begin, run_end) (seeds from the run index, as run_monte_carlo);
/// on_done(done, run_end - run_begin).
MonteCarloRuns run_monte_carlo_range(const SimConfig& base, int run_begin, int run_end,
                                     std::uint64_t seed, int threads,
                                     const std::function<void(int, int)>& on_done = {});

/// Percentiles, extremes and mean of per-run results in run order (the run_monte_carlo
/// summary). Throws std::invalid_argument when empty or of different sizes.
MonteCarloResult summarize_monte_carlo(std::vector<double> miss_m, std::vector<double> dv_mps);

}  // namespace evade::sim
