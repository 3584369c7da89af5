// Issue 24's no-miss check of the catalog screen as operators run it, both ways: all pairs
// (`evade screen --tle`) and one satellite against the catalog (`--primary`, after the
// perigee/apogee prefilter), through run_screen_catalog, the command's own call, against the
// fine-sampling reference (reference_screen.hpp: every pair's range rate every 1 s, each - to
// + sign change refined by Brent's method) driven by the same SGP4 motion. The catalogs are
// built to stress the screen and the prefilter (stress_catalog, sgp4_stress_catalog.hpp): slow
// co-orbital pairs, near-tangent and crossing pairs (sgp4_test_catalog.hpp), and around a
// primary in a 700 km sun-synchronous orbit its own co-orbital companions, near-tangent and
// crossing meetings, HEO objects whose perigee lies below its altitude (radius ranges that
// overlap its own) and high-drag objects whose perigee starts just above its band and decays
// into it during the span.
// Requirement: zero misses and nothing extra (the same approach: tca_tolerance_s below).
//
// ctest runs one catalog (seed 21, 500 objects) over 1 day; the five catalogs over 7 days
// (docs/VALIDATION.md) are the same test with EVADE_STRESS_FULL=1:
//   EVADE_STRESS_FULL=1 build/test/conjunction/conjunction_sgp4_stress_validation
// (EVADE_STRESS_SEEDS="21 22" runs a subset, e.g. one process per core;
// EVADE_STRESS_PRIMARY_ONLY=1 checks --primary alone, against the reference of its pairs.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "evade/conjunction/primary_path_filter.hpp"
#include "evade/conjunction/primary_prefilter.hpp"
#include "evade/conjunction/reference_screen.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/commands/screen_command.hpp"
#include "evade/conjunction/sgp4_motion.hpp"
#include "evade/sgp4/sgp4.hpp"
#include "sgp4_stress_catalog.hpp"
#include "sgp4_test_catalog.hpp"

