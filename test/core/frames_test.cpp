// Local frames: orthonormality, axis conventions, and ECI <-> relative round trips (1e-12).
#include <gtest/gtest.h>

#include "evade/core/constants.hpp"
#include "evade/core/elements.hpp"
#include "evade/core/frames.hpp"

namespace evade {
namespace {

constexpr double kMu = kEarthDefault.mu_m3ps2;

StateEci chief_state(double e, double i_deg) {
  return state_from_elements({7.0e6, e, i_deg * kDegToRad, 0.7, 1.1, 0.4}, kMu);
}

TEST(Frames, RswIsRightHandedOrthonormalWithRadialFirst) {
  const StateEci c = chief_state(0.01, 51.6);
  const Mat3 m = rotation_eci_to_rsw(c);
  EXPECT_LT((m * m.transpose() - Mat3::Identity()).norm(), 1e-15 * 10);
  EXPECT_NEAR(m.determinant(), 1.0, 1e-14);
  EXPECT_LT((m.row(0).transpose() - c.r_eci_m.normalized()).norm(), 1e-15 * 10);
  // For a circular orbit S is the velocity direction.
  const StateEci circ = chief_state(0.0, 51.6);
  EXPECT_LT((rotation_eci_to_rsw(circ).row(1).transpose() - circ.v_eci_mps.normalized()).norm(), 1e-14);
}

TEST(Frames, VvlhPointsZToEarthAndYAgainstOrbitNormal) {
  const StateEci c = chief_state(0.0, 30.0);
  const Mat3 m = rotation_eci_to_vvlh(c);
  EXPECT_LT((m.row(2).transpose() + c.r_eci_m.normalized()).norm(), 1e-14);
  const Vec3 h = c.r_eci_m.cross(c.v_eci_mps).normalized();
  EXPECT_LT((m.row(1).transpose() + h).norm(), 1e-14);
  EXPECT_LT((m.row(0).transpose() - c.v_eci_mps.normalized()).norm(), 1e-14);
  EXPECT_NEAR(m.determinant(), 1.0, 1e-14);
}

class FrameRoundTrip : public ::testing::TestWithParam<std::pair<double, double>> {};

TEST_P(FrameRoundTrip, RelativeStateRoundTripsTo1e12) {
  const auto [e, i_deg] = GetParam();
  const StateEci c = chief_state(e, i_deg);
  const StateEci d{c.r_eci_m + Vec3(1200.0, -800.0, 300.0), c.v_eci_mps + Vec3(0.5, 1.5, -0.7)};
  const StateEci back_rsw = eci_from_relative_rsw(c, relative_rsw_from_eci(c, d));
  const StateEci back_vvlh = eci_from_relative_vvlh(c, relative_vvlh_from_eci(c, d));
  // Relative to the relative quantity (the part that went through the transform).
  EXPECT_LT((back_rsw.r_eci_m - d.r_eci_m).norm() / 1500.0, 1e-12);
  EXPECT_LT((back_rsw.v_eci_mps - d.v_eci_mps).norm() / 1.7, 1e-12);
  EXPECT_LT((back_vvlh.r_eci_m - d.r_eci_m).norm() / 1500.0, 1e-12);
  EXPECT_LT((back_vvlh.v_eci_mps - d.v_eci_mps).norm() / 1.7, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(EccentricityInclinationGrid, FrameRoundTrip,
                         ::testing::Values(std::make_pair(0.0, 0.0), std::make_pair(0.0, 63.4),
                                           std::make_pair(1e-3, 90.0), std::make_pair(0.7, 180.0),
                                           std::make_pair(0.7, 63.4)));

TEST(Frames, CoMovingNeighbourHasZeroRelativeVelocityInRsw) {
  // A deputy on the same circular orbit, slightly ahead, is at rest in the rotating frame.
  const OrbitalElements oe{7.0e6, 0.0, 0.9, 0.2, 0.0, 0.3};
  OrbitalElements ahead = oe;
  ahead.true_anomaly_rad += 1e-4;
  const Vec6 rel = relative_rsw_from_eci(state_from_elements(oe, kMu), state_from_elements(ahead, kMu));
  EXPECT_NEAR(rel(1), 7.0e6 * std::sin(1e-4), 1e-3);
  EXPECT_LT(rel.tail<3>().norm(), 1e-9);
}

TEST(Frames, RejectsDegenerateChief) {
  StateEci c{Vec3(7e6, 0, 0), Vec3(1e3, 0, 0)};  // r x v = 0
  EXPECT_THROW(rotation_eci_to_rsw(c), std::invalid_argument);
}

}  // namespace
}  // namespace evade
