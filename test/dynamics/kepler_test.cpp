// Analytic Kepler propagation (f and g functions).
#include <gtest/gtest.h>

#include <cmath>

#include "evade/core/elements.hpp"
#include "evade/dynamics/kepler_propagator.hpp"
#include "test_orbits.hpp"

namespace evade {
namespace {

const double kMu = kEarthDefault.mu_m3ps2;

// A circular orbit is a uniform rotation: r(t) = R (cos nt, sin nt, 0) in its plane, an
// independent closed form. Tolerance: a few ulp of R (7e6 m * 1e-15 ~ 1e-8 m) times the
// number of angle reductions: 1e-6 m.
TEST(Kepler, CircularEquatorialOrbitIsAUniformRotation) {
  const double r_m = 7000e3;
  const double v = std::sqrt(kMu / r_m);
  const double n = v / r_m;
  const StateEci s0{{r_m, 0.0, 0.0}, {0.0, v, 0.0}};
  for (double t : {1.0, 100.0, 1234.5, 6000.0, 86400.0, -5000.0}) {
    const StateEci s = propagate_kepler(s0, t, kMu);
    ASSERT_TRUE(s.r_eci_m.allFinite() && s.v_eci_mps.allFinite());
    const Vec3 expect(r_m * std::cos(n * t), r_m * std::sin(n * t), 0.0);
    EXPECT_LT((s.r_eci_m - expect).norm(), 1e-6) << t;
    EXPECT_NEAR(s.v_eci_mps.norm(), v, 1e-9);
  }
}

// Retrograde equatorial (i = 180 deg) and polar circular orbits: finite and a rotation in
// the right sense.
TEST(Kepler, RetrogradeAndPolarCircularOrbitsAreFiniteAndRotateCorrectly) {
  const double r_m = 7000e3;
  const double v = std::sqrt(kMu / r_m);
  const double n = v / r_m;
  const double t = 1000.0;
  const StateEci retro{{r_m, 0.0, 0.0}, {0.0, -v, 0.0}};
  const StateEci s = propagate_kepler(retro, t, kMu);
  EXPECT_LT((s.r_eci_m - Vec3(r_m * std::cos(n * t), -r_m * std::sin(n * t), 0.0)).norm(), 1e-6);
  const StateEci polar{{r_m, 0.0, 0.0}, {0.0, 0.0, v}};
  const StateEci p = propagate_kepler(polar, t, kMu);
  EXPECT_LT((p.r_eci_m - Vec3(r_m * std::cos(n * t), 0.0, r_m * std::sin(n * t))).norm(), 1e-6);
}

// Against the element path: advance the mean anomaly by n dt and convert back with the
// core conversions (Vallado algorithms 9 and 10, a different algorithm). 1e-6 m covers
// double rounding in both paths for |r| ~ 1e7 m.
TEST(Kepler, AgreesWithMeanAnomalyAdvanceOfTheElements) {
  for (double e : {0.0001, 0.1, 0.5, 0.9}) {
    OrbitalElements oe;
    oe.a_m = 9000e3 / (1.0 - 0.9 * e);  // keep perigee above 6000 km for every e
    oe.e = e;
    oe.i_rad = 0.7;
    oe.raan_rad = 1.1;
    oe.argp_rad = 2.3;
    oe.true_anomaly_rad = 0.4;
    const StateEci s0 = state_from_elements(oe, kMu);
    const double dt = 3777.0;
    const double m1 = mean_from_true_anomaly(oe.true_anomaly_rad, e) +
                      mean_motion_radps(oe.a_m, kMu) * dt;
    OrbitalElements oe1 = oe;
    oe1.true_anomaly_rad = true_from_mean_anomaly(wrap_two_pi(m1), e);
    const StateEci truth = state_from_elements(oe1, kMu);
    const StateEci s = propagate_kepler(s0, dt, kMu);
    EXPECT_LT((s.r_eci_m - truth.r_eci_m).norm(), 1e-6 * (1.0 + 10.0 * e)) << "e=" << e;
    EXPECT_LT((s.v_eci_mps - truth.v_eci_mps).norm(), 1e-9 * (1.0 + 10.0 * e)) << "e=" << e;
  }
}

// Forward then backward returns to the start. Only rounding remains: the mean-anomaly
// change n dt carries an absolute error ~ eps |n dt| per operation, which moves the point
// by r eps |n dt|; allow 8 such operations plus 1e-7 m, and n times that in velocity.
TEST(Kepler, RoundTripReturnsToStart) {
  const double a = 8000e3;
  const StateEci s0 = test::orbit_state(a, 0.3, 2.0, 0.5, 4.0, 1.0);
  const double n = std::sqrt(kMu / (a * a * a));
  for (double dt : {10.0, 4000.0, 10.0 * kSecondsPerDay}) {
    const double bound_m = 1e-7 + 8.0 * 2.2e-16 * n * dt * a * 1.3;  // r <= a(1+e)
    const StateEci s1 = propagate_kepler(propagate_kepler(s0, dt, kMu), -dt, kMu);
    EXPECT_LT((s1.r_eci_m - s0.r_eci_m).norm(), bound_m) << dt;
    EXPECT_LT((s1.v_eci_mps - s0.v_eci_mps).norm(), 1e-10 + 2.0 * n * bound_m) << dt;
  }
}

// One full period returns to the same point.
TEST(Kepler, OnePeriodIsIdentity) {
  const double a = 7500e3;
  const StateEci s0 = test::orbit_state(a, 0.1, 0.5, 0.1, 0.2, 2.0);
  const double period = kTwoPi * std::sqrt(a * a * a / kMu);
  EXPECT_LT((propagate_kepler(s0, period, kMu).r_eci_m - s0.r_eci_m).norm(), 1e-6);
}

TEST(Kepler, ZeroStepIsIdentity) {
  const StateEci s0 = test::leo_e01();
  const StateEci s = propagate_kepler(s0, 0.0, kMu);
  EXPECT_EQ(s.r_eci_m, s0.r_eci_m);
  EXPECT_EQ(s.v_eci_mps, s0.v_eci_mps);
}

TEST(Kepler, RejectsUnboundAndNonFiniteStates) {
  const double r_m = 7000e3;
  const double v_esc = std::sqrt(2.0 * kMu / r_m);
  EXPECT_THROW(propagate_kepler({{r_m, 0, 0}, {0, v_esc, 0}}, 10.0, kMu), std::invalid_argument);
  EXPECT_THROW(propagate_kepler({{r_m, 0, 0}, {0, 1.2 * v_esc, 0}}, 10.0, kMu),
               std::invalid_argument);
  EXPECT_THROW(propagate_kepler({{r_m, 0, 0}, {100.0, 0, 0}}, 10.0, kMu),  // rectilinear, e = 1
               std::invalid_argument);
  EXPECT_THROW(propagate_kepler({{NAN, 0, 0}, {0, 7000, 0}}, 10.0, kMu), std::invalid_argument);
  EXPECT_THROW(propagate_kepler({{r_m, 0, 0}, {0, 7000, 0}}, NAN, kMu), std::invalid_argument);
  EXPECT_THROW(propagate_kepler({{0, 0, 0}, {0, 7000, 0}}, 1.0, kMu), std::invalid_argument);
}

}  // namespace
}  // namespace evade
