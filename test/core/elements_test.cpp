// Classical elements <-> Cartesian round trips over the singular and ordinary cases
// (issue 2: e in {0, 1e-3, 0.7}, i in {0, 63.4, 90, 180} deg, 1e-12 relative).
#include <gtest/gtest.h>

#include <cmath>

#include "evade/core/constants.hpp"
#include "evade/core/elements.hpp"

namespace evade {
namespace {

constexpr double kMu = kEarthDefault.mu_m3ps2;

struct Case {
  double e;
  double i_deg;
};

class ElementsRoundTrip : public ::testing::TestWithParam<Case> {};

// Angles compared modulo 2pi; the 1e-12 bound is ~4500 ulp of 2pi: double rounding through
// one rotation matrix, a cross product and an atan2 costs tens of ulp.
double angle_diff(double a, double b) { return std::fabs(wrap_pi(a - b)); }

TEST_P(ElementsRoundTrip, StateToElementsToStateIsIdentityTo1e12) {
  const auto [e, i_deg] = GetParam();
  for (double nu_deg : {0.0, 37.0, 135.0, 250.0}) {
    OrbitalElements oe;
    oe.a_m = 7.2e6;
    oe.e = e;
    oe.i_rad = i_deg * kDegToRad;
    oe.raan_rad = 40.0 * kDegToRad;
    oe.argp_rad = 75.0 * kDegToRad;
    oe.true_anomaly_rad = nu_deg * kDegToRad;
    const StateEci s = state_from_elements(oe, kMu);
    const OrbitalElements back = elements_from_state(s, kMu);
    ASSERT_TRUE(std::isfinite(back.a_m) && std::isfinite(back.raan_rad) &&
                std::isfinite(back.argp_rad) && std::isfinite(back.true_anomaly_rad));
    const StateEci s2 = state_from_elements(back, kMu);
    EXPECT_LT((s2.r_eci_m - s.r_eci_m).norm() / s.r_eci_m.norm(), 1e-12);
    EXPECT_LT((s2.v_eci_mps - s.v_eci_mps).norm() / s.v_eci_mps.norm(), 1e-12);
    EXPECT_NEAR(back.a_m / oe.a_m, 1.0, 1e-12);
    EXPECT_NEAR(back.e, e, 1e-12);
    EXPECT_LT(angle_diff(back.i_rad, oe.i_rad), 1e-12);
    const bool circular = e == 0.0;
    const bool equatorial = i_deg == 0.0 || i_deg == 180.0;
    if (!circular && !equatorial) {
      EXPECT_LT(angle_diff(back.raan_rad, oe.raan_rad), 1e-12);
      // argp error scales as 1/e (the perigee direction is defined by e_vec).
      EXPECT_LT(angle_diff(back.argp_rad, oe.argp_rad), 1e-12 / std::min(1.0, e * 1e3));
    }
    if (circular) {
      EXPECT_EQ(back.argp_rad, 0.0);
    }
    if (equatorial) {
      EXPECT_EQ(back.raan_rad, 0.0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    EccentricityInclinationGrid, ElementsRoundTrip,
    ::testing::Values(Case{0.0, 0.0}, Case{0.0, 63.4}, Case{0.0, 90.0}, Case{0.0, 180.0},
                      Case{1e-3, 0.0}, Case{1e-3, 63.4}, Case{1e-3, 90.0}, Case{1e-3, 180.0},
                      Case{0.7, 0.0}, Case{0.7, 63.4}, Case{0.7, 90.0}, Case{0.7, 180.0}));

TEST(Elements, CircularEquatorialGivesTrueLongitude) {
  OrbitalElements oe{7.0e6, 0.0, 0.0, 0.0, 0.0, 1.234};
  const OrbitalElements back = elements_from_state(state_from_elements(oe, kMu), kMu);
  EXPECT_NEAR(back.true_anomaly_rad, 1.234, 1e-13);
  EXPECT_EQ(back.raan_rad, 0.0);
  EXPECT_EQ(back.argp_rad, 0.0);
}

TEST(Elements, RetrogradeEquatorialLongitudeFollowsTheMotion) {
  // i = 180 deg: angles are measured about h = -z, in the direction of motion.
  OrbitalElements oe{7.0e6, 0.1, kPi, 0.0, 0.5, 0.3};
  const StateEci s = state_from_elements(oe, kMu);
  const OrbitalElements back = elements_from_state(s, kMu);
  EXPECT_NEAR(back.argp_rad, 0.5, 1e-12);
  EXPECT_NEAR(back.true_anomaly_rad, 0.3, 1e-12);
}

TEST(Kepler, SolvesForEveryEccentricityToMachinePrecision) {
  for (double e : {0.0, 1e-6, 0.1, 0.5, 0.9, 0.99, 0.999}) {
    for (int k = -20; k <= 20; ++k) {
      const double m = 0.3 * k;
      const double ecc = eccentric_from_mean_anomaly(m, e);
      // Residual of Kepler's equation: a few ulp of |M| <= 6.
      EXPECT_NEAR(ecc - e * std::sin(ecc), m, 4e-15 * std::max(1.0, std::fabs(m))) << "e=" << e;
    }
  }
}

TEST(Kepler, TrueMeanRoundTripKeepsRevolutions) {
  for (double e : {0.0, 0.3, 0.8}) {
    for (double m : {-7.0, -1.0, 0.0, 2.0, 9.5}) {
      EXPECT_NEAR(mean_from_true_anomaly(true_from_mean_anomaly(m, e), e), m, 1e-12);
    }
  }
}

TEST(Elements, RejectsUnboundAndNonFiniteInput) {
  EXPECT_THROW(state_from_elements({7e6, 1.0, 0, 0, 0, 0}, kMu), std::invalid_argument);
  EXPECT_THROW(state_from_elements({-7e6, 0.1, 0, 0, 0, 0}, kMu), std::invalid_argument);
  EXPECT_THROW(state_from_elements({NAN, 0.1, 0, 0, 0, 0}, kMu), std::invalid_argument);
  StateEci hyper{Vec3(7e6, 0, 0), Vec3(0, 12e3, 0)};
  EXPECT_THROW(elements_from_state(hyper, kMu), std::invalid_argument);
  StateEci bad{Vec3(NAN, 0, 0), Vec3(0, 7e3, 0)};
  EXPECT_THROW(elements_from_state(bad, kMu), std::invalid_argument);
  EXPECT_THROW(eccentric_from_mean_anomaly(1.0, 1.2), std::invalid_argument);
}

}  // namespace
}  // namespace evade
