// Event location on the DOP853 dense output: closest approach of two Kepler orbits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "evade/dynamics/events.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/dynamics/kepler_propagator.hpp"
#include "test_orbits.hpp"

namespace evade {
namespace {

using Vec12 = Eigen::Matrix<double, 12, 1>;
const double kMu = kEarthDefault.mu_m3ps2;

// Two circular orbits: A equatorial at radius R, B inclined 30 deg at R + dr, phased so
// both reach the node line (+x axis) at t = kTca. There the separation is dr along x and
// the relative velocity (along y and z) is perpendicular to it, so the range rate is zero
// at kTca exactly: an independent truth for the time of closest approach.
constexpr double kR = 7000e3;
constexpr double kDr = 100.0;
constexpr double kTca = 1500.0;
constexpr double kIncl = 30.0 * kDegToRad;

struct Pair {
  StateEci a;
  StateEci b;
};

Pair make_pair_at_t0() {
  const double na = std::sqrt(kMu / (kR * kR * kR));
  const double rb = kR + kDr;
  const double nb = std::sqrt(kMu / (rb * rb * rb));
  return {test::orbit_state(kR, 0.0, 0.0, 0.0, 0.0, -na * kTca),
          test::orbit_state(rb, 0.0, kIncl, 0.0, 0.0, -nb * kTca)};
}

Vec12 stack(const Pair& p) {
  Vec12 x;
  x << p.a.stacked(), p.b.stacked();
  return x;
}

Vec12 two_orbits(double, const Vec12& x) {
  Vec12 d;
  d << orbit_derivative(x.head<6>(), GravityModel::kTwoBody, kEarthDefault),
      orbit_derivative(x.tail<6>(), GravityModel::kTwoBody, kEarthDefault);
  return d;
}

double range_rate_like(double, const Vec12& x) {  // (r_b - r_a).(v_b - v_a) = range * range rate
  return (x.segment<3>(6) - x.head<3>()).dot(x.segment<3>(9) - x.segment<3>(3));
}

double kepler_range_m(const Pair& p0, double t) {
  return (propagate_kepler(p0.b, t, kMu).r_eci_m - propagate_kepler(p0.a, t, kMu).r_eci_m).norm();
}

// Brute force on the analytic orbits: coarse grid (1 s), then 1 ms, then 1 us around the
// best sample. Returns the grid time of least range (resolution 1 us).
double brute_force_tca_s(const Pair& p0, double t0, double t1) {
  double best = t0;
  double step = 1.0;
  double lo = t0;
  double hi = t1;
  for (int level = 0; level < 3; ++level) {
    double best_range = INFINITY;
    const long count = std::lround((hi - lo) / step);
    for (long k = 0; k <= count; ++k) {
      const double t = lo + step * static_cast<double>(k);
      const double r = kepler_range_m(p0, t);
      if (r < best_range) {
        best_range = r;
        best = t;
      }
    }
    lo = best - step;
    hi = best + step;
    step *= 1e-3;
  }
  return best;
}

// Event time error budget: the tight preset keeps position errors < 1 mm (adaptive test);
// divided by the relative speed (~3.9 km/s) that is < 3e-7 s, plus the 1e-9 s Brent
// tolerance: well inside the 1 us requirement.
TEST(Events, FindsTimeOfClosestApproachOfTwoKeplerOrbitsToOneMicrosecond) {
  const Pair p0 = make_pair_at_t0();
  EventOptions ev_opt;
  ev_opt.direction = EventDirection::kRising;  // range rate - -> + : a minimum of range
  const auto events = propagate_until_events(two_orbits, 0.0, stack(p0), 3000.0, range_rate_like,
                                             AdaptiveOptions::tight(), ev_opt);
  ASSERT_EQ(events.size(), 1u);
  // Grid deliberately not aligned with kTca (starts at 0.1234567 s).
  const double t_brute = brute_force_tca_s(p0, 0.1234567, 3000.0);
  std::printf("TCA: event - truth = %.3e s, brute force - truth = %.3e s (truth %.1f s)\n",
              events[0].t_s - kTca, t_brute - kTca, kTca);
  EXPECT_NEAR(events[0].t_s, kTca, 1e-6);
  EXPECT_NEAR(t_brute, kTca, 1e-6);
  EXPECT_EQ(events[0].direction, +1);
  // The state at the event is the dense output: both objects where Kepler puts them (1 mm).
  EXPECT_LT((events[0].x.head<3>() - propagate_kepler(p0.a, kTca, kMu).r_eci_m).norm(), 1e-3);
  EXPECT_LT((events[0].x.segment<3>(6) - propagate_kepler(p0.b, kTca, kMu).r_eci_m).norm(), 1e-3);
  EXPECT_NEAR((events[0].x.segment<3>(6) - events[0].x.head<3>()).norm(), kDr, 1e-3);
}

// Without the direction filter the range maxima (a quarter orbit either side) appear too,
// marked as falling, in time order.
TEST(Events, ReportsMinimaAndMaximaWithTheirDirections) {
  const Pair p0 = make_pair_at_t0();
  const auto events = propagate_until_events(two_orbits, 0.0, stack(p0), 3000.0, range_rate_like,
                                             AdaptiveOptions::tight());
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].direction, -1);
  EXPECT_EQ(events[1].direction, +1);
  EXPECT_EQ(events[2].direction, -1);
  EXPECT_NEAR(events[1].t_s, kTca, 1e-6);
  EXPECT_LT(events[0].t_s, events[1].t_s);
  EXPECT_LT(events[1].t_s, events[2].t_s);
  // Maxima are a quarter of the (nearly common) period away from the node crossing; the
  // 100 m radius difference shifts them by O(dr/R) of that, i.e. < 1 s.
  const double quarter = 0.25 * kTwoPi * std::sqrt(kR * kR * kR / kMu);
  EXPECT_NEAR(events[0].t_s, kTca - quarter, 1.0);
  EXPECT_NEAR(events[2].t_s, kTca + quarter, 1.0);
}

