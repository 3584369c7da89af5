// LOS geometry of paper 000 (eq. 7, 12, 14–18) against finite differences of the true
// relative motion. Tolerances: central differences with h = 1e-3 s have truncation error
// O(h² u⃛) ≈ 1e-6 relative here, and rounding ≈ 1e-16/h ≈ 1e-13: we allow 1e-6 relative.
#include <cmath>

#include <gtest/gtest.h>

#include "evade/core/constants.hpp"
#include "evade/guidance/los_geometry.hpp"

namespace {

using evade::Vec3;
using namespace evade::guidance;

Vec3 unit_at(const Vec3& r0, const Vec3& v, double t) { return (r0 + v * t).normalized(); }

TEST(LosGeometry, UnitRateMatchesFiniteDifferenceOfStraightLineMotion) {
  const Vec3 r0(30e3, -12e3, 8e3);
  const Vec3 v(-6000.0, 2500.0, -1200.0);
  Vec3 u;
  Vec3 ud;
  los_from_relative(r0, v, &u, &ud);
  const double h = 1e-3;
  const Vec3 fd = (unit_at(r0, v, h) - unit_at(r0, v, -h)) / (2.0 * h);
  EXPECT_LT((ud - fd).norm(), 1e-6 * fd.norm());
  // ω_s = |r × ṙ| / r² (eq. 3, 17).
  EXPECT_NEAR(ud.norm(), r0.cross(v).norm() / r0.squaredNorm(), 1e-15);
}

TEST(LosGeometry, AngleRatesGiveEq17And18) {
  const double el = 0.4, az = -2.1, el_rate = 3e-3, az_rate = -5e-3;
  const Vec3 ud = los_unit_rate_from_angle_rates(el, az, el_rate, az_rate);
  const double h = 1e-4;
  const Vec3 fd = (los_unit_from_angles(el + el_rate * h, az + az_rate * h) -
                   los_unit_from_angles(el - el_rate * h, az - az_rate * h)) /
                  (2.0 * h);
  EXPECT_LT((ud - fd).norm(), 1e-7 * fd.norm());
  // eq. 17: ω_s = sqrt((β̇ cos ε)² + ε̇²)
  EXPECT_NEAR(ud.norm(), std::hypot(az_rate * std::cos(el), el_rate), 1e-15);
  // eq. 18: e_θ = (ε̇ y_s − β̇ cos ε z_s)/ω_s with y_s, z_s of eq. 14 (no flip: zenith chosen
  // along e_ω so the convention keeps the sign).
  const Vec3 y_s(-std::cos(az) * std::sin(el), -std::sin(az) * std::sin(el), std::cos(el));
  const Vec3 z_s(std::sin(az), -std::cos(az), 0.0);
  const double w = std::hypot(az_rate * std::cos(el), el_rate);
  const Vec3 e_theta_eq18 = (el_rate * y_s - az_rate * std::cos(el) * z_s) / w;
  const Vec3 u = los_unit_from_angles(el, az);
  const Vec3 e_omega = u.cross(e_theta_eq18);
  LosFrame f;
  ASSERT_TRUE(los_frame(u, ud, 7e6 * e_omega, Vec3(0, 7500, 0), 0.0, &f));
  EXPECT_FALSE(f.flipped);
  EXPECT_LT((f.e_theta_eci - e_theta_eq18).norm(), 1e-12);
  EXPECT_LT((f.e_omega_eci - e_omega).norm(), 1e-12);
  // Angles round trip.
  const LosAngles a = los_angles_from_unit(u);
  EXPECT_NEAR(a.elevation_rad, el, 1e-15);
  EXPECT_NEAR(a.azimuth_rad, az, 1e-15);
}

TEST(LosGeometry, EthetaAndEomegaMatchTrueRelativeMotion) {
  // e_θ is the direction of the LOS's motion, e_ω ∝ r × ṙ (eq. 3–5), up to the zenith flip.
  const Vec3 r0(20e3, 5e3, -3e3);
  const Vec3 v(-7000.0, -1500.0, 900.0);
  const Vec3 zenith(0.0, 0.0, 1.0);
  Vec3 u;
  Vec3 ud;
  los_from_relative(r0, v, &u, &ud);
  LosFrame f;
  ASSERT_TRUE(los_frame(u, ud, 6.8e6 * zenith, Vec3(7500, 0, 0), 0.0, &f));
  const double h = 1e-3;
  const Vec3 fd = (unit_at(r0, v, h) - unit_at(r0, v, -h)) / (2.0 * h);
  const double sign = f.flipped ? -1.0 : 1.0;
  EXPECT_LT((sign * f.e_theta_eci - fd.normalized()).norm(), 1e-6);
  EXPECT_LT((sign * f.e_omega_eci - r0.cross(v).normalized()).norm(), 1e-12);
  EXPECT_GE(f.e_omega_eci.dot(zenith), 0.0);  // the zenith convention
  EXPECT_NEAR(f.e_theta_eci.dot(f.e_r_eci), 0.0, 1e-15);
  EXPECT_LT((f.e_omega_eci.cross(f.e_r_eci) - f.e_theta_eci).norm(), 1e-15);
}

TEST(LosGeometry, FiniteAndRegularAtElevationNinetyDegrees) {
  for (const double el : {0.5 * evade::kPi, -0.5 * evade::kPi, 0.5 * evade::kPi - 1e-12}) {
    const Vec3 u = los_unit_from_angles(el, 1.0);
    const Vec3 ud = los_unit_rate_from_angle_rates(el, 1.0, 2e-3, 1e6);  // huge β̇, cos ε ≈ 0
    EXPECT_TRUE(ud.allFinite());
    LosFrame f;
    ASSERT_TRUE(los_frame(u, ud, Vec3(6.8e6, 0, 0), Vec3(0, 7500, 0), 0.0, &f));
    EXPECT_TRUE(f.e_theta_eci.allFinite());
    EXPECT_NEAR(f.e_theta_eci.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f.e_theta_eci.dot(u), 0.0, 1e-9);
    const LosAngles a = los_angles_from_unit(u);
    EXPECT_TRUE(std::isfinite(a.azimuth_rad));
    EXPECT_NEAR(std::abs(a.elevation_rad), 0.5 * evade::kPi, 1e-6);
  }
}

TEST(LosGeometry, ZenithFlipKeepsEthetaContinuousWhenTransverseVelocityChangesSign) {
  // Head-on geometry: the transverse relative velocity s·d passes through zero; the raw e_θ
  // reverses (±d) but the flipped one must not.
  const Vec3 zenith(1.0, 0.0, 0.0);
  const Vec3 r(0.0, 50e3, 10e3);
  const Vec3 e_r = r.normalized();
  const Vec3 d = e_r.cross(Vec3(0.3, 0.2, 0.9)).normalized();  // ⊥ LOS, some zenith component
  Vec3 prev;
  bool have_prev = false;
  for (const double s : {1e-2, 1e-4, 1e-7, -1e-7, -1e-4, -1e-2}) {
    const Vec3 v = -7000.0 * e_r + s * d;
    Vec3 u;
    Vec3 ud;
    los_from_relative(r, v, &u, &ud);
    LosFrame f;
    ASSERT_TRUE(los_frame(u, ud, 6.8e6 * zenith, Vec3(0, 7500, 0), 0.0, &f));
    EXPECT_GE(f.e_omega_eci.dot(zenith), 0.0);
    if (have_prev) {
      // Without the flip the difference would be 2 (a reversal). Tolerance: u̇ = (ṙ − (u·ṙ)u)/r
      // cancels 7000 m/s to leave s, so rounding leaves ≈ 7000 ε/s ≈ 1e-5 relative at s = 1e-7.
      EXPECT_LT((f.e_theta_eci - prev).norm(), 1e-4) << "s = " << s;
    }
    prev = f.e_theta_eci;
    have_prev = true;
  }
}

TEST(LosGeometry, FallbackDirectionWhenLosRateIsZeroIsTheFlipConventionsFixedPoint) {
  const Vec3 zenith = Vec3(1.0, 0.2, -0.1).normalized();
  const Vec3 u = Vec3(0.2, 1.0, 0.3).normalized();
  LosFrame f;
  ASSERT_TRUE(los_frame(u, Vec3::Zero(), 6.8e6 * zenith, Vec3(0, 7500, 0), 0.0, &f));
  EXPECT_TRUE(f.fallback);
  // e_ω = zenith projected ⊥ LOS.
  const Vec3 expect_w = (zenith - zenith.dot(u) * u).normalized();
  EXPECT_LT((f.e_omega_eci - expect_w).norm(), 1e-15);
  EXPECT_NEAR(f.e_theta_eci.dot(u), 0.0, 1e-15);
  EXPECT_NEAR(f.e_theta_eci.dot(zenith), 0.0, 1e-15);  // thrust −e_θ is horizontal
  // Fixed point: a small LOS rate built up by thrusting along −e_θ_fallback (relative
  // acceleration +e_θ) gives the same e_θ, unflipped — no jump when the true rate takes over.
  LosFrame g;
  ASSERT_TRUE(los_frame(u, 1e-6 * f.e_theta_eci, 6.8e6 * zenith, Vec3(0, 7500, 0), 0.0, &g));
  EXPECT_FALSE(g.fallback);
  EXPECT_FALSE(g.flipped);
  EXPECT_LT((g.e_theta_eci - f.e_theta_eci).norm(), 1e-15);
  // Below the noise threshold the fallback is used even with a nonzero rate.
  LosFrame h;
  ASSERT_TRUE(los_frame(u, 1e-9 * Vec3(0, 0, 1).cross(u), 6.8e6 * zenith, Vec3(0, 7500, 0),
                        1e-8, &h));
  EXPECT_TRUE(h.fallback);
  // LOS along the zenith: the velocity direction replaces the zenith.
  LosFrame k;
  ASSERT_TRUE(los_frame(zenith, Vec3::Zero(), 6.8e6 * zenith, Vec3(0, 7500, 0), 0.0, &k));
  EXPECT_TRUE(k.e_theta_eci.allFinite());
  EXPECT_NEAR(k.e_theta_eci.norm(), 1.0, 1e-12);
}

// Degenerate navigation (velocity along the position, so the LOS cannot be off both): the
// frame is still orthonormal and finite, so a bad nav sample never puts NaN into a thrust
// direction.
TEST(LosGeometry, FallbackFrameIsOrthonormalWhenLosIsAlongBothZenithAndVelocity) {
  for (const Vec3& axis : {Vec3(1.0, 0.0, 0.0), Vec3(0.0, 0.6, 0.8)}) {
    LosFrame f;
    ASSERT_TRUE(los_frame(axis, Vec3::Zero(), 7e6 * axis, 10.0 * axis, 0.0, &f));
    EXPECT_TRUE(f.fallback);
    EXPECT_NEAR(f.e_theta_eci.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f.e_omega_eci.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f.e_theta_eci.dot(axis), 0.0, 1e-12);
    EXPECT_NEAR(f.e_omega_eci.dot(axis), 0.0, 1e-12);
    EXPECT_NEAR(f.e_theta_eci.dot(f.e_omega_eci), 0.0, 1e-12);
  }
}

TEST(LosGeometry, RejectsNonFiniteInputs) {
  LosFrame f;
  EXPECT_FALSE(los_frame(Vec3(NAN, 0, 1), Vec3::Zero(), Vec3(7e6, 0, 0), Vec3::Zero(), 0.0, &f));
  EXPECT_FALSE(los_frame(Vec3(1, 0, 0), Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), 0.0, &f));
}

