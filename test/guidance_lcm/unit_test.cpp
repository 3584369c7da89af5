// Unit tests of the guidance_lcm pieces: validation ranges, bit-exact conversion, the seq
// tracker, the bounded queue's drop-oldest policy and the cycle statistics
// (docs/GUIDANCE_NODE.md NODE-IN-2..4, NODE-IF-2, NODE-RT-3).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/cycle_stats.hpp"
#include "evade/guidance_lcm/internal/input_queue.hpp"
#include "evade/guidance_lcm/internal/seq_tracker.hpp"
#include "evade/guidance_lcm/lcm_url.hpp"
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

TEST(Convert, AnglesAndNavRoundTripBitExact) {
  guidance::AnglesMeasurement m;
  m.utime_us = 123456789;
  m.seq = 5;
  m.elevation_rad = 0.1 + 1e-17;
  m.azimuth_rad = std::nextafter(1.0, 2.0);
  m.sigma_angle_rad = 3e-6;
  m.has_rates = true;
  m.elevation_rate_radps = 1.234567890123e-9;
  m.azimuth_rate_radps = -4e-9;
  m.sigma_rate_radps = 1e-10;
  m.has_range = true;
  m.range_m = 10000.000000001;
  m.range_rate_mps = -6712.4;
  m.valid = true;
  evade_angles_t msg{};
  to_lcm(m, 77, &msg);
  std::uint8_t buf[512];
  const int n = msg.encode(buf, 0, sizeof(buf));
  evade_angles_t back{};
  ASSERT_EQ(back.decode(buf, 0, n), n);
  guidance::AnglesMeasurement m2;
  from_lcm(back, &m2);
  EXPECT_EQ(m2.utime_us, m.utime_us);
  EXPECT_EQ(m2.seq, 77);
  EXPECT_EQ(m2.elevation_rad, m.elevation_rad);
  EXPECT_EQ(m2.azimuth_rad, m.azimuth_rad);
  EXPECT_EQ(m2.elevation_rate_radps, m.elevation_rate_radps);
  EXPECT_EQ(m2.range_m, m.range_m);
  EXPECT_EQ(m2.range_rate_mps, m.range_rate_mps);

  guidance::NavState nav;
  nav.utime_us = 42;
  nav.r_eci_m = Vec3(7.0e6 + 1e-9, -1.0 / 3.0, 2.0);
  nav.v_eci_mps = Vec3(1.0 / 7.0, 7546.123456789, -0.0);
  nav.valid = true;
  evade_nav_state_t nm{};
  to_lcm(nav, 3, &nm);
  guidance::NavState nav2;
  from_lcm(nm, &nav2);
  EXPECT_EQ(nav2.r_eci_m, nav.r_eci_m);
  EXPECT_EQ(nav2.v_eci_mps, nav.v_eci_mps);
  EXPECT_EQ(nav2.utime_us, 42);
}