// Backward integration finds the same minimum, still labelled rising in physical time.
TEST(Events, WorksWhenIntegratingBackwardInTime) {
  const Pair p0 = make_pair_at_t0();
  const Vec12 x_end = stack({propagate_kepler(p0.a, 3000.0, kMu), propagate_kepler(p0.b, 3000.0, kMu)});
  EventOptions ev_opt;
  ev_opt.direction = EventDirection::kRising;
  const auto events = propagate_until_events(two_orbits, 3000.0, x_end, 0.0, range_rate_like,
                                             AdaptiveOptions::tight(), ev_opt);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NEAR(events[0].t_s, kTca, 1e-6);
}

TEST(Events, TerminalEventStopsAtTheFirstOne) {
  const Pair p0 = make_pair_at_t0();
  EventOptions ev_opt;
  ev_opt.terminal = true;
  const auto events = propagate_until_events(two_orbits, 0.0, stack(p0), 3000.0, range_rate_like,
                                             AdaptiveOptions::tight(), ev_opt);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].direction, -1);
}

// Brent's method alone: cos t has its root at pi/2 in [0, 3]; the result must lie within
// the requested tolerance, and a non-bracketing interval is refused.
TEST(Events, BrentRootConvergesToTheRequestedTolerance) {
  auto g = [](double t) { return std::cos(t); };
  int calls = 0;
  auto counted = [&](double t) { ++calls; return g(t); };
  const double root = brent_root(counted, 0.0, 3.0, g(0.0), g(3.0), 1e-12, 100);
  EXPECT_NEAR(root, kPi / 2.0, 1e-12);
  EXPECT_LT(calls, 20);  // superlinear: far fewer than the ~42 bisections for 1e-12
  EXPECT_THROW(brent_root(g, 0.0, 1.0, g(0.0), g(1.0), 1e-9, 100), std::invalid_argument);
}

}  // namespace
}  // namespace evade
