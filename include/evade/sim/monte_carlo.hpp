// Monte Carlo over sensor/actuator noise seeds for the paper-000 evasion simulation (the
// paper's sec. 5 asks for the effect of measurement errors). Runs are spread over threads;
// run i uses sensor seed splitmix64(seed, 2i) and actuator seed splitmix64(seed, 2i+1), so
// results do not depend on the thread count.
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

/// Percentile p ∈ [0, 100] with linear interpolation between order statistics (R type 7).
double percentile(std::vector<double> values, double p);

/// Runs `runs` simulations of `base` with the in-process guidance. `threads` ≥ 1.
/// on_done(i_done, runs) is called (from worker threads, serialized) after each run.
MonteCarloResult run_monte_carlo(const SimConfig& base, int runs, std::uint64_t seed,
                                 int threads,
                                 const std::function<void(int, int)>& on_done = {});

}  // namespace evade::sim
