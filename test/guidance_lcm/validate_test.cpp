// Edge validation of every LCM message the node reads or the simulator takes (docs/GUIDANCE_NODE.md
// NODE-IN-2): each field's range and finiteness, the range ends accepted.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "evade/guidance/angles_measurement.hpp"
#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/validate.hpp"

namespace evade::guidance_lcm {
namespace {

evade_angles_t good_angles() {
  evade_angles_t a{};
  a.utime = 1;
  a.valid = true;
  a.elevation_rad = 0.3;
  a.azimuth_rad = -2.0;
  a.sigma_angle_rad = 1e-4;
  return a;
}

TEST(Validate, AcceptsGoodAnglesAndTheRangeEnds) {
  evade_angles_t a = good_angles();
  EXPECT_EQ(validate(a), Reason::kOk);
  a.elevation_rad = guidance::MeasurementLimits::kMaxElevationRad;
  a.azimuth_rad = -guidance::MeasurementLimits::kMaxAbsAzimuthRad;
  EXPECT_EQ(validate(a), Reason::kOk);
  a.sigma_angle_rad = guidance::MeasurementLimits::kMaxSigmaAngleRad;  // 0.5 rad, the .lcm's limit
  a.has_range = true;
  a.range_m = guidance::MeasurementLimits::kMaxRangeM;
  EXPECT_EQ(validate(a), Reason::kOk);
  a.valid = false;  // "no detection" is well formed: the law decides
  EXPECT_EQ(validate(a), Reason::kOk);
}

TEST(Validate, RejectsEachBadAngleField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    void (*mutate)(evade_angles_t&, double);
    Reason want;
  } cases[] = {
      {[](evade_angles_t& a, double n) { a.elevation_rad = n; }, Reason::kNotFinite},
      {[](evade_angles_t& a, double) { a.azimuth_rad = -INFINITY; }, Reason::kNotFinite},
      {[](evade_angles_t& a, double n) { a.sigma_angle_rad = n; }, Reason::kNotFinite},
      {[](evade_angles_t& a, double) { a.elevation_rad = 1.5708; }, Reason::kOutOfRange},
      {[](evade_angles_t& a, double) { a.azimuth_rad = 6.3; }, Reason::kOutOfRange},
      {[](evade_angles_t& a, double) { a.sigma_angle_rad = -1e-9; }, Reason::kOutOfRange},
      // Issue 46: a sensor with a 0.6 rad 1-sigma has every message refused; the .lcm comment
      // and NODE-IN-2 now say <= 0.5 rad (docs.LcmCommentsGiveTheNodesLimitsAndDeclaredConstants).
      {[](evade_angles_t& a, double) { a.sigma_angle_rad = 0.6; }, Reason::kOutOfRange},
      {[](evade_angles_t& a, double) { a.has_range = true; a.range_m = 1.0e8 * (1 + 1e-15); },
       Reason::kOutOfRange},
      {[](evade_angles_t& a, double n) { a.has_rates = true; a.azimuth_rate_radps = n; },
       Reason::kNotFinite},
      {[](evade_angles_t& a, double) { a.has_rates = true; a.elevation_rate_radps = 2e6; },
       Reason::kOutOfRange},
      {[](evade_angles_t& a, double) { a.has_range = true; a.range_m = 0.0; },
       Reason::kOutOfRange},
      {[](evade_angles_t& a, double n) { a.has_range = true; a.range_m = 10.0; a.range_rate_mps = n; },
       Reason::kNotFinite},
  };
  for (const auto& c : cases) {
    evade_angles_t a = good_angles();
    c.mutate(a, nan);
    EXPECT_EQ(validate(a), c.want);
  }
  // NaN in a field its flag marks unused still rejects the whole message: a sender that
  // writes NaN anywhere is broken, and its angles must not drive thrust (GUIDANCE_NODE.md
  // NODE-IN-2: every numeric field is checked).
  evade_angles_t a = good_angles();
  a.elevation_rate_radps = nan;
  EXPECT_EQ(validate(a), Reason::kNotFinite);
  a = good_angles();
  a.range_m = nan;
  EXPECT_EQ(validate(a), Reason::kNotFinite);
  a = good_angles();
  a.sigma_range_rate_mps = INFINITY;
  EXPECT_EQ(validate(a), Reason::kNotFinite);
}

TEST(Validate, CommandUnitVectorMustBeUnitWhenThrusting) {
  evade_thrust_cmd_t c{};
  c.mode = evade_thrust_cmd_t::MODE_EVADE;
  c.accel_mps2 = 1.0;
  c.u_eci[0] = 0.6;
  c.u_eci[1] = 0.8;
  EXPECT_EQ(validate(c), Reason::kOk);
  c.u_eci[1] = 0.81;
  EXPECT_EQ(validate(c), Reason::kOutOfRange);
  c.u_eci[0] = c.u_eci[1] = 0.0;
  c.accel_mps2 = 0.0;
  EXPECT_EQ(validate(c), Reason::kOk);  // zero thrust, zero direction
  c.accel_mps2 = -1.0;
  EXPECT_EQ(validate(c), Reason::kOutOfRange);
  c.accel_mps2 = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validate(c), Reason::kNotFinite);
  c.accel_mps2 = 0.0;
  c.mode = 9;
  EXPECT_EQ(validate(c), Reason::kOutOfRange);
}