namespace evade::conjunction {
namespace {

using namespace evade::commands;

using testing::kPrimary;
using testing::kThresholdM;
using testing::sgp4_radius_range;
using testing::stress_catalog;

// The same approach: the same pair, misses within 1 cm, and TCAs within the interval over
// which the distance stays within 1 cm of its minimum. Near a TCA, d(t) = sqrt(m^2 + v^2 dt^2)
// = m + v^2 dt^2 / (2 m): both screens find the same minimum to 1 cm of miss whenever their
// TCAs are within dt = sqrt(2 m 1 cm) / v of each other (1.6 s for a co-orbital pair passing
// at 3.3 km and 5 m/s; 7 ms at 14 km/s and 5 km). The TCA itself, the root of the range rate,
// is that ill-conditioned for slow pairs: SGP4's velocity carries small jumps (where its
// Kepler iteration count changes; sgp4_validation_test.cpp bounds their effect over 1 day by
// 1 ms + m 2e-4 / v^2), and over 7 days slow pairs' roots moved by up to 0.2 s between two
// brackets of the same smooth minimum. Distinct approaches of one pair are half an orbit or
// more apart: neither window can join two of them.
double tca_tolerance_s(double miss_m, double v_mps) {
  const double v = std::max(v_mps, 1e-3);
  return 1e-3 + std::max(miss_m * 2e-4 / (v * v), std::sqrt(2.0 * std::max(miss_m, 0.0) * 0.01) / v);
}

bool same_event(const CatalogEvent& e, long i, long j, double tca_s, double miss_m, double v_mps) {
  return ((e.norad_i == i && e.norad_j == j) || (e.norad_i == j && e.norad_j == i)) &&
         std::abs(e.tca_s - tca_s) < tca_tolerance_s(miss_m, v_mps) && std::abs(e.miss_m - miss_m) < 0.01;
}

struct Tally {
  long reference = 0, found = 0, missed = 0, extra = 0, slow = 0;
  double max_dtca_s = 0.0, max_dmiss_m = 0.0;  // over the matched approaches
  double max_dtca_of_window = 0.0;             // the largest |dTCA| / tca_tolerance_s
};

// Every reference event (restricted to the primary's when primary >= 0) is among the
// screen's, and the screen has nothing else.
Tally compare(const std::vector<CatalogEvent>& screen, const std::vector<Conjunction>& ref,
              const std::vector<long>& ids, long primary) {
  Tally t;
  std::vector<bool> matched(screen.size(), false);
  for (const Conjunction& r : ref) {
    const long i = ids[r.i], j = ids[r.j];
    if (primary >= 0 && i != primary && j != primary) continue;
    ++t.reference;
    t.slow += r.rel_speed_mps < 100.0 ? 1 : 0;
    bool hit = false;
    for (std::size_t k = 0; k < screen.size() && !hit; ++k) {
      if (!same_event(screen[k], i, j, r.tca_s, r.miss_m, r.rel_speed_mps)) continue;
      hit = matched[k] = true;
      const double dt = std::abs(screen[k].tca_s - r.tca_s);
      t.max_dtca_s = std::max(t.max_dtca_s, dt);
      t.max_dmiss_m = std::max(t.max_dmiss_m, std::abs(screen[k].miss_m - r.miss_m));
      t.max_dtca_of_window = std::max(t.max_dtca_of_window, dt / tca_tolerance_s(r.miss_m, r.rel_speed_mps));
    }
    t.found += hit ? 1 : 0;
    t.missed += hit ? 0 : 1;
    EXPECT_TRUE(hit) << "missed: " << i << " - " << j << " tca " << r.tca_s << " miss " << r.miss_m
                     << " v " << r.rel_speed_mps;
  }
  for (std::size_t k = 0; k < screen.size(); ++k) {
    t.extra += matched[k] ? 0 : 1;
    EXPECT_TRUE(matched[k]) << "extra: " << screen[k].norad_i << " - " << screen[k].norad_j
                            << " tca " << screen[k].tca_s;
  }
  return t;
}

ScreenCatalogResult screen(const std::vector<sgp4::MeanElements>& cat, double span_s, long primary) {
  ScreenCatalogRequest req;
  req.catalog.objects = cat;
  req.primary_norad = primary;
  req.span_s = span_s;
  req.robust.threshold_m = kThresholdM;
  req.threads = 2;
  req.validate();
  return run_screen_catalog(req);
}

bool primary_only() {
  const char* v = std::getenv("EVADE_STRESS_PRIMARY_ONLY");
  return v != nullptr && std::string(v) == "1";
}

void check_catalog(std::uint64_t seed, double span_s) {
  const std::vector<sgp4::MeanElements> cat = stress_catalog(seed, 500, span_s);
  ASSERT_EQ(cat.size(), 500u);
  Sgp4MotionOptions mo;
  mo.span_s = span_s;
  mo.threads = 2;
  const Sgp4Screening s = sgp4_screening(cat, mo);
  ASSERT_TRUE(s.rejected.empty()) << s.rejected.front().message();
  ScreenOptions opt;
  opt.motion = s.motion;
  opt.gravity = GravityModel::kTwoBodyJ2;
  opt.earth = wgs72_earth();
  opt.threshold_m = kThresholdM;
  opt.include_warning_radius = false;
  opt.threads = 2;
  if (primary_only())
    for (std::size_t k = 0; k < s.norad_ids.size(); ++k)
      if (s.norad_ids[k] == kPrimary) opt.primary = static_cast<long>(k);
  const ScreenResult ref = screen_reference(s.objects, span_s, 1.0, opt);
  const ScreenCatalogResult all = primary_only() ? ScreenCatalogResult{} : screen(cat, span_s, -1);
  const ScreenCatalogResult one = screen(cat, span_s, kPrimary);
  const Tally ta = primary_only() ? Tally{} : compare(all.events, ref.events, s.norad_ids, -1);
  const Tally tp = compare(one.events, ref.events, s.norad_ids, kPrimary);
  ASSERT_TRUE(one.prefilter.has_value());
  const PrimaryPrefilterCounts& pc = *one.prefilter;
  ASSERT_TRUE(one.time_filter.has_value());
  const TimeFilterCounts& tf = *one.time_filter;
  std::printf("seed %llu, %zu objects, %.0f s: all pairs: reference %ld (%ld slow < 100 m/s), "
              "screen %zu, missed %ld, extra %ld, largest |dTCA| %.3g s (%.2f of its window), "
              "|dmiss| %.2g m; primary: reference %ld, screen %zu, missed %ld, extra %ld; "
              "prefilter removed %ld (perigee/apogee) and %ld (orbit path) of %ld, kept %ld; time filter removed %ld, %ld windows (%.0f s), "
              "%ld screened over the whole span\n",
              static_cast<unsigned long long>(seed), cat.size(), span_s, ta.reference, ta.slow,
              all.events.size(), ta.missed, ta.extra, ta.max_dtca_s, ta.max_dtca_of_window,
              ta.max_dmiss_m, tp.reference, one.events.size(), tp.missed, tp.extra,
              pc.removed_radius, pc.removed_path, pc.objects, pc.kept, tf.removed, tf.windows, tf.window_s, tf.unfiltered);
  if (!primary_only()) {
    EXPECT_GT(ta.slow, 0) << "no slow approach: the catalog does not stress the screen";
  }
  EXPECT_GT(tp.reference, 0) << "no approach of the primary: nothing tested in --primary mode";
}

bool full() {
  const char* v = std::getenv("EVADE_STRESS_FULL");
  return v != nullptr && std::string(v) == "1";
}

// The seeds of the full run: EVADE_STRESS_SEEDS="21 23" (a subset, e.g. one per process), else
// all five.
std::vector<std::uint64_t> full_seeds() {
  std::vector<std::uint64_t> seeds;
  if (const char* v = std::getenv("EVADE_STRESS_SEEDS"); v != nullptr) {
    char* end = nullptr;
    for (const char* p = v;; p = end) {
      const unsigned long long x = std::strtoull(p, &end, 10);
      if (end == p) break;
      seeds.push_back(x);
    }
  }
  if (seeds.empty()) seeds = {21, 22, 23, 24, 25};
  return seeds;
}

TEST(Sgp4StressNoMiss, AllPairsAndPrimaryFindEveryReferenceApproach) {
  if (!full()) {
    check_catalog(21, 86400.0);
    return;
  }
  for (std::uint64_t seed : full_seeds()) check_catalog(seed, 7.0 * 86400.0);
}

// The drifters do what they are there for: above the primary's band + D over their first
// orbit, inside it by the end of the span (SGP4 with their B*).
TEST(Sgp4StressNoMiss, DriftersSinkIntoThePrimarysBand) {
  for (double span_s : {86400.0, 7.0 * 86400.0}) {
    const std::vector<sgp4::MeanElements> cat = stress_catalog(21, 500, span_s);
    const double band_top_m = sgp4_radius_range(cat[0], 0.0, span_s).max_m + kThresholdM;
    int drifters = 0, sank = 0;
    for (const sgp4::MeanElements& m : cat) {
      if (m.name.rfind("drift", 0) != 0) continue;
      ++drifters;
      EXPECT_GT(sgp4_radius_range(m, 0.0, 6000.0).min_m, band_top_m) << m.name << " starts inside";
      sank += sgp4_radius_range(m, span_s - 6000.0, span_s).min_m < band_top_m ? 1 : 0;
    }
    EXPECT_EQ(drifters, 4);
    EXPECT_EQ(sank, drifters) << "span " << span_s << " s";
  }
}

// The orbit-path filter (primary_path_filter.hpp) never clears a piece of the span in which
// SGP4 brings the pair within D: seed 21's catalog, 6 hours cut into 30-minute pieces, every
// object whose radius range comes within 100 km of the primary's, distances sampled every
// 1 s. A sampled distance is at least the true minimum over the piece, so a piece cleared for
// a D at or above its sampled minimum would be a miss (counted; must be 0) whatever the
// sampling step. The counts of cleared pieces show the filter is not vacuous on this catalog.
TEST(PrimaryPathFilter, NeverClearsAPieceWhereSgp4ComesWithinD) {
  const double span_s = 21600.0, piece_s = 1800.0;
  const std::vector<sgp4::MeanElements> cat = stress_catalog(21, 500, span_s);
  const double start_s = sgp4::latest_epoch_seconds_since_j2000(cat);
  const auto offset_s = [&](const sgp4::MeanElements& m) { return start_s - sgp4::epoch_seconds_since_j2000(m); };
  const sgp4::Sgp4Propagator p(cat[0]);
  ASSERT_EQ(cat[0].norad_id, kPrimary);
  const double po = offset_s(cat[0]);
  std::vector<Eigen::Vector3d> rp;
  for (double t = 0.0; t <= span_s; t += 1.0) rp.push_back(p.propagate_s(t + po).r_teme_m);
  const sgp4::RadiusBounds band = p.radius_bounds(po / 60.0, (po + span_s) / 60.0);
  const double d_m[4] = {1e3, 5e3, 20e3, 100e3};
  long pairs = 0, pieces = 0, within = 0, cleared = 0, cleared_5km = 0, misses = 0;
  for (std::size_t k = 1; k < cat.size(); ++k) {
    const sgp4::Sgp4Propagator j(cat[k]);
    const double jo = offset_s(cat[k]);
    const sgp4::RadiusBounds rj = j.radius_bounds(jo / 60.0, (jo + span_s) / 60.0);
    if (!rj.bounded || rj.min_m > band.max_m + 100e3 || rj.max_m < band.min_m - 100e3) continue;
    ++pairs;
    for (double t0 = 0.0; t0 < span_s; t0 += piece_s) {
      double dmin = 1e300;
      for (double t = t0; t <= t0 + piece_s; t += 1.0)
        dmin = std::min(dmin, (j.propagate_s(t + jo).r_teme_m - rp[static_cast<std::size_t>(t)]).norm());
      const sgp4::PathBounds bp = p.path_bounds((t0 + po) / 60.0, (t0 + piece_s + po) / 60.0);
      const sgp4::PathBounds bj = j.path_bounds((t0 + jo) / 60.0, (t0 + piece_s + jo) / 60.0);
      ++pieces;
      within += dmin <= 5e3 ? 1 : 0;
      for (const double d : d_m) {
        const bool clear = path_piece_clear(bp, bj, d);
        cleared += clear ? 1 : 0;
        cleared_5km += clear && d == 5e3 ? 1 : 0;
        if (clear && dmin <= d) {
          ++misses;
          ADD_FAILURE() << cat[k].name << " piece at " << t0 << " s cleared for D = " << d << " m, sampled "
                        << dmin << " m";
        }
      }
    }
  }
  EXPECT_EQ(misses, 0);
  EXPECT_GT(within, 10) << "too few pieces within 5 km: the check would be weak";
  EXPECT_GT(cleared_5km, pieces / 10) << "the filter clears almost nothing here";
  std::printf("%ld pairs, %ld pieces of 30 min: %ld within 5 km (sampled), %ld of %ld tests cleared "
              "(%ld at 5 km), none of them within its D\n",
              pairs, pieces, within, cleared, 4 * pieces, cleared_5km);
}

// Seed 24's primary and its co-orbital companion pco2 (5.1 m/s, 4.81 km) over 7 days: SGP4's
// small velocity jumps made the range rate cross zero twice, 0.47 s apart, at three of their
// 102 approaches, and the screen reported those three twice (the 7-day run of the test
// above found them as "extra"). One approach is one event: the same count and approaches
// as the reference.
TEST(Sgp4StressNoMiss, RepeatedRootsOfOneApproachAreOneEvent) {
  const std::vector<sgp4::MeanElements> cat = stress_catalog(24, 500, 7.0 * 86400.0);
  std::vector<sgp4::MeanElements> pair;
  for (const sgp4::MeanElements& m : cat)
    if (m.norad_id == kPrimary || m.name == "pco2") pair.push_back(m);
  ASSERT_EQ(pair.size(), 2u);
  Sgp4MotionOptions mo;
  mo.span_s = 7.0 * 86400.0;
  const Sgp4Screening s = sgp4_screening(pair, mo);
  ScreenOptions opt;
  opt.motion = s.motion;
  opt.gravity = GravityModel::kTwoBodyJ2;
  opt.earth = wgs72_earth();
  opt.threshold_m = kThresholdM;
  opt.include_warning_radius = false;
  opt.threads = 1;
  const ScreenResult ref = screen_reference(s.objects, mo.span_s, 1.0, opt);
  const ScreenResult rob = screen_robust(s.objects, mo.span_s, opt);
  EXPECT_GE(rob.stats.repeated_roots_merged, 3);
  ASSERT_EQ(rob.events.size(), ref.events.size());
  std::vector<CatalogEvent> found;
  for (const Conjunction& c : rob.events)
    found.push_back({s.norad_ids[c.i], s.norad_ids[c.j], "", "", c.tca_s, "", c.miss_m, c.rel_speed_mps});
  const Tally t = compare(found, ref.events, s.norad_ids, -1);
  EXPECT_EQ(t.missed, 0);
  EXPECT_EQ(t.extra, 0);
}

}  // namespace
}  // namespace evade::conjunction
