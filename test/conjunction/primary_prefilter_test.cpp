// The perigee/apogee prefilter of one satellite against a catalog (primary_prefilter.hpp):
// the screen with the prefilter finds exactly the events of the screen without it (same
// pairs, TCA within 1 ms, miss within 1 cm: the same narrow phase on the same grid), on the
// shipped catalog for LEO primaries at several altitudes and on seeded catalogs whose slow
// co-orbital, near-tangent and crossing pairs put partners in the primary's shell; and it
// sets objects aside (the point of it), counted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "evade/conjunction/primary_prefilter.hpp"
#include "evade/commands/screen_command.hpp"
#include "evade/sgp4/catalog.hpp"
#include "sgp4_test_catalog.hpp"

namespace evade::conjunction {
namespace {

using namespace evade::commands;

sgp4::Catalog shipped() { return testing::shipped_catalog(); }

ScreenCatalogResult screen(const sgp4::Catalog& cat, long primary, double span_s, bool prefilter,
                           double threshold_m = 5000.0) {
  ScreenCatalogRequest req;
  req.robust.threshold_m = threshold_m;
  req.catalog = cat;
  req.primary_norad = primary;
  req.span_s = span_s;
  req.robust.step_s = 60.0;  // the same grid with and without the prefilter (auto_step_s depends on N)
  req.threads = 2;
  req.prefilter = prefilter;
  return run_screen_catalog(req);
}

void expect_same_events(const ScreenCatalogResult& a, const ScreenCatalogResult& b, long primary) {
  ASSERT_EQ(a.events.size(), b.events.size()) << "primary " << primary;
  for (std::size_t k = 0; k < a.events.size(); ++k) {
    const CatalogEvent& x = a.events[k];
    bool found = false;
    for (const CatalogEvent& y : b.events)
      found = found || (x.norad_i == y.norad_i && x.norad_j == y.norad_j &&
                        std::abs(x.tca_s - y.tca_s) < 1e-3 && std::abs(x.miss_m - y.miss_m) < 0.01);
    EXPECT_TRUE(found) << "primary " << primary << ": " << x.norad_i << "-" << x.norad_j;
  }
}

TEST(PrimaryPrefilter, ShippedCatalogSameEventsFewerObjects) {
  const sgp4::Catalog cat = shipped();
  long events = 0;
  for (const long primary : {90000L, 90100L, 90300L, 90600L}) {
    // 50 km: enough approaches in 6 h to compare (5 km gives none for these primaries).
    const ScreenCatalogResult with = screen(cat, primary, 21600.0, true, 50e3);
    const ScreenCatalogResult without = screen(cat, primary, 21600.0, false, 50e3);
    expect_same_events(with, without, primary);
    expect_same_events(without, with, primary);
    events += static_cast<long>(without.events.size());
    ASSERT_TRUE(with.prefilter);
    const PrimaryPrefilterCounts& c = *with.prefilter;
    EXPECT_EQ(c.objects, 1200);
    EXPECT_EQ(c.kept + c.removed_radius + c.removed_path, c.objects);
    EXPECT_EQ(with.objects, c.kept);
    if (c.primary_bounded) {
      EXPECT_GT(c.removed_radius, 200) << primary;  // a LEO primary
    }
    EXPECT_FALSE(without.prefilter);
  }
  EXPECT_GE(events, 5);  // the comparison is not vacuous
  std::printf("shipped catalog, 4 primaries, 6 h, 50 km: %ld events, the same with the prefilter\n",
              events);
}

TEST(PrimaryPrefilter, SeededPairsAreKept) {
  long events = 0;
  for (const std::uint64_t seed : {11u, 12u}) {
    testing::Sgp4TestCatalogOptions o;
    o.seed = seed;
    o.background = 150;
    sgp4::Catalog cat;
    cat.objects = testing::sgp4_test_catalog(o);
    // A member of each kind of pair: the catalog lists the background first, then the pairs.
    for (const std::size_t k : {std::size_t{150}, std::size_t{158}, std::size_t{174}}) {
      const long primary = cat.objects[k].norad_id;
      const ScreenCatalogResult with = screen(cat, primary, 21600.0, true);
      const ScreenCatalogResult without = screen(cat, primary, 21600.0, false);
      expect_same_events(with, without, primary);
      expect_same_events(without, with, primary);
      events += static_cast<long>(without.events.size());
    }
  }
  EXPECT_GT(events, 3);
  std::printf("seeded catalogs, 6 primaries, 6 h: %ld events, the same with the prefilter\n", events);
}

// The deep-space bound from 30-minute samples holds on 1-minute sampling over 7 days for
// every deep-space element set of the shipped catalog (GEO, navigation MEO, HEO).
TEST(PrimaryPrefilter, DeepSpaceSampledBoundHoldsOnFineSampling) {
  const sgp4::Catalog cat = shipped();
  int deep = 0;
  double widest_geo_m = 0.0;
  for (const sgp4::MeanElements& m : cat.objects) {
    const sgp4::Sgp4Propagator p(m);
    if (p.radius_bounds(0.0, 1.0).bounded) continue;  // near-Earth: the analytic bound
    ++deep;
    const sgp4::RadiusBounds b = sampled_radius_bounds(p, 0.0, 7.0 * 86400.0);
    ASSERT_TRUE(b.bounded) << m.norad_id;
    double lo = 1e300, hi = 0.0;
    for (double t = 0.0; t <= 7.0 * 86400.0; t += 60.0) {
      const double r = p.propagate_s(t).r_teme_m.norm();
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
    ASSERT_GE(lo, b.min_m) << m.norad_id;
    ASSERT_LE(hi, b.max_m) << m.norad_id;
    if (m.eccentricity < 0.01 && m.mean_motion_revpday < 1.1)
      widest_geo_m = std::max({widest_geo_m, lo - b.min_m, b.max_m - hi});
  }
  EXPECT_GT(deep, 200);
  EXPECT_LT(widest_geo_m, 500e3);  // GEO: about 300 km of slack, far from any LEO shell
  std::printf("%d deep-space element sets inside their bounds; GEO slack at most %.0f m\n", deep,
              widest_geo_m);
}

// The primary alone survives (its copy raised to 12 rev/day, ~1,700 km, is set aside):
// no event, no error.
TEST(PrimaryPrefilter, NothingInTheShellIsNotAnError) {
  sgp4::Catalog cat = shipped();
  cat.objects.resize(2);
  cat.objects[1] = cat.objects[0];
  cat.objects[1].norad_id = 99999;
  cat.objects[1].mean_motion_revpday = 12.0;
  const ScreenCatalogResult r = screen(cat, cat.objects[0].norad_id, 3600.0, true);
  EXPECT_TRUE(r.events.empty());
  EXPECT_EQ(r.objects, 1);
  ASSERT_TRUE(r.prefilter);
  EXPECT_EQ(r.prefilter->removed_radius, 1);
}

}  // namespace
}  // namespace evade::conjunction