// A lockstep tick's utime becomes the cycle time; the node adds its tolerances to it. A
// tick at INT64_MAX overflowed that sum (found with the lcm_sim_clock fuzz harness,
// docs/ASSURANCE.md): ticks are accepted only in [0, Limits::kMaxTickUtimeUs].
TEST(Validate, SimClockTickUtimeWithinZeroAndTheLimit) {
  evade_sim_clock_t t{};
  t.seq = 1;
  for (const std::int64_t ok : {std::int64_t{0}, std::int64_t{1000000}, Limits::kMaxTickUtimeUs}) {
    t.utime = ok;
    EXPECT_EQ(validate(t), Reason::kOk) << ok;
  }
  for (const std::int64_t bad : {std::int64_t{-1}, Limits::kMaxTickUtimeUs + 1,
                                 std::numeric_limits<std::int64_t>::max()}) {
    t.utime = bad;
    EXPECT_EQ(validate(t), Reason::kOutOfRange) << bad;
  }
}

// NODE-IN-2 for the nav state: every component finite, and position and velocity within
// the limits a spacecraft state can have (a corrupt but finite 1e300 is out of range).
TEST(Validate, NavStateMustBeFiniteAndWithinLimits) {
  evade_nav_state_t n{};
  n.valid = true;
  n.r_eci_m[0] = 7.0e6;
  n.v_eci_mps[1] = 7.5e3;
  EXPECT_EQ(validate(n), Reason::kOk);
  evade_nav_state_t bad = n;
  bad.v_eci_mps[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validate(bad), Reason::kNotFinite);
  bad = n;
  bad.r_eci_m[1] = -INFINITY;
  EXPECT_EQ(validate(bad), Reason::kNotFinite);
  bad = n;
  bad.r_eci_m[2] = 1.0e300;
  EXPECT_EQ(validate(bad), Reason::kOutOfRange);
  bad = n;
  bad.v_eci_mps[0] = 2.0 * Limits::kMaxVelocityMps;
  EXPECT_EQ(validate(bad), Reason::kOutOfRange);
}

