// Cycle statistics: quantiles over the window, max and overruns since start (docs/GUIDANCE_NODE.md
// NODE-RT-3).
#include <gtest/gtest.h>

#include <cmath>

#include "evade/guidance_lcm/cycle_stats.hpp"

namespace evade::guidance_lcm {
namespace {

TEST(CycleStats, QuantilesOverTheWindowAndMaxSinceStart) {
  CycleStats s;
  s.add(1e6);  // pushed out of the window later, but stays the max
  for (int i = 1; i <= static_cast<int>(CycleStats::kWindow); ++i) s.add(i);
  EXPECT_EQ(s.max_us(), 1e6);
  EXPECT_NEAR(s.quantile(0.5), 512.5, 0.5);
  EXPECT_NEAR(s.quantile(0.99), 0.99 * 1024, 1.0);
  EXPECT_EQ(s.quantile(1.0), 1024.0);
  EXPECT_EQ(s.count(), 1025);
}

// The status reports 0 before the first sample (not an uninitialised window), a quantile
// above 1 gives the window's largest sample (never a read past it), and overruns count up.
TEST(CycleStats, EmptyWindowIsZeroQuantileClampedAndOverrunsCounted) {
  CycleStats s;
  EXPECT_EQ(s.quantile(0.5), 0.0);
  EXPECT_EQ(s.max_us(), 0.0);
  s.add(7.0);
  s.add(3.0);
  s.add(5.0);
  EXPECT_EQ(s.max_us(), 7.0);
  EXPECT_EQ(s.quantile(0.0), 3.0);
  EXPECT_EQ(s.quantile(2.0), 7.0);
  EXPECT_EQ(s.overruns(), 0);
  s.add_overrun();
  s.add_overrun();
  EXPECT_EQ(s.overruns(), 2);
  EXPECT_EQ(s.count(), 3);
}

}  // namespace
}  // namespace evade::guidance_lcm
