// Cycle-time statistics over a fixed-size ring (no allocation after construction): p50/p99
// over the last kWindow samples, max and count since start, overruns. Used for the node's
// compute time and its wake-up latency (docs/GUIDANCE_NODE.md NODE-RT-3); public, since the
// node reports them (guidance_node.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace evade::guidance_lcm {

class CycleStats {
 public:
  static constexpr std::size_t kWindow = 1024;

  void add(double sample_us) noexcept {
    ring_[next_] = sample_us;
    next_ = (next_ + 1) % kWindow;
    if (filled_ < kWindow) ++filled_;
    if (count_ == 0 || sample_us > max_us_) max_us_ = sample_us;
    ++count_;
  }
  void add_overrun() noexcept { ++overruns_; }

  /// q-quantile (0..1) of the samples in the window (nearest-rank); 0 when empty.
  double quantile(double q) const noexcept {
    if (filled_ == 0) return 0.0;
    std::copy(ring_.begin(), ring_.begin() + static_cast<std::ptrdiff_t>(filled_),
              scratch_.begin());
    double pos = q * static_cast<double>(filled_ - 1);
    std::size_t k = static_cast<std::size_t>(std::lround(pos));  // pos >= 0 for q in 0..1
    if (k >= filled_) k = filled_ - 1;
    std::nth_element(scratch_.begin(), scratch_.begin() + static_cast<std::ptrdiff_t>(k),
                     scratch_.begin() + static_cast<std::ptrdiff_t>(filled_));
    return scratch_[k];
  }
  double max_us() const noexcept { return max_us_; }
  std::int64_t count() const noexcept { return count_; }
  std::int64_t overruns() const noexcept { return overruns_; }

 private:
  std::array<double, kWindow> ring_{};
  mutable std::array<double, kWindow> scratch_{};
  std::size_t next_ = 0;
  std::size_t filled_ = 0;
  std::int64_t count_ = 0;
  std::int64_t overruns_ = 0;
  double max_us_ = 0.0;
};

}  // namespace evade::guidance_lcm