// A range measurement needs non-negative sigmas; a tick needs a non-negative time; a
// command's mode is one of the five and a zero-thrust command's direction is zero or unit.
TEST(Validate, RangeSigmasTickTimeAndCommandModeAndDirection) {
  evade_angles_t a = good_angles();
  a.has_range = true;
  a.range_m = 1000.0;
  a.range_rate_mps = -10.0;
  EXPECT_EQ(validate(a), Reason::kOk);
  a.sigma_range_rate_mps = -0.1;
  EXPECT_EQ(validate(a), Reason::kOutOfRange);

  evade_sim_clock_t tick{};
  EXPECT_EQ(validate(tick), Reason::kOk);
  tick.utime = -1;
  EXPECT_EQ(validate(tick), Reason::kOutOfRange);
  EXPECT_EQ(validate(evade_arm_t{}), Reason::kOk);

  evade_thrust_cmd_t c{};
  c.mode = -1;
  EXPECT_EQ(validate(c), Reason::kOutOfRange);
  c.mode = evade_thrust_cmd_t::MODE_SAFE;
  c.u_eci[2] = 1.0;  // zero thrust along a unit direction: allowed
  EXPECT_EQ(validate(c), Reason::kOk);
  c.u_eci[2] = 0.5;  // zero thrust, neither zero nor unit: a broken sender
  EXPECT_EQ(validate(c), Reason::kOutOfRange);
  c.u_eci[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validate(c), Reason::kNotFinite);
}

// A range sigma is checked only when the range is flagged present; either negative one is
// out of range, and a commanded acceleration outside [0, kMaxAccelMps2] is too.
TEST(Validate, NegativeRangeSigmaAndAccelerationOutsideItsLimitsAreOutOfRange) {
  evade_angles_t a = good_angles();
  a.has_range = true;
  a.range_m = 1000.0;
  a.range_rate_mps = -10.0;
  a.sigma_range_m = -1e-9;
  EXPECT_EQ(validate(a), Reason::kOutOfRange);
  a.sigma_range_m = 0.0;
  a.sigma_range_rate_mps = -1e-9;
  EXPECT_EQ(validate(a), Reason::kOutOfRange);
  a.sigma_range_rate_mps = 0.0;
  EXPECT_EQ(validate(a), Reason::kOk);

  evade_thrust_cmd_t c{};
  c.mode = evade_thrust_cmd_t::MODE_EVADE;
  c.u_eci[0] = 1.0;
  c.accel_mps2 = Limits::kMaxAccelMps2;
  EXPECT_EQ(validate(c), Reason::kOk);
  c.accel_mps2 = std::nextafter(Limits::kMaxAccelMps2, 1e9);
  EXPECT_EQ(validate(c), Reason::kOutOfRange);
  c.accel_mps2 = -1e-12;
  EXPECT_EQ(validate(c), Reason::kOutOfRange);
  c.accel_mps2 = 0.5;
  c.u_eci[0] = 0.9;  // thrusting along a non-unit direction
  EXPECT_EQ(validate(c), Reason::kOutOfRange);
}

// The reason names key the node's input accounting in its JSON summary: one distinct
// snake_case name per reason, the ones docs/GUIDANCE_NODE.md quotes among them.
TEST(Validate, EveryRejectionReasonHasItsOwnName) {
  std::set<std::string> names;
  for (int r = 0; r < static_cast<int>(Reason::kCount); ++r) {
    const std::string n = reason_name(static_cast<Reason>(r));
    EXPECT_NE(n, "?");
    EXPECT_EQ(n.find_first_not_of("abcdefghijklmnopqrstuvwxyz_"), std::string::npos) << n;
    names.insert(n);
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(Reason::kCount));
  EXPECT_EQ(names.count("decode_failed"), 1u);
  EXPECT_EQ(names.count("seq_jump"), 1u);
  // The names are a table in enumerator order: the first, a middle and the last entry.
  EXPECT_STREQ(reason_name(Reason::kOk), "ok");
  EXPECT_STREQ(reason_name(Reason::kSeqJump), "seq_jump");
  EXPECT_STREQ(reason_name(Reason::kBadMac), "bad_mac");
  EXPECT_STREQ(reason_name(Reason::kNotPersisted), "not_persisted");
  EXPECT_STREQ(reason_name(Reason::kCount), "?");
}

}  // namespace
}  // namespace evade::guidance_lcm
