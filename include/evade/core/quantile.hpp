// Order statistics of offline samples (latencies, ages): the one nearest-rank quantile.
// The interpolated percentile of Monte Carlo results is sim::percentile; the real-time
// window statistics of the node are guidance_lcm::CycleStats (no allocation).
#pragma once

#include <vector>

namespace evade {

/// The q-quantile (q in [0, 1]) of v by nearest rank: sorted v at index lround(q (n - 1)),
/// clamped to the last element; 0 when v is empty. Takes v by value (it sorts a copy).
double nearest_rank_quantile(std::vector<double> v, double q);

}  // namespace evade
