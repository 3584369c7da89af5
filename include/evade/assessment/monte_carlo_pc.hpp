// Monte Carlo collision probability with two-body motion (no short-term assumptions).
//
// Alfano 2009, "Satellite Conjunction Monte Carlo Analysis" (AAS 09-233): draw each object's
// state at TCA from its Gaussian (mean, 6x6 covariance; a square root V sqrt(max(L, 0))
// of the eigen-decomposition, so a position-only covariance with a zero velocity block is
// sampled exactly), propagate both draws with two-body motion (KeplerOrbit, f and g) over
// [-window, +window] around TCA, and count a hit when the closest distance is below the
// hard-body radius. The closest distance is found on a 64-interval grid refined by golden
// section around the grid minimum. The count k of N gives Pc = k/N with the Wilson score
// interval (Wilson 1927, JASA 22): (p + z^2/2N +- z sqrt(p(1-p)/N + z^2/4N^2)) / (1 + z^2/N),
// z = 1.96 for 95 %. Reproducible for a given seed (std::mt19937_64).
#pragma once

#include <cstdint>

#include "evade/core/state.hpp"

namespace evade::assessment {

struct MonteCarloOptions {
  long samples = 100000;
  std::uint64_t seed = 1;
  double window_s = 0.0;   ///< half-width of the time window around TCA [s] (> 0)
  double z = 1.96;         ///< normal quantile of the interval (1.96: 95 %)
};

struct MonteCarloResult {
  double pc = 0.0;
  double pc_low = 0.0;
  double pc_high = 0.0;
  long hits = 0;
  long samples = 0;
  double window_s = 0.0;
};

/// Throws std::invalid_argument for samples < 1, window_s <= 0 or hbr_m <= 0.
MonteCarloResult pc_monte_carlo(const StateEci& obj1, const Mat6& cov1_eci,
                                const StateEci& obj2, const Mat6& cov2_eci, double hbr_m,
                                double mu_m3ps2, const MonteCarloOptions& opt);

/// The Wilson score interval of k hits in n samples.
void wilson_interval(long k, long n, double z, double* low, double* high);

}  // namespace evade::assessment
