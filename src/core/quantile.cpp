// Nearest-rank quantile (evade/core/quantile.hpp).
#include "evade/core/quantile.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace evade {

double nearest_rank_quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  // lround, not +0.5 truncation, which rounds 0.49999999999999994 up.
  const auto k = static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)));
  return v[std::min(k, v.size() - 1)];
}

}  // namespace evade
