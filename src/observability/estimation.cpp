// Angles-only batch estimation for paper 004's Table 1 question ("does the burn degrade the
// chaser's estimate?"): measurement eq. 3, dynamics eq. 1–2 (HCW), prior P0 of §3. Solved
// with Ceres; the covariance is ceres::Covariance. See estimation.hpp for the model.
#include "evade/observability/estimation.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <ceres/ceres.h>

#include "evade/dynamics/hcw.hpp"

namespace evade::observability {
namespace {

// Residual of one sample: predicted LOS r = d − Φ_rr r0 − Φ_rv v0 (frame P), angles of eq. 3
// minus the measured ones, divided by σ. The pitch difference is written as
// atan((z x_m − x z_m) / (x x_m + z z_m)), i.e. ε − ε_m modulo π, smooth across the branch.
struct AngleResidual {
  Mat3 rr, rv;      // Φ_rr, Φ_rv in P
  Vec3 d;           // known burn displacement (zero if the estimator ignores the burn)
  Vec3 r_meas;      // measured LOS vector (only its direction enters)
  double az_meas;   // measured azimuth θ_m
  double inv_sigma;

  template <typename T>
  bool operator()(const T* const x, T* residual) const {
    T r[3];
    for (int i = 0; i < 3; ++i) {
      r[i] = T(d(i));
      for (int j = 0; j < 3; ++j) r[i] -= T(rr(i, j)) * x[j] + T(rv(i, j)) * x[3 + j];
    }
    using std::atan;
    using std::sqrt;
    const T num = r[2] * r_meas.x() - r[0] * r_meas.z();
    const T den = r[0] * r_meas.x() + r[2] * r_meas.z();
    residual[0] = atan(num / den) * inv_sigma;
    residual[1] = (atan(r[1] / sqrt(r[0] * r[0] + r[2] * r[2])) - az_meas) * inv_sigma;
    return true;
  }
};

// Prior residual (x − x_prior) ./ σ_prior: a diagonal P0.
struct PriorResidual {
  Vec6 x_prior;
  Vec6 inv_sigma;
  template <typename T>
  bool operator()(const T* const x, T* residual) const {
    for (int i = 0; i < 6; ++i) residual[i] = (x[i] - T(x_prior(i))) * T(inv_sigma(i));
    return true;
  }
};

// Linear measurement rows (for the covariance check): (H x − z) / σ.
struct LinearResidual {
  Eigen::Matrix<double, 1, 6> h;
  double z;
  double inv_sigma;
  template <typename T>
  bool operator()(const T* const x, T* residual) const {
    T s = T(-z);
    for (int i = 0; i < 6; ++i) s += T(h(i)) * x[i];
    residual[0] = s * T(inv_sigma);
    return true;
  }
};

void add_prior(ceres::Problem& problem, double* x, const Vec6& x_prior, const Vec6& prior_sigma) {
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PriorResidual, 6, 6>(
                               new PriorResidual{x_prior, prior_sigma.cwiseInverse()}),
                           nullptr, x);
}

ceres::Solver::Summary solve(ceres::Problem& problem, int max_iterations) {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_QR;
  o.minimizer_type = ceres::TRUST_REGION;
  o.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  o.max_num_iterations = max_iterations;
  o.function_tolerance = 1e-14;
  o.gradient_tolerance = 1e-14;
  o.parameter_tolerance = 1e-12;
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  o.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(o, &problem, &summary);
  return summary;
}

Mat6 covariance(ceres::Problem& problem, const double* x) {
  ceres::Covariance::Options o;
  o.algorithm_type = ceres::DENSE_SVD;  // 6 parameters: exact, and reports rank deficiency
  o.num_threads = 1;
  ceres::Covariance cov(o);
  const std::vector<std::pair<const double*, const double*>> blocks{{x, x}};
  if (!cov.Compute(blocks, &problem))
    throw std::runtime_error("ceres::Covariance::Compute failed (rank-deficient information)");
  Eigen::Matrix<double, 6, 6, Eigen::RowMajor> c;
  cov.GetCovarianceBlock(x, x, c.data());
  return c;
}

}  // namespace

void validate(const EstimationConfig& c) {
  if (!std::isfinite(c.sigma_rad) || c.sigma_rad <= 0.0)
    throw std::invalid_argument("estimation: sigma_rad = " + std::to_string(c.sigma_rad) +
                                " is invalid; allowed: finite, > 0 rad");
  for (int i = 0; i < 6; ++i)
    if (!std::isfinite(c.prior_sigma(i)) || c.prior_sigma(i) <= 0.0)
      throw std::invalid_argument("estimation: prior_sigma[" + std::to_string(i) + "] = " +
                                  std::to_string(c.prior_sigma(i)) +
                                  " is invalid; allowed: finite, > 0 [m or m/s]");
  if (c.max_iterations < 1)
    throw std::invalid_argument("estimation: max_iterations = " + std::to_string(c.max_iterations) +
                                " is invalid; allowed: >= 1");
}