TEST(LosGeometry, ZemAndTimeToGoMatchStraightLineClosestApproach) {
  // Straight-line relative motion: true miss |r × v|/|v|, true time |r·v|/|v|². Eq. 7 and 12
  // use the instantaneous range rate, exact to second order in V_θ/|ṙ| (here 1e-3 → 1e-6).
  const Vec3 r(40e3, 0.0, 0.0);
  const Vec3 v(-7000.0, 7.0, 0.0);
  Vec3 u;
  Vec3 ud;
  los_from_relative(r, v, &u, &ud);
  double zem = 0.0;
  double tgo = 0.0;
  const double rdot = u.dot(v);
  ASSERT_TRUE(zero_effort_miss_m(r.norm(), rdot, ud.norm(), &zem));
  ASSERT_TRUE(time_to_go_s(r.norm(), rdot, &tgo));
  const double miss_true = r.cross(v).norm() / v.norm();
  const double t_true = -r.dot(v) / v.squaredNorm();
  EXPECT_NEAR(zem, miss_true, 2e-6 * miss_true);
  EXPECT_NEAR(tgo, t_true, 2e-6 * t_true);
  EXPECT_FALSE(zero_effort_miss_m(r.norm(), +10.0, ud.norm(), &zem));  // receding
  EXPECT_FALSE(time_to_go_s(r.norm(), 0.0, &tgo));
}

}  // namespace
