// GuidanceLaw (paper 000): modes, limits, arm flag, the −e_θ law, config validation.
// Closed-loop behaviours that need the truth (COAST after the encounter, Δv/burn limits on a
// real run, the sign proof) are in test/sim/.
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "evade/guidance/guidance_law.hpp"
#include "evade/guidance/los_geometry.hpp"

namespace {

using evade::Vec3;
using namespace evade::guidance;

constexpr std::int64_t kT0 = 5'000'000;
constexpr std::int64_t kCycle = 20'000;

// Head-on-ish straight-line relative motion seen from a satellite at 6.8e6 m on +x.
struct Geometry {
  Vec3 r0{0.0, 60e3, 10e3};
  Vec3 v{0.0, -6000.0, -1000.0 + 0.3};
  Vec3 rel_r(double t) const { return r0 + v * t; }
};

AnglesMeasurement measure(const Geometry& g, std::int64_t utime, bool with_range = false) {
  const double t = 1e-6 * static_cast<double>(utime - kT0);
  Vec3 u;
  Vec3 ud;
  los_from_relative(g.rel_r(t), g.v, &u, &ud);
  const LosAngles a = los_angles_from_unit(u);
  const double ce = std::cos(a.elevation_rad);
  const Vec3 y_s(-std::cos(a.azimuth_rad) * std::sin(a.elevation_rad),
                 -std::sin(a.azimuth_rad) * std::sin(a.elevation_rad), ce);
  const Vec3 z_s(std::sin(a.azimuth_rad), -std::cos(a.azimuth_rad), 0.0);
  AnglesMeasurement m;
  m.utime_us = utime;
  m.valid = true;
  m.elevation_rad = a.elevation_rad;
  m.azimuth_rad = a.azimuth_rad;
  m.has_rates = true;
  m.elevation_rate_radps = ud.dot(y_s);
  m.azimuth_rate_radps = -ud.dot(z_s) / ce;
  m.has_range = with_range;
  m.range_m = g.rel_r(t).norm();
  m.range_rate_mps = u.dot(g.v);
  return m;
}

GuidanceInput input(const Geometry& g, std::int64_t utime, bool armed) {
  GuidanceInput in;
  in.armed = armed;
  in.nav.valid = true;
  in.nav.utime_us = utime;
  in.nav.r_eci_m = Vec3(6.8e6, 0, 0);
  in.nav.v_eci_mps = Vec3(0, 7500, 0);
  in.has_measurement = true;
  in.meas = measure(g, utime);
  return in;
}

GuidanceConfig config() {
  GuidanceConfig c;
  c.max_accel_mps2 = 1.5;
  return c;
}

TEST(GuidanceLaw, EvadesAtMaxAccelAlongMinusEthetaWithZenithConvention) {
  const Geometry g;
  GuidanceLaw law(config());
  ThrustCommand c;
  for (int k = 0; k < 5; ++k) c = law.step(input(g, kT0 + k * kCycle, true), kT0 + k * kCycle);
  EXPECT_EQ(c.mode, GuidanceMode::kEvade);
  EXPECT_DOUBLE_EQ(c.accel_mps2, 1.5);
  // Truth: e_θ ∝ u̇ with e_ω = e_r × e_θ flipped to the zenith (+x) side.
  const double t = 4 * 0.02;
  Vec3 u;
  Vec3 ud;
  los_from_relative(g.rel_r(t), g.v, &u, &ud);
  Vec3 e_theta = ud.normalized();
  if (u.cross(e_theta).x() < 0.0) e_theta = -e_theta;
  EXPECT_LT((c.u_eci + e_theta).norm(), 1e-6);
  EXPECT_NEAR(c.u_eci.norm(), 1.0, 1e-12);
  EXPECT_NEAR(c.u_eci.dot(u), 0.0, 1e-9);  // perpendicular to the LOS
}

TEST(GuidanceLaw, DisarmedTracksButNeverThrusts) {
  const Geometry g;
  GuidanceLaw law(config());
  for (int k = 0; k < 50; ++k) {
    const ThrustCommand c = law.step(input(g, kT0 + k * kCycle, false), kT0 + k * kCycle);
    EXPECT_EQ(c.accel_mps2, 0.0);
    EXPECT_EQ(c.u_eci, Vec3::Zero());
    if (k > 2) {
      EXPECT_EQ(c.mode, GuidanceMode::kTracking);
      EXPECT_EQ(c.reason, CommandReason::kDisarmed);
    }
  }
  EXPECT_EQ(law.status().dv_used_mps, 0.0);
}

TEST(GuidanceLaw, StandbyWithoutMeasurements) {
  GuidanceLaw law(config());
  GuidanceInput in = input(Geometry{}, kT0, true);
  in.has_measurement = false;
  const ThrustCommand c = law.step(in, kT0);
  EXPECT_EQ(c.mode, GuidanceMode::kStandby);
  EXPECT_EQ(c.reason, CommandReason::kNoTrack);
  EXPECT_EQ(c.accel_mps2, 0.0);
}

TEST(GuidanceLaw, SafeWithZeroThrustOnInvalidNav) {
  const Geometry g;
  GuidanceLaw law(config());
  for (int k = 0; k < 3; ++k) law.step(input(g, kT0 + k * kCycle, true), kT0 + k * kCycle);
  GuidanceInput in = input(g, kT0 + 3 * kCycle, true);
  in.nav.valid = false;
  ThrustCommand c = law.step(in, kT0 + 3 * kCycle);
  EXPECT_EQ(c.mode, GuidanceMode::kSafe);
  EXPECT_EQ(c.reason, CommandReason::kNavInvalid);
  EXPECT_EQ(c.accel_mps2, 0.0);
  in = input(g, kT0 + 4 * kCycle, true);
  in.nav.r_eci_m.x() = NAN;
  c = law.step(in, kT0 + 4 * kCycle);
  EXPECT_EQ(c.mode, GuidanceMode::kSafe);
  EXPECT_EQ(c.reason, CommandReason::kNavInvalid);
  EXPECT_EQ(c.accel_mps2, 0.0);
  // Recovers as soon as the input is good again.
  c = law.step(input(g, kT0 + 5 * kCycle, true), kT0 + 5 * kCycle);
  EXPECT_EQ(c.mode, GuidanceMode::kEvade);
}

TEST(GuidanceLaw, SafeOnStaleNav) {
  const Geometry g;
  GuidanceLaw law(config());
  GuidanceInput in = input(g, kT0, true);
  in.nav.utime_us = kT0 - 600'000;  // 0.6 s old > stale_limit_s 0.5
  const ThrustCommand c = law.step(in, kT0);
  EXPECT_EQ(c.mode, GuidanceMode::kSafe);
  EXPECT_EQ(c.reason, CommandReason::kNavStale);
  EXPECT_EQ(c.accel_mps2, 0.0);
}

TEST(GuidanceLaw, SafeOnMalformedMeasurement) {
  const Geometry g;
  for (int which = 0; which < 4; ++which) {
    GuidanceLaw law(config());
    for (int k = 0; k < 3; ++k) law.step(input(g, kT0 + k * kCycle, true), kT0 + k * kCycle);
    GuidanceInput in = input(g, kT0 + 3 * kCycle, true);
    if (which == 0) in.meas.elevation_rad = NAN;
    if (which == 1) in.meas.azimuth_rad = INFINITY;
    if (which == 2) in.meas.elevation_rad = 2.0;  // > π/2
    if (which == 3) in.meas.sigma_angle_rad = -1.0;
    const ThrustCommand c = law.step(in, kT0 + 3 * kCycle);
    EXPECT_EQ(c.mode, GuidanceMode::kSafe) << which;
    EXPECT_EQ(c.reason, CommandReason::kMeasurementInvalid) << which;
    EXPECT_EQ(c.accel_mps2, 0.0) << which;
    EXPECT_EQ(law.status().meas_invalid, 1) << which;
  }
}

TEST(GuidanceLaw, SafeWhenMeasurementsStopWhileTracking) {
  const Geometry g;
  GuidanceLaw law(config());
  for (int k = 0; k < 3; ++k) law.step(input(g, kT0 + k * kCycle, true), kT0 + k * kCycle);
  ThrustCommand c;
  for (int k = 3; k < 40; ++k) {
    GuidanceInput in = input(g, kT0 + k * kCycle, true);
    in.has_measurement = false;
    c = law.step(in, kT0 + k * kCycle);
  }
  EXPECT_EQ(c.mode, GuidanceMode::kSafe);  // 0.74 s without data > stale_limit_s
  EXPECT_EQ(c.reason, CommandReason::kMeasurementStale);
  EXPECT_EQ(c.accel_mps2, 0.0);
}

TEST(GuidanceLaw, DvBudgetAndBurnTimeAreRespected) {
  const Geometry g;
  GuidanceConfig cfg = config();
  cfg.dv_budget_mps = 0.5;  // 1.5 m/s² → exhausted after 1/3 s
  GuidanceLaw law(cfg);
  ThrustCommand c;
  for (int k = 0; k < 100; ++k) c = law.step(input(g, kT0 + k * kCycle, true), kT0 + k * kCycle);
  EXPECT_EQ(c.mode, GuidanceMode::kCoast);
  EXPECT_EQ(c.reason, CommandReason::kDvBudgetExhausted);
  EXPECT_LE(law.status().dv_used_mps, 0.5 + 1e-9);
  EXPECT_GE(law.status().dv_used_mps, 0.5 - 1e-9);

  cfg = config();
  cfg.max_burn_s = 0.3;
  GuidanceLaw law2(cfg);
  for (int k = 0; k < 100; ++k) c = law2.step(input(g, kT0 + k * kCycle, true), kT0 + k * kCycle);
  EXPECT_EQ(c.mode, GuidanceMode::kCoast);
  EXPECT_EQ(c.reason, CommandReason::kBurnTimeExhausted);
  EXPECT_LE(law2.status().burn_s, 0.3 + 1e-9);
  EXPECT_GE(law2.status().burn_s, 0.3 - 0.02 - 1e-9);  // within one cycle of the limit
}

TEST(GuidanceLaw, RangeSensorGivesZemTgoAndCoastsWhenRangeRateTurnsPositive) {
  // Straight-line pass with a 10 km miss, closest approach at t = 10 s: ZEM (eq. 7) is above
  // the 5 km trigger, so the law only tracks; once the range rate turns positive: COAST.
  Geometry g;
  g.v = Vec3(0.0, -6000.0, 0.0);
  GuidanceConfig cfg = config();
  cfg.zem_trigger_m = 5000.0;
  GuidanceLaw law(cfg);
  bool saw_coast = false;
  for (int k = 0; k <= 520; ++k) {
    const std::int64_t now = kT0 + k * kCycle;
    GuidanceInput in = input(g, now, true);
    in.meas = measure(g, now, true);
    const ThrustCommand c = law.step(in, now);
    const double t = 0.02 * k;
    EXPECT_EQ(c.accel_mps2, 0.0) << "t = " << t;
    if (k == 2) {
      EXPECT_EQ(c.mode, GuidanceMode::kTracking);
      EXPECT_EQ(c.reason, CommandReason::kZemAboveTrigger);
      const Vec3 r = g.rel_r(t);
      const double rdot = r.normalized().dot(g.v);
      const double w = r.cross(g.v).norm() / r.squaredNorm();
      ASSERT_TRUE(law.status().zem_valid);
      EXPECT_NEAR(law.status().zem_m, r.squaredNorm() * w / -rdot, 1e-3);  // eq. 7
      ASSERT_TRUE(law.status().t_go_valid);
      EXPECT_NEAR(law.status().t_go_s, r.norm() / -rdot, 1e-9);  // eq. 12
    }
    if (k >= 1 && t < 9.99) {  // k = 0: one update < min_track_updates = 2: STANDBY
      EXPECT_EQ(c.mode, GuidanceMode::kTracking) << "t = " << t;
    }
    if (t > 10.01) {
      EXPECT_EQ(c.mode, GuidanceMode::kCoast) << "t = " << t;
      EXPECT_EQ(c.reason, CommandReason::kPassedClosestApproach);
      saw_coast = true;
    }
  }
  EXPECT_TRUE(saw_coast);
}

// Fuzz finding 10: a range rate of -1e-300 m/s (closing, but barely) gives t_go = 1e304 s,
// which has no µs time; the law keeps t_go in its status but predicts no closest approach,
// so when the range goes stale the t_go-elapsed trigger of the COAST latch cannot fire
// from it. Before the fix the time of closest approach was an
// out-of-range float-to-int conversion (INT64_MIN on x86: an "elapsed" TCA, COAST at once).
TEST(GuidanceLaw, NearZeroClosingRatePredictsNoClosestApproach) {
  Geometry g;
  g.v = Vec3(0.0, -6000.0, 0.0);  // the 10 km pass above: closest approach at t = 10 s
  GuidanceConfig cfg = config();
  cfg.zem_trigger_m = 5000.0;
  GuidanceLaw law(cfg);
  for (int k = 0; k <= 250; ++k) {  // 5 s, range only in the first 4 cycles
    const std::int64_t now = kT0 + k * kCycle;
    GuidanceInput in = input(g, now, true);
    in.meas = measure(g, now, k < 4);
    in.meas.range_rate_mps = -1e-300;
    const ThrustCommand c = law.step(in, now);
    if (k == 3) {
      ASSERT_TRUE(law.status().t_go_valid);
      EXPECT_GT(law.status().t_go_s, 1e300);
    }
    // Tracking, then (angles only once the range is stale) whatever the LOS-rate trigger
    // decides; never the COAST latch of a passed closest approach: it is 5 s ahead.
    if (k >= 1) {
      EXPECT_TRUE(c.mode == GuidanceMode::kTracking || c.mode == GuidanceMode::kEvade)
          << "t = " << 0.02 * k << ", mode " << mode_name(c.mode);
    }
    EXPECT_NE(c.reason, CommandReason::kPassedClosestApproach) << "t = " << 0.02 * k;
  }
}

TEST(GuidanceConfig, ValidateNamesTheFieldValueAndRange) {
  GuidanceConfig c;
  EXPECT_EQ(c.validate(), "");
  c.max_accel_mps2 = -1.0;
  EXPECT_NE(c.validate().find("max_accel_mps2"), std::string::npos);
  EXPECT_NE(c.validate().find("(0, 100]"), std::string::npos);
  EXPECT_THROW(GuidanceLaw{c}, std::invalid_argument);
  c = GuidanceConfig{};
  c.filter.process_noise_radps2 = NAN;
  EXPECT_NE(c.validate().find("filter.process_noise_radps2"), std::string::npos);
  c = GuidanceConfig{};
  c.stale_limit_s = INFINITY;
  EXPECT_NE(c.validate().find("stale_limit_s"), std::string::npos);
  c = GuidanceConfig{};
  c.min_track_updates = 0;
  EXPECT_NE(c.validate().find("min_track_updates"), std::string::npos);
}

// A measurement the sensor flags "no detection", or one that arrives after stale_limit_s,
// is counted as invalid and not fed to the filter, and the law does not go SAFE on it: the
// track and the evasion continue on the measurements that are timely (stage 1).
TEST(GuidanceLaw, NoDetectionAndLateMeasurementsAreCountedAndIgnoredWithoutSafe) {
  const Geometry g;
  GuidanceLaw law(config());
  ThrustCommand c;
  std::int64_t t = kT0;
  for (int k = 0; k < 5; ++k, t += kCycle) c = law.step(input(g, t, true), t);
  ASSERT_EQ(c.mode, GuidanceMode::kEvade);
  const long accepted = law.status().meas_accepted;

  GuidanceInput none = input(g, t, true);
  none.meas.valid = false;  // no detection this cycle
  c = law.step(none, t);
  EXPECT_EQ(c.mode, GuidanceMode::kEvade);
  EXPECT_EQ(law.status().meas_invalid, 1);
  EXPECT_EQ(law.status().meas_accepted, accepted);

  t += kCycle;
  GuidanceInput late = input(g, t, true);
  late.meas = measure(g, t - 600'000);  // 0.6 s old: beyond the default 0.5 s limit
  c = law.step(late, t);
  EXPECT_EQ(c.mode, GuidanceMode::kEvade);
  EXPECT_EQ(c.accel_mps2, 1.5);
  EXPECT_EQ(law.status().meas_invalid, 2);
  EXPECT_EQ(law.status().meas_accepted, accepted);
}

// reset() is a new encounter: no track (STANDBY), the cycle and Δv tallies from zero, and
// the full budget available to the next evasion.
TEST(GuidanceLaw, ResetForgetsTheTrackAndTheSpentBudget) {
  const Geometry g;
  GuidanceLaw law(config());
  std::int64_t t = kT0;
  for (int k = 0; k < 6; ++k, t += kCycle) law.step(input(g, t, true), t);
  ASSERT_EQ(law.status().mode, GuidanceMode::kEvade);
  ASSERT_GT(law.status().dv_used_mps, 0.0);

  law.reset();
  EXPECT_EQ(law.status().cycles, 0);
  EXPECT_EQ(law.status().dv_used_mps, 0.0);
  GuidanceInput in = input(g, t, true);
  in.has_measurement = false;
  ThrustCommand c = law.step(in, t);
  EXPECT_EQ(c.mode, GuidanceMode::kStandby);
  EXPECT_EQ(c.reason, CommandReason::kNoTrack);
  EXPECT_EQ(c.accel_mps2, 0.0);
  for (int k = 0; k < 5; ++k) {
    t += kCycle;
    c = law.step(input(g, t, true), t);
  }
  EXPECT_EQ(c.mode, GuidanceMode::kEvade);
  EXPECT_DOUBLE_EQ(c.accel_mps2, 1.5);
  EXPECT_EQ(law.status().cycles, 6);
}

// The mode and reason names are the output vocabulary of the simulator's CSV and JSON and of
// the node: one distinct name per value; a value outside the enum (a corrupted byte) is
// named UNKNOWN / unknown, never read out of a table.
TEST(GuidanceNames, EveryModeAndReasonHasItsOwnNameAndOthersAreUnknown) {
  std::set<std::string> modes;
  for (int m = 0; m <= static_cast<int>(GuidanceMode::kSafe); ++m) {
    modes.insert(mode_name(static_cast<GuidanceMode>(m)));
  }
  EXPECT_EQ(modes.size(), 5u);
  EXPECT_EQ(modes.count("UNKNOWN"), 0u);
  EXPECT_STREQ(mode_name(GuidanceMode::kEvade), "EVADE");
  EXPECT_STREQ(mode_name(static_cast<GuidanceMode>(200)), "UNKNOWN");

  std::set<std::string> reasons;
  for (int r = 0; r <= static_cast<int>(CommandReason::kLowLosRate); ++r) {
    reasons.insert(reason_name(static_cast<CommandReason>(r)));
  }
  EXPECT_EQ(reasons.size(), 12u);
  EXPECT_EQ(reasons.count("unknown"), 0u);
  EXPECT_STREQ(reason_name(CommandReason::kPassedClosestApproach), "passed_closest_approach");
  EXPECT_STREQ(reason_name(static_cast<CommandReason>(200)), "unknown");
}

}  // namespace