EstimationResult estimate_angles_only(const SampledProblem& s, const EstimationConfig& c,
                                      const Vec3& dv_p_mps) {
  validate(c);
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(dv_p_mps(i)))
      throw std::invalid_argument("estimation: dv_p_mps[" + std::to_string(i) + "] is not finite");
  const ObservabilityProblem& p = s.problem;
  const Mat3 cp = rotation_rsw_to_paper();
  double x[6];
  for (int i = 0; i < 6; ++i) x[i] = p.x_chaser_p0(i);  // start at the prior mean

  ceres::Problem problem;
  for (std::size_t k = 0; k < s.t_s.size(); ++k) {
    const HcwBlocks b = hcw_stm_blocks(p.n_radps, s.t_s[k]);
    const Vec3 d_true = s.b_r_p[k] * dv_p_mps;
    const Vec3 r_true = d_true - s.r_chaser_p[k];  // evader rel. chaser, truth
    const auto ang = los_angles(r_true);
    auto* f = new AngleResidual{cp * b.rr * cp, cp * b.rv * cp,
                                c.estimator_knows_burn ? d_true : Vec3::Zero(), r_true,
                                ang.second, 1.0 / c.sigma_rad};
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<AngleResidual, 2, 6>(f), nullptr, x);
  }
  add_prior(problem, x, p.x_chaser_p0, c.prior_sigma);
  const ceres::Solver::Summary summary = solve(problem, c.max_iterations);

  EstimationResult out;
  out.x_hat_p0 = Eigen::Map<const Vec6>(x);
  out.cov_p0 = covariance(problem, x);
  out.final_cost = summary.final_cost;
  out.iterations = static_cast<int>(summary.iterations.size());
  out.converged = summary.termination_type == ceres::CONVERGENCE;

  const double tf = s.t_s.back();
  Mat6 phi;
  {
    const Mat6 c6 = (Vec6() << -1, -1, 1, -1, -1, 1).finished().asDiagonal();
    phi = c6 * hcw_stm(p.n_radps, tf) * c6;  // Φ in P
  }
  const Mat6 pf = phi * out.cov_p0 * phi.transpose();
  out.cov_pos_tf = pf.topLeftCorner<3, 3>();
  Eigen::SelfAdjointEigenSolver<Mat3> es(out.cov_pos_tf);
  out.major_axis_m = std::sqrt(std::max(0.0, es.eigenvalues().maxCoeff()));
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es2(pf.topLeftCorner<2, 2>());
  out.in_plane_major_axis_m = std::sqrt(std::max(0.0, es2.eigenvalues().maxCoeff()));
  // Chaser rel. actual evader at t_f: truth Φ_P X_P0 − B_r Δv; estimate Φ_P x̂ (− B_r Δv if
  // the estimator knows the burn).
  const Vec3 truth = s.r_chaser_p.back() - s.b_r_p.back() * dv_p_mps;
  Vec3 est = (phi * out.x_hat_p0).head<3>();
  if (c.estimator_knows_burn) est -= s.b_r_p.back() * dv_p_mps;
  out.error_tf_m = (est - truth).norm();
  return out;
}

LinearBatchResult solve_linear_batch(const Eigen::MatrixXd& h, const Eigen::VectorXd& z,
                                     double sigma, const Vec6& x_prior, const Vec6& prior_sigma) {
  if (h.cols() != 6 || h.rows() != z.size() || h.rows() < 1)
    throw std::invalid_argument("solve_linear_batch: H must be m x 6 and z of length m >= 1");
  EstimationConfig c;
  c.sigma_rad = sigma;
  c.prior_sigma = prior_sigma;
  validate(c);
  double x[6];
  for (int i = 0; i < 6; ++i) x[i] = x_prior(i);
  ceres::Problem problem;
  for (Eigen::Index r = 0; r < h.rows(); ++r)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<LinearResidual, 1, 6>(
                                 new LinearResidual{h.row(r), z(r), 1.0 / sigma}),
                             nullptr, x);
  add_prior(problem, x, x_prior, prior_sigma);
  solve(problem, 50);
  LinearBatchResult out;
  out.x_hat = Eigen::Map<const Vec6>(x);
  out.cov = covariance(problem, x);
  return out;
}

}  // namespace evade::observability
