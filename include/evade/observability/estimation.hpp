// The chaser's angles-only batch estimate of the relative state, for the `estimation`
// objective of the observability-minimizing burn (paper 004, §3 and Table 1).
//
// Model (our definition; the paper states only P0 and "4th-order Runge–Kutta error
// propagation", not its estimator nor the measurement noise):
//  * Truth: the evader burns Δv at t0. The chaser measures (ε_m, θ_m) of eq. 3 of the LOS
//    r_PE(t_k) = B_r(t_k) Δv − Φ_P(t_k) X_P0 (frame P, problem.hpp) at every t_k = k dt,
//    k = 0..N. Measurements are noise-free (the covariance does not depend on the noise
//    realization; the fitted estimate is then the noise-free mean estimate).
//  * Estimator: a batch least-squares estimate of x = X_P0 (chaser rel. the evader's nominal
//    orbit at t0, frame P) with prior mean = the true X_P0 (the paper assumes the initial
//    relative state known) and prior covariance P0 = diag(prior_sigma²). Cost
//        Σ_k ‖(h(d_k − Φ_P(t_k) x) ⊖ z_k) / σ‖² + ‖(x − x_prior) ./ prior_sigma‖²,
//    where d_k = 0 when the chaser does NOT know about the burn (default: it fits a no-burn
//    HCW trajectory to the measurements of the maneuvered evader) and d_k = B_r(t_k) Δv when
//    it does (estimator_knows_burn). ⊖ is the angle difference (pitch modulo π).
//    Solved with Ceres (Levenberg–Marquardt, dense QR, autodiff); the covariance of x at the
//    solution is ceres::Covariance (= (Jᵀ R⁻¹ J + P0⁻¹)⁻¹ of the whitened problem, not scaled
//    by the residuals).
//  * Output: P_f = Φ(t_f) P Φ(t_f)ᵀ at the end of the window; the objective is the 1σ
//    semi-major axis sqrt(λ_max) of its 3×3 position block [m] (maximized: the burn that
//    leaves the chaser most uncertain). The estimate's actual position error at t_f (bias of
//    the no-burn fit) is reported beside it.
#pragma once

#include <Eigen/Dense>

#include "evade/observability/problem.hpp"

namespace evade::observability {

struct EstimationConfig {
  double sigma_rad = 1e-3;  ///< 1σ noise of each measured angle [rad] (our choice, > 0)
  Vec6 prior_sigma = (Vec6() << 2000.0, 2000.0, 2000.0, 5.0, 2.0, 1.0).finished();  ///< sqrt(diag P0), Table 1 [m, m/s]
  bool estimator_knows_burn = false;  ///< true: the fit includes the true burn
  int max_iterations = 50;            ///< Levenberg–Marquardt iterations
};

/// Throws std::invalid_argument on sigma <= 0, non-finite or non-positive prior_sigma,
/// max_iterations < 1.
void validate(const EstimationConfig& c);

struct EstimationResult {
  Vec6 x_hat_p0 = Vec6::Zero();     ///< estimated X_P0, frame P [m, m/s]
  Mat6 cov_p0 = Mat6::Zero();       ///< ceres::Covariance of x at t0 [m², m²/s, m²/s²]
  Mat3 cov_pos_tf = Mat3::Zero();   ///< position covariance at t_f, frame P [m²]
  double major_axis_m = 0.0;        ///< sqrt(λ_max(cov_pos_tf)), 1σ [m] (the objective)
  double in_plane_major_axis_m = 0.0;  ///< same for the x–y (orbit-plane) block [m]
  double error_tf_m = 0.0;          ///< |estimated − true chaser rel. evader position| at t_f [m]
  double final_cost = 0.0;          ///< Ceres cost (½ Σ whitened residual²) [-]
  int iterations = 0;               ///< LM iterations
  bool converged = false;           ///< Ceres reported convergence
};

/// Batch estimate after a burn dv_p_mps (frame P; zero for the no-burn case).
EstimationResult estimate_angles_only(const SampledProblem& s, const EstimationConfig& c,
                                      const Vec3& dv_p_mps);

/// The same Ceres least-squares + prior + ceres::Covariance machinery on a linear model
/// z = H x + noise (σ per row), used to check the covariance against the analytic
/// (Hᵀ R⁻¹ H + P0⁻¹)⁻¹. Returns the estimate and its covariance.
struct LinearBatchResult {
  Vec6 x_hat = Vec6::Zero();
  Mat6 cov = Mat6::Zero();
};
LinearBatchResult solve_linear_batch(const Eigen::MatrixXd& h, const Eigen::VectorXd& z,
                                     double sigma, const Vec6& x_prior, const Vec6& prior_sigma);

}  // namespace evade::observability
