// The onboard propagation (docs/AUTONOMY.md AUT-3): the J2 gradient written out against central
// differences of the acceleration; RK4 at the onboard step against the ground's DOP853 at
// 1 mm (AdaptiveOptions::tight) over 1.5 LEO orbits; the transition matrix against finite
// differences of whole propagations; bounded step counts; no allocation.
#include <gtest/gtest.h>

#include <cmath>

#include "evade/autonomy/orbit_stm.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/dynamics/orbit_propagator.hpp"
#include "support/counting_new.hpp"

namespace evade::autonomy {
namespace {

// A 700 km, 97.9 deg LEO (sun-synchronous-like) state with some eccentricity.
Vec6 leo() {
  Vec6 x;
  x << 6.9e6, 0.8e6, 1.1e6, -900.0, 1100.0, 7380.0;
  return x;
}

TEST(OrbitStm, AccelerationIsTheGroundsTwoBodyPlusJ2) {
  const Vec3 r = leo().head<3>();
  const Vec3 ground = accel_eci_mps2(r, GravityModel::kTwoBodyJ2, kEarthDefault);
  EXPECT_LT((gravity_j2_eci_mps2(r, kEarthDefault) - ground).norm(), 1e-15 * ground.norm());
}

// Central differences with h = 1 m: truncation (h/r)^2 ~ 2e-14 of the gradient, rounding
// eps |a| / h ~ 2e-15 1/s^2 against |G| ~ 2.4e-6: the written-out gradient must agree to 1e-9.
TEST(OrbitStm, J2GradientMatchesCentralDifferencesOfTheAcceleration) {
  for (const Vec3& r : {Vec3(6.9e6, 0.8e6, 1.1e6), Vec3(-2e6, 5e6, -4.4e6), Vec3(0.0, 0.0, 7e6),
                        Vec3(4.2e7, 0.0, 0.0)}) {
    const Mat3 g = gravity_j2_gradient(r, kEarthDefault);
    Mat3 fd;
    for (int j = 0; j < 3; ++j) {
      Vec3 dr = Vec3::Zero();
      dr[j] = 1.0;
      fd.col(j) = (gravity_j2_eci_mps2(r + dr, kEarthDefault) -
                   gravity_j2_eci_mps2(r - dr, kEarthDefault)) / 2.0;
    }
    EXPECT_LT((g - fd).norm(), 1e-9 * g.norm()) << r.transpose();
    EXPECT_LT((g - g.transpose()).norm(), 1e-15 * g.norm()) << "the gradient of a potential";
  }
}

// RK4's global error is O(h^4): at 5 s over 1.5 orbits (8,900 s) in LEO it must stay within
// 1 m of DOP853 at 1 mm, and halving the step must shrink it about 16 times.
TEST(OrbitStm, Rk4AtTheOnboardStepIsWithinAMetreOfTheGroundIntegrator) {
  const double dt = 8900.0;
  const StateEci truth = propagate_orbit(StateEci::from_stacked(leo()), dt,
                                         GravityModel::kTwoBodyJ2, kEarthDefault,
                                         AdaptiveOptions::tight());
  Vec6 x5 = leo(), x2 = leo();
  ASSERT_TRUE(propagate(&x5, dt, 5.0, kEarthDefault));
  ASSERT_TRUE(propagate(&x2, dt, 2.5, kEarthDefault));
  const double e5 = (x5.head<3>() - truth.r_eci_m).norm();
  const double e2 = (x2.head<3>() - truth.r_eci_m).norm();
  EXPECT_LT(e5, 1.0);
  EXPECT_GT(e5 / e2, 10.0);
  EXPECT_LT(e5 / e2, 22.0);
}

// Phi against finite differences of whole propagations (1 m and 1 mm/s perturbations): the
// nonlinearity over 1.5 orbits is O(delta^2 / r) ~ 1e-7 of Phi delta.
TEST(OrbitStm, TransitionMatrixMatchesFiniteDifferencesOfThePropagation) {
  StateStm s;
  s.x_eci = leo();
  ASSERT_TRUE(propagate_stm(&s, 8900.0, 5.0, kEarthDefault));
  const double delta[6] = {1.0, 1.0, 1.0, 1e-3, 1e-3, 1e-3};
  for (int j = 0; j < 6; ++j) {
    Vec6 plus = leo(), minus = leo();
    plus[j] += delta[j];
    minus[j] -= delta[j];
    ASSERT_TRUE(propagate(&plus, 8900.0, 5.0, kEarthDefault));
    ASSERT_TRUE(propagate(&minus, 8900.0, 5.0, kEarthDefault));
    const Vec6 fd = (plus - minus) / (2.0 * delta[j]);
    EXPECT_LT((s.phi.col(j) - fd).norm(), 1e-6 * fd.norm()) << "column " << j;
  }
  EXPECT_LT((s.x_eci - [] {
              Vec6 x = leo();
              EXPECT_TRUE(propagate(&x, 8900.0, 5.0, kEarthDefault));
              return x;
            }()).norm(), 1e-6) << "the state of propagate_stm is propagate's";
}

TEST(OrbitStm, StepCountsAreBoundedAndBadInputChangesNothing) {
  EXPECT_EQ(steps_for(0.0, 5.0), 0);
  EXPECT_EQ(steps_for(1.0, 5.0), 1);
  EXPECT_EQ(steps_for(-10.0, 5.0), 2);
  EXPECT_EQ(steps_for(1e12, 1e-3), kMaxSteps);
  EXPECT_EQ(steps_for(NAN, 5.0), 0);
  EXPECT_EQ(steps_for(10.0, 0.0), 0);
  Vec6 x = leo();
  const Vec6 x0 = x;
  EXPECT_FALSE(propagate(&x, NAN, 5.0, kEarthDefault));
  EXPECT_FALSE(propagate(&x, 10.0, -1.0, kEarthDefault));
  Vec6 inside = Vec6::Zero();
  inside[0] = 1.0;  // |r| = 1 m: not an orbit
  EXPECT_FALSE(propagate(&inside, 10.0, 5.0, kEarthDefault));
  EXPECT_EQ(x, x0);
}

TEST(OrbitStm, PropagationAllocatesNothing) {
  StateStm s;
  s.x_eci = leo();
  const long before = g_news.load();
  ASSERT_TRUE(propagate_stm(&s, 3600.0, 5.0, kEarthDefault));
  Vec6 x = leo();
  ASSERT_TRUE(propagate(&x, 3600.0, 5.0, kEarthDefault));
  EXPECT_EQ(g_news.load() - before, 0);
}

}  // namespace
}  // namespace evade::autonomy
