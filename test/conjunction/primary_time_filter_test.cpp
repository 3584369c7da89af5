// The time filter of one satellite against a catalog (primary_time_filter.hpp): the speed and
// acceleration bounds it rests on hold on every object of the shipped catalog, every sampled
// approach within D lies inside a window, and an object it cannot bound (no radius bound, SGP4
// failing in the span, an unusable primary) is screened over the whole span.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "evade/conjunction/primary_prefilter.hpp"
#include "evade/conjunction/primary_time_filter.hpp"
#include "evade/sgp4/catalog.hpp"
#include "sgp4_test_catalog.hpp"

namespace evade::conjunction {
namespace {

std::vector<sgp4::MeanElements> shipped() { return testing::shipped_catalog().objects; }

// An object of the filter, over [start, start + span].
struct Bound {
  sgp4::Sgp4Propagator prop;
  FilterObject f;
  Bound(const sgp4::MeanElements& m, double start_j2000_s, double span_s) : prop(m) {
    const double offset_s = start_j2000_s - sgp4::epoch_seconds_since_j2000(m);
    f = sgp4_motion_bounds(prop, m, offset_s - kPrefilterPadS, offset_s + span_s + kPrefilterPadS);
    f.prop = &prop;
    f.offset_s = offset_s;
  }
  Eigen::Vector3d r(double t) const { return prop.propagate_s(f.offset_s + t).r_teme_m; }
};

// |d/dt r| by the central difference (tau = 0.05 s: truncation 4e-6 m/s in LEO), |d2/dt2 r| by
// the five-point difference (h = 5 s: 3e-6 m/s^2 of Kepler-iteration noise), and |SGP4 v -
// d/dt r|, every 120 s over one day, against the bounds and the allowance. Measured: the speed
// bound is 0.6 % above LEO speeds (the 1 % of a_cap), the acceleration bound 1 % above.
TEST(PrimaryTimeFilter, SpeedAndAccelerationBoundsHoldOnTheShippedCatalog) {
  const std::vector<sgp4::MeanElements> cat = shipped();
  const double start = sgp4::latest_epoch_seconds_since_j2000(cat), span = 86400.0;
  double speed_ratio = 0.0, accel_ratio = 0.0, v_diff = 0.0;
  long bounded = 0;
  for (const sgp4::MeanElements& m : cat) {
    const Bound b(m, start, span);
    if (!(b.f.speed_bound_mps > 0.0)) continue;  // no bound: the filter leaves it whole
    ++bounded;
    for (double t = 0.0; t <= span; t += 120.0) {
      const Eigen::Vector3d v = (b.r(t + 0.05) - b.r(t - 0.05)) / 0.1;
      const Eigen::Vector3d a = (-b.r(t - 10) + 16.0 * b.r(t - 5) - 30.0 * b.r(t) + 16.0 * b.r(t + 5) - b.r(t + 10)) / 300.0;
      speed_ratio = std::max(speed_ratio, v.norm() / b.f.speed_bound_mps);
      accel_ratio = std::max(accel_ratio, a.norm() / b.f.accel_bound_mps2);
      v_diff = std::max(v_diff, (b.prop.propagate_s(b.f.offset_s + t).v_teme_mps - v).norm() /
                                    velocity_allowance_mps(b.f.speed_bound_mps));
    }
  }
  std::printf("%ld of %zu objects bounded; largest |v| / bound %.5f, |a| / bound %.5f, "
              "|SGP4 v - dr/dt| / allowance %.4f\n",
              bounded, cat.size(), speed_ratio, accel_ratio, v_diff);
  EXPECT_EQ(bounded, static_cast<long>(cat.size()));
  EXPECT_LT(speed_ratio, 1.0);
  EXPECT_LT(accel_ratio, 1.0);
  EXPECT_LT(v_diff, 1.0);
}

// Primary 90000 against the objects the perigee/apogee filter keeps, D = 100 km over 1 day:
// every 4 s sample within D lies in a window (an approach within 100 km at up to 16 km/s lasts
// 12 s or more inside D, so it is sampled), and most objects get no window.
TEST(PrimaryTimeFilter, EverySampleWithinTheThresholdLiesInAWindow) {
  const std::vector<sgp4::MeanElements> cat = shipped();
  const double start = sgp4::latest_epoch_seconds_since_j2000(cat), span = 86400.0, d_m = 100e3;
  const std::vector<sgp4::MeanElements> kept = prefilter_primary(cat, 90000, start, span, d_m, nullptr, 2);
  ASSERT_EQ(kept.front().norad_id, 90000);
  TimeFilterOptions opt;
  opt.threshold_m = d_m;
  const Bound p(kept.front(), start, span);
  const PrimaryTrack track = primary_track(p.f, span, opt);
  ASSERT_TRUE(track.why_unusable.empty()) << track.why_unusable;
  long removed = 0, close_samples = 0, windows = 0;
  std::vector<Eigen::Vector3d> rp;
  for (double t = 0.0; t <= span; t += 4.0) rp.push_back(p.r(t));
  for (std::size_t k = 1; k < kept.size(); ++k) {
    const Bound j(kept[k], start, span);
    const ObjectWindows w = primary_time_windows(track, j.f, opt);
    EXPECT_FALSE(w.unfiltered) << kept[k].norad_id << ": " << w.why_unfiltered;
    removed += w.windows.empty() ? 1 : 0;
    windows += static_cast<long>(w.windows.size());
    for (std::size_t s = 0; s < rp.size(); ++s) {
      const double t = 4.0 * static_cast<double>(s);
      if ((j.r(t) - rp[s]).norm() > d_m) continue;
      ++close_samples;
      const bool inside = std::any_of(w.windows.begin(), w.windows.end(),
                                      [t](const TimeWindow& x) { return x.t0_s <= t && t <= x.t1_s; });
      EXPECT_TRUE(inside) << "NORAD " << kept[k].norad_id << " within D at t = " << t << " s outside every window";
    }
  }
  std::printf("%zu objects after perigee/apogee: %ld without a window, %ld windows, %ld samples within D\n",
              kept.size() - 1, removed, windows, close_samples);
  EXPECT_GT(close_samples, 0);                                      // not vacuous
  EXPECT_GT(removed, static_cast<long>(kept.size()) / 2);           // the point of the filter
}

TEST(PrimaryTimeFilter, AnObjectWithoutABoundIsScreenedOverTheWholeSpan) {
  const std::vector<sgp4::MeanElements> cat = shipped();
  const double start = sgp4::latest_epoch_seconds_since_j2000(cat), span = 3600.0;
  const Bound p(cat.front(), start, span);
  const PrimaryTrack track = primary_track(p.f, span, TimeFilterOptions{});
  Bound j(cat[1], start, span);
  j.f.speed_bound_mps = 0.0;
  const ObjectWindows w = primary_time_windows(track, j.f, TimeFilterOptions{});
  EXPECT_TRUE(w.unfiltered);
  ASSERT_EQ(w.windows.size(), 1u);
  EXPECT_EQ(w.windows[0].t0_s, 0.0);
  EXPECT_EQ(w.windows[0].t1_s, span);
  PrimaryTrack bad = track;
  bad.why_unusable = "primary: SGP4 error";
  EXPECT_TRUE(primary_time_windows(bad, Bound(cat[1], start, span).f, TimeFilterOptions{}).unfiltered);
}

// A LEO object that decays within the span (B* = 0.01 /ER at 15.9 rev/day: SGP4 reports decay
// 2.5 days into the span): SGP4 fails at the end, which
// the filter evaluates, so the object is screened over the whole span (and the screen rejects it).
TEST(PrimaryTimeFilter, AnObjectDecayingInTheSpanIsScreenedOverTheWholeSpan) {
  const std::vector<sgp4::MeanElements> cat = shipped();
  const double start = sgp4::latest_epoch_seconds_since_j2000(cat), span = 7.0 * 86400.0;
  sgp4::MeanElements m = cat.front();
  m.mean_motion_revpday = 15.9;
  m.eccentricity = 0.0005;
  m.bstar_per_er = 0.01;
  const Bound j(m, start, span);
  ASSERT_EQ(j.prop.propagate_s(j.f.offset_s).error, sgp4::Sgp4Error::kNone);
  ASSERT_NE(j.prop.propagate_s(j.f.offset_s + span).error, sgp4::Sgp4Error::kNone);  // it decays
  const Bound p(cat.front(), start, span);
  const ObjectWindows w = primary_time_windows(primary_track(p.f, span, TimeFilterOptions{}), j.f, TimeFilterOptions{});
  EXPECT_TRUE(w.unfiltered) << w.windows.size() << " windows";
  std::printf("decaying object: %s\n", w.why_unfiltered.c_str());
}

}  // namespace
}  // namespace evade::conjunction
