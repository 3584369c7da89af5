// Monte Carlo collision probability from full 6x6 covariances (no short-term assumptions).
//
// Alfano 2009, "Satellite Conjunction Monte Carlo Analysis" (AAS 09-233): draw each object's
// state at TCA from its Gaussian (mean, 6x6 covariance; a square root V sqrt(max(L, 0))
// of the eigen-decomposition, so a position-only covariance with a zero velocity block is
// sampled exactly), propagate both draws over [-window, +window] about TCA with two-body
// motion (KeplerOrbit, f and g) or, as an option, two-body + J2 (DOP853), and count a hit
// when they enter the hard-body sphere during the window: outside it at some time in the
// window and inside it later. A pair already inside at the window's start is not a new
// collision in the window (D. Hall, "Expected collision rates for tracked satellites", JSR
// 58(3), 2021: Nc counts entries; NASA CARA's Monte Carlo values of the Alfano cases agree
// with it); it matters only for slow pairs that stay inside for longer than the window,
// e.g. Alfano case 9 (2 mm/s): 0.28 over +-10800 s by entries, 0.365 by Alfano's 2009
// count of every sample whose closest distance is below the radius.
// Closest distance: the relative distance on a grid of step min(P/64, w/16) (w the window
// half-width, P the shorter period, +infinity when unbound); every local minimum of the grid
// (and each end) whose lower bound d - h (|v_rel| + a_max h) is below the radius is refined
// by Newton on the range rate,
// dt = -(r.v)/(|v|^2 + r.a), kept inside its grid bracket; an entry is an evaluated distance
// below the radius after one at or above it (evaluated distances are true distances: a miss
// cannot be counted as a hit).
// Samples are drawn in blocks of kMcBlockSamples, block b from its own generator
// (std::mt19937_64 seeded with (seed, b)), so a result depends only on the seed and the
// number of blocks run, not on threads or MPI ranks. The count k of n gives Pc = k/n with
// the Wilson score interval (Wilson 1927, JASA 22): (p + z^2/2n +- z sqrt(p(1-p)/n +
// z^2/4n^2)) / (1 + z^2/n). Stopping rule: with target_rel_accuracy > 0, after each block
// (in block order) the run stops once k > 0 and the interval's half-width is at most
// target_rel_accuracy * Pc; otherwise, or at the latest, after `samples`.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"

namespace evade::assessment {

inline constexpr long kMcBlockSamples = 10000;  ///< samples per independently seeded block

struct MonteCarloOptions {
  long samples = 100000;            ///< largest number of samples [-]
  std::uint64_t seed = 1;
  double window_s = 0.0;            ///< half-width of the time window about TCA [s] (> 0)
  double z = 1.96;                  ///< normal quantile of the interval (1.96: 95 %)
  double target_rel_accuracy = 0.0; ///< > 0: stop at half-width <= this x Pc [-]
  bool j2 = false;                  ///< two-body + J2 motion instead of two-body
  int threads = 1;                  ///< worker threads (>= 1)
  int wave_blocks = 0;              ///< blocks handed to the runner at a time (0: threads)
};


struct MonteCarloResult {
  double pc = 0.0;
  double pc_low = 0.0;
  double pc_high = 0.0;
  long hits = 0;
  long samples = 0;
  double window_s = 0.0;
  double z = 1.96;
  bool stopped_at_target = false;  ///< the relative-accuracy target was met
  bool j2 = false;
};

/// One Monte Carlo problem: both objects' mean states and 6x6 ECI covariances at TCA.
struct McEncounter {
  StateEci obj1, obj2;
  Mat6 cov1_eci = Mat6::Zero(), cov2_eci = Mat6::Zero();
  double hbr_m = 0.0;
  EarthModel earth = kEarthDefault;
};

/// Computes the hits of blocks [first, first + count) (block b holds
/// min(kMcBlockSamples, samples - b kMcBlockSamples) samples) into hits[0 .. count).
/// The default runs them on opt.threads threads; an MPI layer spreads them over ranks.
using McBlockRunner = std::function<void(const McEncounter& e, const MonteCarloOptions& opt,
                                         long first, long count, long* hits)>;

/// How a Monte Carlo runs: threads, and the block runner with its wave (MPI ranks set both:
/// distributed_pc_monte_carlo.hpp). Empty runner: the threaded one.
struct McExecution {
  int threads = 1;
  int wave_blocks = 0;  ///< 0: threads
  McBlockRunner runner;
  int ranks = 1;        ///< processes the runner spreads over (reported)
};

/// Throws std::invalid_argument for samples < 1, window_s <= 0, hbr_m <= 0, threads < 1,
/// target_rel_accuracy < 0 or non-finite states and covariances.
MonteCarloResult pc_monte_carlo(const McEncounter& e, const MonteCarloOptions& opt,
                                const McBlockRunner& runner = {});

/// Hits of block b alone (the unit an MPI rank or a thread computes).
long pc_monte_carlo_block(const McEncounter& e, const MonteCarloOptions& opt, long block);

/// The threaded block runner (the default of pc_monte_carlo).
void run_mc_blocks_threaded(const McEncounter& e, const MonteCarloOptions& opt, long first,
                            long count, long* hits);

/// The Wilson score interval of k hits in n samples.
void wilson_interval(long k, long n, double z, double* low, double* high);

}  // namespace evade::assessment
