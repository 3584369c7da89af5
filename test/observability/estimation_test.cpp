// The Ceres angles-only batch estimator of the `estimation` objective (paper 004 Table 1):
// its covariance against the analytic linear covariance (Jᵀ R⁻¹ J + P0⁻¹)⁻¹, on a linear
// problem and at the nonlinear solution (J by central differences of eq. 3 written out here),
// and the estimation objective's optimum against a brute-force grid.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "evade/dynamics/hcw.hpp"
#include "evade/observability/estimation.hpp"
#include "evade/observability/planner.hpp"
#include "seed4_problem.hpp"

namespace evade::observability {
namespace {

using test::seed4;

const Vec6 kPriorSigma = (Vec6() << 2000, 2000, 2000, 5, 2, 1).finished();

TEST(ObservabilityEstimation, CeresCovarianceEqualsAnalyticOnLinearProblem) {
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::MatrixXd h(40, 6);
  Eigen::VectorXd z(40);
  for (int r = 0; r < 40; ++r) {
    for (int c = 0; c < 6; ++c) h(r, c) = g(rng) * (c < 3 ? 1e-5 : 1e-2);
    z(r) = g(rng) * 1e-3;
  }
  const double sigma = 1e-3;
  const Vec6 x_prior = (Vec6() << 100, -50, 20, 1, -1, 0.5).finished();
  const LinearBatchResult res = solve_linear_batch(h, z, sigma, x_prior, kPriorSigma);
  const Mat6 p0_inv = kPriorSigma.cwiseAbs2().cwiseInverse().asDiagonal();
  const Mat6 info = h.transpose() * h / (sigma * sigma) + p0_inv;
  const Mat6 p_analytic = info.inverse();
  const Vec6 x_analytic = p_analytic * (h.transpose() * z / (sigma * sigma) + p0_inv * x_prior);
  // Relative 1e-8: dense SVD of a 6x6 information matrix with condition ~1e6 in double.
  EXPECT_LT((res.cov - p_analytic).norm() / p_analytic.norm(), 1e-8);
  // The estimate is solver-tolerance limited, not exact: LM stops when the relative cost
  // decrease falls below function_tolerance = 1e-14, so the excess cost ½ dᵀ I d over the
  // analytic minimum must be a negligible fraction of the minimum cost (1e-10 allows for
  // the last accepted steps).
  const Vec6 d = res.x_hat - x_analytic;
  const Eigen::VectorXd rm = (h * x_analytic - z) / sigma;
  const double cost_min = 0.5 * (rm.squaredNorm() + (p0_inv.diagonal().cwiseSqrt().asDiagonal() * (x_analytic - x_prior)).squaredNorm());
  EXPECT_LT(0.5 * d.dot(info * d), 1e-10 * cost_min);
}

// Eq. 3 pitch/azimuth of the predicted LOS for state x (frame P), independent of the library.
Eigen::Vector2d predict(double n, double t, const Vec6& x, const Vec3& known_disp) {
  const Mat6 c6 = (Vec6() << -1, -1, 1, -1, -1, 1).finished().asDiagonal();
  const Vec6 xp = c6 * hcw_stm(n, t) * c6 * x;
  const Vec3 r = known_disp - xp.head<3>();
  return {std::atan(r.z() / r.x()), std::atan(r.y() / std::hypot(r.x(), r.z()))};
}

TEST(ObservabilityEstimation, CeresCovarianceEqualsLinearizedCovarianceAtTheSolution) {
  const SampledProblem s = sample(seed4());
  EstimationConfig ec;
  for (double theta : {-3.2453, -2.231}) {
    const Vec3 dv = dv_paper_from_angles(0.01, theta, 3.0);
    const EstimationResult e = estimate_angles_only(s, ec, dv);
    ASSERT_TRUE(e.converged);
    Mat6 info = kPriorSigma.cwiseAbs2().cwiseInverse().asDiagonal();
    for (double t : s.t_s) {
      Eigen::Matrix<double, 2, 6> j;
      for (int i = 0; i < 6; ++i) {
        const double step = i < 3 ? 1.0 : 1e-3;  // central differences: error ~ step² · h'''
        Vec6 xp = e.x_hat_p0, xm = e.x_hat_p0;
        xp(i) += step;
        xm(i) -= step;
        j.col(i) = (predict(s.problem.n_radps, t, xp, Vec3::Zero()) -
                    predict(s.problem.n_radps, t, xm, Vec3::Zero())) / (2 * step);
      }
      info += j.transpose() * j / (ec.sigma_rad * ec.sigma_rad);
    }
    const Mat6 p = info.inverse();
    // 1e-6 relative: truncation error of the central differences (range ~1e5 m, step 1 m).
    EXPECT_LT((e.cov_p0 - p).norm() / p.norm(), 1e-6) << theta;
  }
}

TEST(ObservabilityEstimation, NoBurnFitIsExactAndUnbiased) {
  // Noise-free measurements of an unmaneuvered evader are consistent with the prior mean.
  const SampledProblem s = sample(seed4());
  const EstimationResult e = estimate_angles_only(s, EstimationConfig{}, Vec3::Zero());
  EXPECT_LT((e.x_hat_p0 - s.problem.x_chaser_p0).norm(), 1e-6);
  EXPECT_LT(e.error_tf_m, 1e-6);
  EXPECT_LT(e.final_cost, 1e-12);
  EXPECT_GT(e.major_axis_m, 1000.0);  // range stays weakly observable from angles alone
}

TEST(ObservabilityEstimation, UnknownBurnBiasesTheEstimate) {
  // The chaser fitting a no-burn trajectory to a maneuvered evader ends with a position error;
  // the error is smaller for the observability-optimal direction than for direction B.
  const SampledProblem s = sample(seed4());
  const EstimationResult opt = estimate_angles_only(s, EstimationConfig{}, dv_paper_from_angles(0, -3.2453, 3));
  const EstimationResult b = estimate_angles_only(s, EstimationConfig{}, dv_paper_from_angles(0, -1.571, 3));
  EXPECT_GT(opt.error_tf_m, 1.0);
  EXPECT_GT(b.error_tf_m, 1.0);
  EXPECT_GT(b.final_cost, opt.final_cost);  // B's burn is seen in the residuals
}

TEST(ObservabilityEstimation, RejectsBadConfig) {
  const SampledProblem s = sample(seed4());
  EstimationConfig ec;
  ec.sigma_rad = 0.0;
  EXPECT_THROW(estimate_angles_only(s, ec, Vec3::Zero()), std::invalid_argument);
  ec = EstimationConfig{};
  ec.prior_sigma(4) = NAN;
  EXPECT_THROW(estimate_angles_only(s, ec, Vec3::Zero()), std::invalid_argument);
  EXPECT_THROW(estimate_angles_only(s, EstimationConfig{}, Vec3(NAN, 0, 0)), std::invalid_argument);
}

TEST(ObservabilityEstimation, IsresReachesGridOptimumOfEstimationObjective) {
  // A coarser problem (dt = 50 s, 21 samples) keeps the Ceres grid affordable in a unit test.
  ObservabilityProblem p = seed4();
  p.dt_obs_s = 50.0;
  p.eps_max_rad = 0.0;  // in-plane only: a 1-D grid over θ
  const SampledProblem s = sample(p);
  const EstimationConfig ec;
  auto f = [&](double t) {
    return estimate_angles_only(s, ec, dv_paper_from_angles(0, t, 3.0)).major_axis_m;
  };
  double best_t = 0, best_v = -1;
  for (int j = 0; j <= 400; ++j) {
    const double t = p.theta_min_rad + (p.theta_max_rad - p.theta_min_rad) * j / 400;
    const double v = f(t);
    if (v > best_v) best_t = t, best_v = v;
  }
  const double step = (p.theta_max_rad - p.theta_min_rad) / 400;
  const double c = best_t;
  for (int j = -200; j <= 200; ++j) {
    const double t = std::clamp(c + j * step / 100, p.theta_min_rad, p.theta_max_rad);
    const double v = f(t);
    if (v > best_v) best_t = t, best_v = v;
  }
  IsresOptions o;
  o.seed = 3;
  o.population = 20;
  o.max_evaluations = 300;
  const PlanResult r = plan_isres(s, ObjectiveKind::kEstimation, ec, o);
  std::printf("estimation objective: grid theta %.5f (%.3f m), ISRES %.5f (%.3f m), %d evals\n", best_t,
              best_v, r.theta_rad, r.value, r.evaluations);
  EXPECT_NEAR(r.theta_rad, best_t, 1e-3);
  EXPECT_GE(r.value, best_v - 1e-6);
}

}  // namespace
}  // namespace evade::observability
