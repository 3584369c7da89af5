// The uplinked own state against the node's navigation (docs/AUTONOMY.md AUT-2): the node's nav
// propagated to TCA lands on the event's object 1 when the event was built from it (0 sigma to
// the propagation's metre), a shift of 6 sigma along any axis of the covariance reads 6,
// the same distance along a shorter axis reads more, and a near-singular covariance is floored.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "evade/autonomy/nav_check.hpp"
#include "evade/autonomy/orbit_stm.hpp"

namespace evade::autonomy {
namespace {

constexpr std::int64_t kNow = 1'000'000'000'000;

TEST(NavCheck, TheOwnStateOfAnEventBuiltFromTheNavIsZeroSigmaAway) {
  Vec6 nav;
  nav << 6.9e6, 0.8e6, 1.1e6, -900.0, 1100.0, 7380.0;
  ConjunctionEvent e;
  e.tca_us = kNow + 5'400'000'000;  // 1.5 h ahead
  e.x1_eci = nav;
  ASSERT_TRUE(propagate(&e.x1_eci, 5400.0, 1.0, kEarthDefault));  // the ground's, at 1 s
  e.cov1_eci = Mat6::Identity() * 100.0 * 100.0;
  const NavCheck c = check_own_state(e, nav, kNow, 5.0, kEarthDefault);
  ASSERT_TRUE(c.ok);
  EXPECT_LT(c.distance_m, 1.0) << "5 s against 1 s steps over 1.5 h";
  EXPECT_LT(c.sigma, 0.01);
}

TEST(NavCheck, MahalanobisReadsTheCovarianceAxesAndIsFloored) {
  Mat3 c = Mat3::Zero();
  c.diagonal() << 1000.0 * 1000.0, 50.0 * 50.0, 10.0 * 10.0;
  EXPECT_NEAR(mahalanobis(Vec3(6000.0, 0.0, 0.0), c, 1.0), 6.0, 1e-12);
  EXPECT_NEAR(mahalanobis(Vec3(0.0, 0.0, 60.0), c, 1.0), 6.0, 1e-12);
  EXPECT_NEAR(mahalanobis(Vec3(0.0, 6000.0, 0.0), c, 1.0), 120.0, 1e-9);
  Mat3 singular = Mat3::Zero();
  singular(0, 0) = 1e6;  // zero variance across: 3 m across reads 3 sigma, not infinity
  EXPECT_NEAR(mahalanobis(Vec3(0.0, 3.0, 0.0), singular, 1.0), 3.0, 1e-12);
}

TEST(NavCheck, AFailedPropagationIsNotACheck) {
  ConjunctionEvent e;
  e.tca_us = kNow + 1'000'000;
  const NavCheck c = check_own_state(e, Vec6::Zero(), kNow, 5.0, kEarthDefault);
  EXPECT_FALSE(c.ok);
}

}  // namespace
}  // namespace evade::autonomy
