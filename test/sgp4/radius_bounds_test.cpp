// Sgp4Propagator::radius_bounds (sgp4/radius_bounds.cpp): every near-Earth element set of the
// shipped catalog, sampled every 60 s over
// 7 days, stays inside its bounds; the bounds are tight enough to filter (their width
// exceeds the sampled range by the short-period terms' few km, not by hundreds); deep-space
// element sets claim no bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/sgp4.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::sgp4 {
namespace {

Catalog shipped() {
  std::ifstream in(EVADE_TEST_SHIPPED_CATALOG);
  std::ostringstream os;
  os << in.rdbuf();
  return read_tle(os.str(), "synthetic-1200.tle");
}

TEST(RadiusBounds, SampledRadiusStaysInsideOverSevenDays) {
  const Catalog cat = shipped();
  ASSERT_EQ(cat.objects.size(), 1200u);
  const double t1_min = 7.0 * 1440.0;
  int bounded = 0;
  double worst_excess_m = 0.0;
  for (const MeanElements& m : cat.objects) {
    const Sgp4Propagator p(m);
    const RadiusBounds b = p.radius_bounds(0.0, t1_min);
    if (!b.bounded) continue;
    ++bounded;
    double lo = 1e300, hi = 0.0;
    for (double t = 0.0; t <= t1_min; t += 1.0) {
      const Sgp4State s = p.propagate_min(t);
      if (s.error != Sgp4Error::kNone) break;
      const double r = s.r_teme_m.norm();
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
    ASSERT_GE(lo, b.min_m) << m.norad_id;
    ASSERT_LE(hi, b.max_m) << m.norad_id;
    worst_excess_m = std::max({worst_excess_m, lo - b.min_m, b.max_m - hi});
  }
  EXPECT_GE(bounded, 900);  // the near-Earth part of the catalog (275 are deep space)
  // Slack: the short-period terms bounded by their amplitude (~10 km in low LEO), the
  // J3 long-period term and drag over 7 days. 50 km keeps the filter useful.
  EXPECT_LT(worst_excess_m, 50e3);
  std::printf("bounded %d of %zu, widest slack %.0f m\n", bounded, cat.objects.size(),
              worst_excess_m);
}

TEST(RadiusBounds, DeepSpaceHasNoBound) {
  const Catalog cat = shipped();
  int deep = 0;
  for (const MeanElements& m : cat.objects) {
    // The theory's deep-space test is on the un-Kozai'd period (>= 225 min): clear of it.
    if (1440.0 / m.mean_motion_revpday < 230.0) continue;
    ++deep;
    EXPECT_FALSE(Sgp4Propagator(m).radius_bounds(0.0, 1440.0).bounded) << m.norad_id;
  }
  EXPECT_GT(deep, 200);
}

TEST(RadiusBounds, BackwardAndStraddlingIntervals) {
  const Catalog cat = shipped();
  const Sgp4Propagator p(cat.objects[0]);
  const RadiusBounds a = p.radius_bounds(-1440.0, 1440.0);
  ASSERT_TRUE(a.bounded);
  for (double t = -1440.0; t <= 1440.0; t += 0.5) {
    const double r = p.propagate_min(t).r_teme_m.norm();
    ASSERT_GE(r, a.min_m);
    ASSERT_LE(r, a.max_m);
  }
  EXPECT_FALSE(p.radius_bounds(10.0, 0.0).bounded);  // an empty interval
}

}  // namespace
}  // namespace evade::sgp4
