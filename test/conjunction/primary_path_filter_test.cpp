// The orbit-path filter's bounds (sgp4::PathBounds, path_bounds.cpp) against SGP4 itself, and
// the filter on the shipped catalog: what primary_path_filter.hpp's argument rests on.
//  - Plane: SGP4's position direction uv lies in a plane whose normal W is within eps of the
//    centre normal Wc (node and inclination in their ranges), so |Wc . uv| <= eps.
//  - Radius against direction: uv's angle s_c in the centre plane is within asin(eps) of the
//    position's own argument of latitude su (the projection of uv on the centre plane is
//    within eps of the in-plane unit vector at su), so |r| lies in path_radius_in_arc over
//    s_c -+ asin(eps).
// Checked at every 30 s of 2-hour pieces spread over 7 days for every near-Earth element set
// of synthetic-1200.tle. The end-to-end check (no piece cleared where SGP4 comes within D) is
// in sgp4_stress_validation_test.cpp, on the stress catalogs (sgp4_stress_catalog.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "evade/conjunction/primary_path_filter.hpp"
#include "evade/conjunction/primary_prefilter.hpp"
#include "evade/commands/screen_command.hpp"
#include "evade/sgp4/catalog.hpp"
#include "sgp4_test_catalog.hpp"

namespace evade::conjunction {
namespace {

using namespace evade::commands;

TEST(PathBounds, PlaneAndRadiusAgainstDirectionHoldOnTheShippedCatalogOverSevenDays) {
  const sgp4::Catalog cat = testing::shipped_catalog();
  long objects = 0, states = 0;
  double worst_plane = 0.0, worst_radius = 0.0, arc_width_m = 0.0, orbit_width_m = 0.0;
  double closest_m = 1e300;  // of |r| to an end of its arc's range
  for (const sgp4::MeanElements& m : cat.objects) {
    const sgp4::Sgp4Propagator p(m);
    if (p.deep_space()) continue;
    ++objects;
    for (int day = 0; day < 7; ++day) {
      const double t0_s = day * 86400.0 + 3600.0 * (objects % 11), t1_s = t0_s + 7200.0;
      const sgp4::PathBounds b = p.path_bounds(t0_s / 60.0, t1_s / 60.0);
      ASSERT_TRUE(b.bounded) << m.norad_id;
      const PathCentrePlane c = path_centre_plane(b);
      const double w = std::asin(std::min(1.0, c.eps)) * (1.0 + 1e-9) + 1e-12;
      for (double t = t0_s; t <= t1_s; t += 30.0) {
        const sgp4::Sgp4State s = p.propagate_s(t);
        ASSERT_EQ(s.error, sgp4::Sgp4Error::kNone) << m.norad_id;
        const double r = s.r_teme_m.norm();
        const Eigen::Vector3d uv = s.r_teme_m / r;
        worst_plane = std::max(worst_plane, std::abs(c.w.dot(uv)) / c.eps);
        ASSERT_LE(std::abs(c.w.dot(uv)), c.eps * (1.0 + 1e-9) + 1e-12) << m.norad_id << " t " << t;
        const double sc = std::atan2(uv.dot(c.m), uv.dot(c.n));
        const sgp4::RadiusBounds rb = sgp4::path_radius_in_arc(b, sc - w, sc + w);
        ASSERT_TRUE(rb.bounded);
        ASSERT_GE(r, rb.min_m) << m.norad_id << " t " << t;
        ASSERT_LE(r, rb.max_m) << m.norad_id << " t " << t;
        // How much of the arc's range the radius uses (1: at an end of it).
        const double mid = 0.5 * (rb.min_m + rb.max_m), half = 0.5 * (rb.max_m - rb.min_m);
        worst_radius = std::max(worst_radius, std::abs(r - mid) / half);
        closest_m = std::min({closest_m, r - rb.min_m, rb.max_m - r});
        arc_width_m += rb.max_m - rb.min_m;
        orbit_width_m += b.radius.max_m - b.radius.min_m;
        ++states;
      }
    }
  }
  EXPECT_GT(objects, 900);
  std::printf("%ld near-Earth element sets, %ld states: |Wc.uv| at most %.3f of eps; |r| at most "
              "%.4f of the arc's half range from its middle (%.3f m from an end); the arc's range %.0f m on average "
              "against %.0f m for the whole orbit\n",
              objects, states, worst_plane, worst_radius, closest_m, arc_width_m / static_cast<double>(states),
              orbit_width_m / static_cast<double>(states));
}

sgp4::MeanElements leo(long norad, double rev_per_day, double e, double incl_deg, double argp_deg,
                       double mean_anomaly_deg) {
  sgp4::MeanElements m;
  m.norad_id = norad;
  m.name = "P" + std::to_string(norad);
  m.epoch_year = 2026;
  m.epoch_day_of_year = 318.5;
  m.mean_motion_revpday = rev_per_day;
  m.eccentricity = e;
  m.inclination_deg = incl_deg;
  m.raan_deg = 0.0;
  m.arg_perigee_deg = argp_deg;
  m.mean_anomaly_deg = mean_anomaly_deg;
  m.bstar_per_er = 2e-5;
  return m;
}

// A 700 km sun-synchronous primary; an eccentric crosser (e = 0.05, 442-1158 km: its radius
// range holds the primary's, so the perigee/apogee filter keeps it) whose apsides lie on the
// line of mutual nodes: at the nodes it is 250 km below or 450 km above the primary, so the
// path filter sets it aside over 7 days (the nodes' regression and the apsides' turn move
// those radii by tens of km, not hundreds). The primary's co-orbital companion, 0.01 deg
// behind (1.2 km), and the same crosser with its apsides turned by 90 deg (it crosses the
// primary's radius at the nodes) are kept.
TEST(PrimaryPathFilter, SetsAsideACrosserWhoseNodesMissTheShellAndKeepsTheOthers) {
  const sgp4::MeanElements primary = leo(1, 14.58, 0.001, 97.9, 0.0, 0.0);
  const sgp4::MeanElements companion = leo(2, 14.58, 0.001, 97.9, 0.0, -0.01);
  const sgp4::MeanElements crosser = leo(3, 14.28, 0.05, 50.0, 0.0, 40.0);
  const sgp4::MeanElements turned = leo(4, 14.28, 0.05, 50.0, 90.0, 40.0);
  const sgp4::Sgp4Propagator p(primary);
  const double span_s = 7.0 * 86400.0;
  const auto test = [&](const sgp4::MeanElements& m) {
    return path_never_within(p, 0.0, sgp4::Sgp4Propagator(m), 0.0, -kPrefilterPadS, span_s + kPrefilterPadS,
                             5000.0);
  };
  const PathFilterResult a = test(crosser), b = test(companion), c = test(turned);
  EXPECT_TRUE(a.never_within) << a.tests << " tests";
  EXPECT_FALSE(b.never_within);
  EXPECT_FALSE(c.never_within);
  // The perigee/apogee filter keeps all three (the crosser's radius range holds the primary's).
  const sgp4::RadiusBounds rp = p.radius_bounds(0.0, span_s / 60.0);
  for (const sgp4::MeanElements& m : {crosser, turned}) {
    const sgp4::RadiusBounds rj = sgp4::Sgp4Propagator(m).radius_bounds(0.0, span_s / 60.0);
    EXPECT_LT(rj.min_m, rp.min_m);
    EXPECT_GT(rj.max_m, rp.max_m);
  }
  // Through the prefilter: counted, and the crosser alone set aside.
  PrimaryPrefilterCounts counts;
  const std::vector<sgp4::MeanElements> kept = prefilter_primary(
      {primary, companion, crosser, turned}, 1, sgp4::epoch_seconds_since_j2000(primary), span_s, 5000.0,
      &counts, 2);
  EXPECT_EQ(counts.removed_radius, 0);
  EXPECT_EQ(counts.removed_path, 1);
  EXPECT_EQ(counts.kept, 3);
  EXPECT_EQ(counts.kept + counts.removed_radius + counts.removed_path, counts.objects);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[2].norad_id, 4);
  std::printf("crosser set aside after %ld tests of pieces; companion kept after %ld, turned crosser after %ld\n",
              a.tests, b.tests, c.tests);
}

}  // namespace
}  // namespace evade::conjunction
