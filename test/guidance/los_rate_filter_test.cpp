// LosRateFilter (paper 000 sec. 3: e_θ from filtered angle measurements). Truth here is a
// great circle traversed at a constant rate — exactly the filter's process model — sampled
// at 50 Hz with white angle noise, seeded.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "evade/core/constants.hpp"
#include "evade/guidance/los_geometry.hpp"
#include "evade/guidance/los_rate_filter.hpp"

namespace {

using evade::Vec3;
using namespace evade::guidance;

struct GreatCircle {
  Vec3 u0;
  Vec3 e_theta0;  // ⊥ u0
  double rate_radps;
  Vec3 u(double t) const {
    return std::cos(rate_radps * t) * u0 + std::sin(rate_radps * t) * e_theta0;
  }
  Vec3 u_dot(double t) const {
    return rate_radps * (-std::sin(rate_radps * t) * u0 + std::cos(rate_radps * t) * e_theta0);
  }
};

GreatCircle make_circle(const Vec3& u0, const Vec3& dir, double rate) {
  const Vec3 u = u0.normalized();
  return {u, (dir - dir.dot(u) * u).normalized(), rate};
}

// A measurement with its time of validity in the filter's time base.
struct LosMeasurement : AnglesMeasurement {
  double t_s = 0.0;
};
LosUpdateResult update(LosRateFilter& f, const LosMeasurement& m) { return f.update(m, m.t_s); }

// Noisy angles of u: isotropic tangent noise σ (what the filter assumes).
LosMeasurement noisy(const Vec3& u, double t, double sigma, std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  const Vec3 a = (std::abs(u.x()) < 0.9) ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 t1 = u.cross(a).normalized();
  const Vec3 t2 = u.cross(t1);
  const Vec3 z = (u + sigma * n(rng) * t1 + sigma * n(rng) * t2).normalized();
  const LosAngles ang = los_angles_from_unit(z);
  LosMeasurement m;
  m.t_s = t;
  m.elevation_rad = ang.elevation_rad;
  m.azimuth_rad = ang.azimuth_rad;
  m.sigma_angle_rad = sigma;
  return m;
}

LosFilterConfig quiet_config() {
  LosFilterConfig c;
  c.process_noise_radps2 = 1e-9;  // truth has a constant rate
  return c;
}

TEST(LosRateFilter, ConvergesOnConstantRateLosWithNoise) {
  const GreatCircle gc = make_circle(Vec3(1, 2, 0.5), Vec3(0, 0, 1), 2e-3);
  const double sigma = 50e-6;
  std::mt19937_64 rng(11);
  LosRateFilter f(quiet_config());
  for (int k = 0; k <= 500; ++k) {  // 10 s at 50 Hz
    const double t = 0.02 * k;
    const LosUpdateResult r = update(f, noisy(gc.u(t), t, sigma, rng));
    if (k == 0) {
      EXPECT_EQ(r, LosUpdateResult::kInitialized);
    }
  }
  const double t = 10.0;
  const double rate_err = std::abs(f.los_rate_radps() - gc.rate_radps);
  // CV-filter rate accuracy after N = 500 samples over T = 10 s: σ_ω ≈ σ sqrt(12/(N T²))
  // ≈ 7.7e-7 rad/s; allow 5σ and compare with the filter's own estimate.
  EXPECT_LT(rate_err, 4e-6);
  EXPECT_LT(rate_err, 5.0 * std::sqrt(f.los_rate_variance()));
  const Vec3 e_theta = f.u_dot_eci_ps().normalized();
  EXPECT_LT((e_theta - gc.u_dot(t).normalized()).norm(), 5e-3);
  EXPECT_LT((f.u_eci() - gc.u(t)).norm(), 5.0 * sigma);
  EXPECT_EQ(f.rejected(), 0);
}

// reset() forgets the track (the next measurement initializes it again, counters from
// zero) and keeps the configuration.
TEST(LosRateFilter, ResetForgetsTheTrackAndKeepsTheConfiguration) {
  const GreatCircle gc = make_circle(Vec3(1, 2, 0.5), Vec3(0, 0, 1), 2e-3);
  std::mt19937_64 rng(5);
  LosFilterConfig cfg = quiet_config();
  cfg.gate_chi2_2dof = 9.21;  // p = 0.99 instead of the default 0.999
  LosRateFilter f(cfg);
  for (int k = 0; k <= 50; ++k) update(f, noisy(gc.u(0.02 * k), 0.02 * k, 50e-6, rng));
  ASSERT_TRUE(f.initialized());
  ASSERT_GT(f.accepted(), 0);
  f.reset();
  EXPECT_FALSE(f.initialized());
  EXPECT_EQ(f.accepted(), 0);
  EXPECT_EQ(f.updates_since_init(), 0);
  EXPECT_EQ(update(f, noisy(gc.u(2.0), 2.0, 50e-6, rng)), LosUpdateResult::kInitialized);
  EXPECT_EQ(f.config().gate_chi2_2dof, 9.21);
}

TEST(LosRateFilter, UsesMeasuredRatesWhenPresent) {
  const GreatCircle gc = make_circle(Vec3(0.3, -1, 0.2), Vec3(1, 0, 0), 4e-9);  // paper 000
  LosFilterConfig cfg;
  LosRateFilter f(cfg);
  const Vec3 u = gc.u(0.0);
  const LosAngles a = los_angles_from_unit(u);
  // ε̇, β̇ from u̇ = ε̇ y_s − β̇ cos ε z_s.
  const Vec3 y_s(-std::cos(a.azimuth_rad) * std::sin(a.elevation_rad),
                 -std::sin(a.azimuth_rad) * std::sin(a.elevation_rad), std::cos(a.elevation_rad));
  const Vec3 z_s(std::sin(a.azimuth_rad), -std::cos(a.azimuth_rad), 0.0);
  LosMeasurement m;
  m.elevation_rad = a.elevation_rad;
  m.azimuth_rad = a.azimuth_rad;
  m.has_rates = true;
  m.elevation_rate_radps = gc.u_dot(0.0).dot(y_s);
  m.azimuth_rate_radps = -gc.u_dot(0.0).dot(z_s) / std::cos(a.elevation_rad);
  update(f, m);
  EXPECT_NEAR(f.los_rate_radps(), 4e-9, 1e-20);
  EXPECT_LT((f.u_dot_eci_ps().normalized() - gc.e_theta0).norm(), 1e-9);
}

TEST(LosRateFilter, GateRejectsAnOutlierAndCountsIt) {
  const GreatCircle gc = make_circle(Vec3(1, 0, 0), Vec3(0, 1, 0), 1e-3);
  std::mt19937_64 rng(3);
  LosRateFilter f(quiet_config());
  for (int k = 0; k <= 200; ++k) update(f, noisy(gc.u(0.02 * k), 0.02 * k, 50e-6, rng));
  const Vec3 u_before = f.u_eci();
  const double t = 0.02 * 201;
  LosMeasurement bad = noisy(gc.u(t), t, 50e-6, rng);
  bad.elevation_rad += 0.01;  // 200 σ
  EXPECT_EQ(update(f, bad), LosUpdateResult::kRejected);
  EXPECT_EQ(f.rejected(), 1);
  EXPECT_GT(f.last_nis(), f.config().gate_chi2_2dof);
  EXPECT_EQ(f.u_eci(), u_before);  // state untouched
  EXPECT_EQ(update(f, noisy(gc.u(t + 0.02), t + 0.02, 50e-6, rng)), LosUpdateResult::kAccepted);
}

TEST(LosRateFilter, GapGrowsCovarianceThenReinitializesAfterTooLongAGap) {
  const GreatCircle gc = make_circle(Vec3(1, 1, 0), Vec3(0, 0, 1), 1e-3);
  std::mt19937_64 rng(5);
  LosFilterConfig cfg;  // default process noise, reinit_gap_s = 2
  LosRateFilter f(cfg);
  for (int k = 0; k <= 100; ++k) update(f, noisy(gc.u(0.02 * k), 0.02 * k, 50e-6, rng));
  evade::Mat6 p_now;
  evade::Mat6 p_later;
  f.predict_to(f.time_s(), nullptr, nullptr, &p_now);
  f.predict_to(f.time_s() + 1.5, nullptr, nullptr, &p_later);
  EXPECT_GT(p_later.trace(), 10.0 * p_now.trace());
  // 1.5 s gap: still tracked, accepted.
  const double t1 = f.time_s() + 1.5;
  EXPECT_EQ(update(f, noisy(gc.u(t1), t1, 50e-6, rng)), LosUpdateResult::kAccepted);
  EXPECT_EQ(f.reinitializations(), 0);
  // 2.5 s gap > reinit_gap_s: re-initialised from the new measurement.
  const double t2 = t1 + 2.5;
  EXPECT_EQ(update(f, noisy(gc.u(t2), t2, 50e-6, rng)), LosUpdateResult::kInitialized);
  EXPECT_EQ(f.reinitializations(), 1);
  EXPECT_EQ(f.updates_since_init(), 1);
}

TEST(LosRateFilter, StaysFiniteThroughTheElevationPole) {
  // Great circle through +z: (ε, β) are singular at the pole, u and u̇ are not.
  const GreatCircle gc = make_circle(Vec3(1, 0, 0.2), Vec3(0, 0, 1), 0.2);
  std::mt19937_64 rng(9);
  LosFilterConfig cfg = quiet_config();
  cfg.init_rate_sigma_radps = 0.5;  // the true 0.2 rad/s must be inside the prior
  LosRateFilter f(cfg);
  for (int k = 0; k <= 500; ++k) {
    const double t = 0.02 * k;
    update(f, noisy(gc.u(t), t, 50e-6, rng));
    ASSERT_TRUE(f.u_eci().allFinite());
    ASSERT_TRUE(f.u_dot_eci_ps().allFinite());
  }
  EXPECT_NEAR(f.los_rate_radps(), 0.2, 1e-4);
  EXPECT_EQ(f.rejected(), 0);
}

// Consistency: NEES of the 4-dof tangent error (angles + rates) at t = 5 s over 200 seeded
// runs. For a consistent filter the mean NEES of N runs times N is chi-square with 4N dof;
// the two-sided 99% interval for the mean (Wilson–Hilferty) with N = 200 is [3.50, 4.54].
TEST(LosRateFilter, NeesWithinChiSquareBoundsOverSeededRuns) {
  const int runs = 200;
  double nees_sum = 0.0;
  for (int i = 0; i < runs; ++i) {
    std::mt19937_64 rng(1000 + i);
    const GreatCircle gc = make_circle(Vec3(1, 0.5, -0.3), Vec3(0.2, 0, 1), 3e-3);
    LosRateFilter f(quiet_config());
    const double sigma = 50e-6;
    for (int k = 0; k <= 250; ++k) update(f, noisy(gc.u(0.02 * k), 0.02 * k, sigma, rng));
    const double t = 5.0;
    const Vec3 u = gc.u(t);
    const Vec3 a = (std::abs(u.x()) < 0.9) ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 t1 = u.cross(a).normalized();
    const Vec3 t2 = u.cross(t1);
    Eigen::Matrix<double, 4, 6> T = Eigen::Matrix<double, 4, 6>::Zero();
    T.block<1, 3>(0, 0) = t1.transpose();
    T.block<1, 3>(1, 0) = t2.transpose();
    T.block<1, 3>(2, 3) = t1.transpose();
    T.block<1, 3>(3, 3) = t2.transpose();
    evade::Vec6 err;
    err << f.u_eci() - u, f.u_dot_eci_ps() - gc.u_dot(t);
    const Eigen::Vector4d e = T * err;
    const Eigen::Matrix4d P = T * f.covariance() * T.transpose();
    nees_sum += e.dot(P.ldlt().solve(e));
  }
  const double mean = nees_sum / runs;
  std::printf("mean NEES over %d runs = %.3f (4-dof; 99%% bounds [3.50, 4.54])\n", runs, mean);
  EXPECT_GT(mean, 3.50);
  EXPECT_LT(mean, 4.54);
}

}  // namespace
