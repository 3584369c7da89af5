// Gravity: accelerations are gradients of their potentials; secular rates match Vallado's
// closed forms at special inclinations.
#include <gtest/gtest.h>

#include <cmath>

#include "evade/dynamics/gravity.hpp"

namespace evade {
namespace {

const EarthModel kEarth = kEarthDefault;

// J2 part of the geopotential U = mu/r [1 - J2 (Re/r)^2 P2(sin phi)] (Vallado eq. 8-20),
// P2(s) = (3 s^2 - 1)/2, s = z/r. The acceleration is a = grad U.
double j2_potential(const Vec3& r) {
  const double rn = r.norm();
  const double s = r.z() / rn;
  return -kEarth.mu_m3ps2 / rn * kEarth.j2 * std::pow(kEarth.re_m / rn, 2) *
         0.5 * (3.0 * s * s - 1.0);
}

// Central differences with step 1 m have truncation error ~ (1 m)^2 |d3R/dr3| / 6
// ~ 1e-12 relative to |a_J2| (~1e-2 m/s^2 at 7000 km, scale length 7e6 m), and rounding
// error ~ eps |R| / 1 m ~ 1e-16 * 6e4 = 6e-12 m/s^2 ~ 1e-9 relative: require 1e-7.
TEST(Gravity, J2AccelerationIsTheGradientOfTheJ2Potential) {
  const Vec3 points[] = {{7000e3, 0.0, 0.0}, {3000e3, -4000e3, 5000e3}, {-100e3, 200e3, -7100e3},
                         {4000e3, 4000e3, 2000e3}};
  for (const Vec3& r : points) {
    Vec3 grad;
    for (int k = 0; k < 3; ++k) {
      Vec3 dr = Vec3::Zero();
      dr(k) = 1.0;
      grad(k) = (j2_potential(r + dr) - j2_potential(r - dr)) / 2.0;
    }
    const Vec3 a = accel_j2_eci_mps2(r, kEarth);
    EXPECT_LT((a - grad).norm(), 1e-7 * a.norm()) << r.transpose();
  }
}

TEST(Gravity, TwoBodyPointsToTheCentreWithInverseSquareMagnitude) {
  const Vec3 r(3000e3, -4000e3, 5000e3);
  const Vec3 a = accel_two_body_eci_mps2(r, kEarth.mu_m3ps2);
  EXPECT_NEAR(a.norm(), kEarth.mu_m3ps2 / r.squaredNorm(), 1e-15 * a.norm());
  EXPECT_NEAR(a.normalized().dot(r.normalized()), -1.0, 1e-15);
}

TEST(Gravity, TotalAccelerationAndDerivativeCombineTheTerms) {
  const Vec3 r(3000e3, -4000e3, 5000e3);
  const Vec3 v(1.0, 2.0, 3.0);
  Vec6 x;
  x << r, v;
  const Vec6 d = orbit_derivative(x, GravityModel::kTwoBodyJ2, kEarth);
  EXPECT_EQ(d.head<3>(), v);
  EXPECT_LT((d.tail<3>() - accel_two_body_eci_mps2(r, kEarth.mu_m3ps2) -
             accel_j2_eci_mps2(r, kEarth)).norm(), 1e-15);
  EXPECT_EQ(accel_eci_mps2(r, GravityModel::kTwoBody, kEarth),
            accel_two_body_eci_mps2(r, kEarth.mu_m3ps2));
}

// Known features of the secular rates: no nodal motion at i = 90 deg, the critical
// inclination 63.435 deg freezes the perigee, the node regresses for prograde orbits.
TEST(Gravity, SecularRatesVanishAtPolarAndCriticalInclinations) {
  const double a = 7000e3;
  EXPECT_NEAR(j2_secular_rates(a, 0.01, 90.0 * kDegToRad, kEarth).raan_dot_radps, 0.0, 1e-20);
  const double i_crit = std::asin(std::sqrt(0.8));  // 4 - 5 sin^2 i = 0
  EXPECT_NEAR(j2_secular_rates(a, 0.01, i_crit, kEarth).argp_dot_radps, 0.0, 1e-20);
  const J2SecularRates r = j2_secular_rates(a, 0.01, 50.0 * kDegToRad, kEarth);
  EXPECT_LT(r.raan_dot_radps, 0.0);
  EXPECT_NEAR(r.arg_latitude_dot_radps, r.argp_dot_radps + r.mean_anomaly_dot_radps, 1e-20);
}

// Sun-synchronous check (Vallado example 9-? style): a = 7078 km, e = 0, i = 98.19 deg
// gives a nodal rate of +360 deg / 365.2422 days to within 0.5% (i rounded to 0.01 deg).
TEST(Gravity, SunSynchronousOrbitPrecessesOncePerYear) {
  const double target = kTwoPi / (365.2422 * kSecondsPerDay);
  const double rate = j2_secular_rates(7078e3, 0.0, 98.19 * kDegToRad, kEarth).raan_dot_radps;
  EXPECT_NEAR(rate / target, 1.0, 5e-3);
}

TEST(Gravity, SecularRatesRejectUnboundOrbits) {
  EXPECT_THROW(j2_secular_rates(7000e3, 1.0, 0.5, kEarth), std::invalid_argument);
  EXPECT_THROW(j2_secular_rates(-1.0, 0.1, 0.5, kEarth), std::invalid_argument);
  EXPECT_THROW(j2_secular_rates(7000e3, NAN, 0.5, kEarth), std::invalid_argument);
}

}  // namespace
}  // namespace evade