// The command and the status the node publishes, read back by a subscriber (the simulator,
// the HIL scripts): bit-exact through the encoded bytes. The status carries ZEM and t_go
// only as a pair (has_range), and never a stale value of an invalid one.
TEST(Convert, CommandAndStatusRoundTripBitExact) {
  guidance::ThrustCommand c;
  c.utime_us = 1700000000123456LL;
  c.mode = guidance::GuidanceMode::kEvade;
  c.u_eci = Vec3(1.0 / 3.0, -std::sqrt(5.0 / 9.0), 1.0 / 3.0);
  c.accel_mps2 = 0.1 + 1e-17;
  c.reason = guidance::CommandReason::kLowLosRate;
  evade_thrust_cmd_t cm{};
  to_lcm(c, 41, 1700000000100000LL, &cm);
  std::uint8_t buf[1024];
  int n = cm.encode(buf, 0, sizeof(buf));
  evade_thrust_cmd_t cback{};
  ASSERT_EQ(cback.decode(buf, 0, n), n);
  EXPECT_EQ(cback.seq, 41);
  EXPECT_EQ(cback.input_utime, 1700000000100000LL);
  guidance::ThrustCommand c2;
  from_lcm(cback, &c2);
  EXPECT_EQ(c2.utime_us, c.utime_us);
  EXPECT_EQ(c2.mode, c.mode);
  EXPECT_EQ(c2.u_eci, c.u_eci);
  EXPECT_EQ(c2.accel_mps2, c.accel_mps2);
  EXPECT_EQ(c2.reason, c.reason);

  guidance::GuidanceStatus s;
  s.mode = guidance::GuidanceMode::kTracking;
  s.reason = guidance::CommandReason::kZemAboveTrigger;
  s.track_valid = true;
  s.los_rate_radps = 1.234567890123e-3;
  s.los_rate_var_rad2ps2 = 1e-13;
  s.e_theta_eci = Vec3(0.0, std::nextafter(1.0, 0.0), -0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s.e_theta_cov_eci(i, j) = 1e-6 * (3 * i + j + 1) / 7.0;
  s.zem_valid = s.t_go_valid = true;
  s.zem_m = 123.456789;
  s.t_go_s = 9.87654321;
  s.dv_used_mps = 0.75;
  evade_guidance_status_t sm{};
  to_lcm(s, &sm);
  sm.utime = 99;
  sm.cycles = 1234;
  n = sm.encode(buf, 0, sizeof(buf));
  evade_guidance_status_t sback{};
  ASSERT_EQ(sback.decode(buf, 0, n), n);
  guidance::GuidanceStatus s2;
  from_lcm(sback, &s2);
  EXPECT_EQ(s2.utime_us, 99);
  EXPECT_EQ(s2.cycles, 1234);
  EXPECT_EQ(s2.mode, s.mode);
  EXPECT_EQ(s2.reason, s.reason);
  EXPECT_EQ(s2.track_valid, s.track_valid);
  EXPECT_EQ(s2.los_rate_radps, s.los_rate_radps);
  EXPECT_EQ(s2.los_rate_var_rad2ps2, s.los_rate_var_rad2ps2);
  EXPECT_EQ(s2.e_theta_eci, s.e_theta_eci);
  EXPECT_EQ(s2.e_theta_cov_eci, s.e_theta_cov_eci);
  EXPECT_TRUE(s2.zem_valid && s2.t_go_valid);
  EXPECT_EQ(s2.zem_m, s.zem_m);
  EXPECT_EQ(s2.t_go_s, s.t_go_s);
  EXPECT_EQ(s2.dv_used_mps, s.dv_used_mps);

  // One of the pair invalid: no range, and the invalid one is sent as 0, not its old value.
  s.t_go_valid = false;
  to_lcm(s, &sm);
  EXPECT_FALSE(sm.has_range);
  EXPECT_EQ(sm.zem_m, s.zem_m);
  EXPECT_EQ(sm.t_go_s, 0.0);
  s.zem_valid = false;
  s.t_go_valid = true;
  to_lcm(s, &sm);
  EXPECT_FALSE(sm.has_range);
  EXPECT_EQ(sm.zem_m, 0.0);
  EXPECT_EQ(sm.t_go_s, s.t_go_s);
  from_lcm(sm, &s2);
  EXPECT_FALSE(s2.zem_valid || s2.t_go_valid);
}

TEST(SeqTracker, ClassifiesDuplicateOutOfOrderAndGaps) {
  SeqTracker s;
  std::int64_t gaps = -1;
  EXPECT_EQ(s.check(10, 100, &gaps), Reason::kOk);
  EXPECT_EQ(gaps, 0);
  EXPECT_EQ(s.check(10, 100, &gaps), Reason::kDuplicateSeq);
  EXPECT_EQ(s.check(9, 90, &gaps), Reason::kOutOfOrderSeq);
  EXPECT_EQ(s.check(11, 110, &gaps), Reason::kOk);
  EXPECT_EQ(s.check(15, 150, &gaps), Reason::kOk);
  EXPECT_EQ(gaps, 3);
  EXPECT_EQ(s.last(), 15);
}

// NODE-IN-4: one spoofed or corrupted seq far ahead is rejected and does not capture the
// channel: the genuine next message still continues the sequence and is accepted.
TEST(SeqTracker, OneSpoofedJumpCannotLockOutTheSender) {
  SeqTracker s(1000);
  std::int64_t gaps = 0;
  EXPECT_EQ(s.check(5, 50, &gaps), Reason::kOk);
  EXPECT_EQ(s.check(5 + 1000000000000LL, 60, &gaps), Reason::kSeqJump);
  for (std::int64_t k = 6; k < 20; ++k) {
    EXPECT_EQ(s.check(k, 10 * k + 10, &gaps), Reason::kOk) << "seq " << k;
    EXPECT_EQ(gaps, 0);
  }
  EXPECT_EQ(s.restarts(), 0);
}

// NODE-IN-4: a genuine sender restart (seq back to 0, time going on) is confirmed by the
// message after it and the channel follows the new sequence; one message is lost.
TEST(SeqTracker, GenuineRestartIsConfirmedByTheNextMessage) {
  SeqTracker s(1000);
  std::int64_t gaps = 0;
  for (std::int64_t k = 100; k < 110; ++k) ASSERT_EQ(s.check(k, 10 * k, &gaps), Reason::kOk);
  EXPECT_EQ(s.check(0, 2000, &gaps), Reason::kOutOfOrderSeq);  // candidate
  EXPECT_EQ(s.check(1, 2010, &gaps), Reason::kOk);             // confirms the restart
  EXPECT_EQ(gaps, 0);
  EXPECT_EQ(s.restarts(), 1);
  EXPECT_EQ(s.check(2, 2020, &gaps), Reason::kOk);
  EXPECT_EQ(s.last(), 2);
}

// A late (reordered) message never confirms a restart: its time is older.
TEST(SeqTracker, ReorderedLateMessagesNeverConfirmARestart) {
  SeqTracker s(1000);
  std::int64_t gaps = 0;
  for (std::int64_t k = 1; k <= 10; ++k) ASSERT_EQ(s.check(k, 10 * k, &gaps), Reason::kOk);
  EXPECT_EQ(s.check(7, 70, &gaps), Reason::kOutOfOrderSeq);
  EXPECT_EQ(s.check(8, 80, &gaps), Reason::kOutOfOrderSeq);
  EXPECT_EQ(s.restarts(), 0);
  EXPECT_EQ(s.check(11, 110, &gaps), Reason::kOk);
}

// Extreme values: differences are unsigned, so INT64_MIN then INT64_MAX is no overflow
// (it was undefined behaviour and gave -2 gaps) and no gap is ever negative.
TEST(SeqTracker, ExtremeSeqValuesNeitherOverflowNorGiveNegativeGaps) {
  SeqTracker s(1000);
  std::int64_t gaps = 0;
  const std::int64_t lo = std::numeric_limits<std::int64_t>::min();
  const std::int64_t hi = std::numeric_limits<std::int64_t>::max();
  EXPECT_EQ(s.check(lo, 1, &gaps), Reason::kOk);
  EXPECT_EQ(s.check(hi, 2, &gaps), Reason::kSeqJump);  // 2^64 - 1 ahead: implausible
  EXPECT_EQ(gaps, 0);
  EXPECT_EQ(s.check(lo + 3, 3, &gaps), Reason::kOk);
  EXPECT_EQ(gaps, 2);
  SeqTracker t(1000);
  EXPECT_EQ(t.check(hi - 1, 1, &gaps), Reason::kOk);
  EXPECT_EQ(t.check(hi, 2, &gaps), Reason::kOk);
  EXPECT_EQ(gaps, 0);
  EXPECT_EQ(t.check(lo, 3, &gaps), Reason::kOk);  // the sequence wraps modulo 2^64
  EXPECT_EQ(gaps, 0);
}

TEST(InputQueue, DropsOldestWhenFull) {
  InputQueue q(3);
  for (std::uint8_t i = 0; i < 5; ++i) {
    const bool kept = q.push(Input::kAngles, 0, 0, &i, 1);
    EXPECT_EQ(kept, i < 3);
  }
  ASSERT_EQ(q.size(), 3u);
  for (std::uint8_t want = 2; want < 5; ++want) {
    EXPECT_EQ(q.front().data[0], want);
    q.pop();
  }
  EXPECT_TRUE(q.empty());
}

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
// NODE-IN-6: a udpm:// input gets the node's receive buffer unless the URL sets one.
TEST(LcmUrl, UdpmGetsTheReceiveBufferOthersUnchanged) {
  EXPECT_EQ(lcm_url_with_recv_buf("", nullptr, 8388608),
            "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=8388608");
  EXPECT_EQ(lcm_url_with_recv_buf("", "udpm://239.1.2.3:7000", 1024),
            "udpm://239.1.2.3:7000?recv_buf_size=1024");
  EXPECT_EQ(lcm_url_with_recv_buf("udpm://239.1.2.3:7000?recv_buf_size=5", nullptr, 1024),
            "udpm://239.1.2.3:7000?recv_buf_size=5");
  EXPECT_EQ(lcm_url_with_recv_buf("memq://", nullptr, 1024), "memq://");
  EXPECT_EQ(lcm_url_with_recv_buf("file:///x.log?speed=0", nullptr, 1024), "file:///x.log?speed=0");
}

}  // namespace evade::guidance_lcm
