// Paper 004 objectives checked against an independent model and a brute-force grid, and the
// ISRES planner against the grid optimum. The independent model integrates the HCW ODE
// (written here in the paper frame P, where it has the same form as in RSW because P is RSW
// turned by π about the normal) with classical RK4 at 1 s steps, instead of the closed-form
// STM used by the library. RK4 with h = 1 s on a system of frequency n ≈ 1.13e-3 rad/s has
// a relative error ~ (n h)^4 / 120 ≈ 1e-14 per step, so values agree to ~1e-9.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "evade/core/constants.hpp"
#include "evade/observability/objectives.hpp"
#include "evade/observability/planner.hpp"
#include "seed4_problem.hpp"

namespace evade::observability {
namespace {

using test::seed4;

// ---- independent reference -------------------------------------------------------------
using S6 = std::array<double, 6>;

S6 hcw_rhs(double n, const S6& x) {
  return {x[3], x[4], x[5], 3 * n * n * x[0] + 2 * n * x[4], -2 * n * x[3], -n * n * x[2]};
}

// Positions at t = 0, dt, 2 dt, ... (count samples), integrating with RK4 at h = dt/10.
std::vector<Vec3> rk4_positions(double n, S6 x, double dt, std::size_t count) {
  std::vector<Vec3> out;
  const int sub = 10;
  const double h = dt / sub;
  for (std::size_t k = 0; k < count; ++k) {
    out.emplace_back(x[0], x[1], x[2]);
    for (int s = 0; s < sub; ++s) {
      auto add = [](const S6& a, const S6& b, double c) {
        S6 r;
        for (int i = 0; i < 6; ++i) r[i] = a[i] + c * b[i];
        return r;
      };
      const S6 k1 = hcw_rhs(n, x);
      const S6 k2 = hcw_rhs(n, add(x, k1, h / 2));
      const S6 k3 = hcw_rhs(n, add(x, k2, h / 2));
      const S6 k4 = hcw_rhs(n, add(x, k3, h));
      for (int i = 0; i < 6; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
  }
  return out;
}

struct Reference {
  std::vector<Vec3> chaser;  // chaser rel. evader nominal, P
  double n;
  std::size_t count;
  double dt;
};

Reference make_reference(const ObservabilityProblem& p) {
  S6 x;
  for (int i = 0; i < 6; ++i) x[i] = p.x_chaser_p0(i);
  const std::size_t count = static_cast<std::size_t>(std::floor(p.t_obs_s / p.dt_obs_s + 1e-9)) + 1;
  return {rk4_positions(p.n_radps, x, p.dt_obs_s, count), p.n_radps, count, p.dt_obs_s};
}

std::vector<Vec3> ref_displacement(const Reference& r, const Vec3& dv_p) {
  return rk4_positions(r.n, {0, 0, 0, dv_p.x(), dv_p.y(), dv_p.z()}, r.dt, r.count);
}

// Eq. 23 with the k = 0 term contributing 0 (OA'_0 = 0).
double ref_paper_f(const Reference& r, const Vec3& dv_p) {
  const auto d = ref_displacement(r, dv_p);
  double f = 0;
  for (std::size_t k = 0; k < r.count; ++k) {
    if (d[k].norm() == 0) continue;
    f += (-r.chaser[k]).normalized().dot(d[k].normalized());
  }
  return f;
}

// Max |Δazimuth| and the summed angular change, with eq. 3 written out directly.
std::pair<double, double> ref_los(const Reference& r, const Vec3& dv_p) {
  const auto d = ref_displacement(r, dv_p);
  double mx = 0, sum = 0;
  for (std::size_t k = 0; k < r.count; ++k) {
    const Vec3 a = -r.chaser[k], b = a + d[k];
    const double az0 = std::atan2(a.y(), std::sqrt(a.x() * a.x() + a.z() * a.z()));
    const double az1 = std::atan2(b.y(), std::sqrt(b.x() * b.x() + b.z() * b.z()));
    const double el0 = std::atan(a.z() / a.x()), el1 = std::atan(b.z() / b.x());
    mx = std::max(mx, std::abs(az1 - az0));
    sum += std::hypot(az1 - az0, el1 - el0);  // x < 0 all along: no π wrap of atan(z/x)
  }
  return {mx, sum};
}

// ---- brute-force grid ----------------------------------------------------------------------
struct GridBest {
  double eps, theta, value;
};

// Coarse 2-D grid over the whole box, then two finer grids around the best cell: exhaustive
// evaluation, no optimizer. Final spacing 2e-5 rad in θ, 2.5e-4 rad in ε.
template <class F>
GridBest grid_search(const ObservabilityProblem& p, bool maximize, F f) {
  GridBest best{0, 0, maximize ? -1e300 : 1e300};
  auto consider = [&](double e, double t) {
    const double v = f(e, t);
    if (maximize ? v > best.value : v < best.value) best = {e, t, v};
  };
  const int ne = 9, nt = 1000;
  for (int i = 0; i < ne; ++i)
    for (int j = 0; j <= nt; ++j)
      consider(-p.eps_max_rad + 2 * p.eps_max_rad * i / (ne - 1),
               p.theta_min_rad + (p.theta_max_rad - p.theta_min_rad) * j / nt);
  double de = 2 * p.eps_max_rad / (ne - 1), dt = (p.theta_max_rad - p.theta_min_rad) / nt;
  for (int level = 0; level < 2; ++level) {
    const GridBest c = best;
    const double de2 = de / 10, dt2 = dt / 50;
    for (int i = -10; i <= 10; ++i)
      for (int j = -100; j <= 100; ++j) {
        const double e = std::clamp(c.eps + i * de2, -p.eps_max_rad, p.eps_max_rad);
        const double t = std::clamp(c.theta + j * dt2, p.theta_min_rad, p.theta_max_rad);
        consider(e, t);
      }
    de = de2;
    dt = dt2;
  }
  return best;
}

// ---- tests ---------------------------------------------------------------------------------

TEST(ObservabilityObjectives, PaperObjectiveMatchesIndependentRk4Model) {
  const SampledProblem s = sample(seed4());
  const Reference ref = make_reference(s.problem);
  for (double eps : {-0.05, 0.0, 0.03}) {
    for (double th = -4.7; th < -1.6; th += 0.31) {
      const Vec3 dv = dv_paper_from_angles(eps, th, 3.0);
      // 1e-9 absolute on a sum of 100 unit dot products: RK4 error (see file comment).
      EXPECT_NEAR(paper_objective(s, eps, th), ref_paper_f(ref, dv), 1e-9) << eps << " " << th;
    }
  }
}

TEST(ObservabilityObjectives, LosChangeMatchesIndependentRk4Model) {
  const SampledProblem s = sample(seed4());
  const Reference ref = make_reference(s.problem);
  for (double eps : {-0.05, 0.0, 0.02}) {
    for (double th = -4.7; th < -1.6; th += 0.37) {
      const Vec3 dv = dv_paper_from_angles(eps, th, 3.0);
      const LosChange lc = los_change(s, eps, th);
      const auto r = ref_los(ref, dv);
      EXPECT_NEAR(lc.max_azimuth_change_rad, r.first, 1e-11);
      EXPECT_NEAR(lc.sum_rad, r.second, 1e-9);
    }
  }
}

TEST(ObservabilityObjectives, NoBurnChangesNoAngle) {
  const SampledProblem s = sample(seed4());
  const LosChange lc = los_change_dv(s, Vec3::Zero());
  EXPECT_EQ(lc.sum_rad, 0.0);
  EXPECT_EQ(lc.max_azimuth_change_rad, 0.0);
}

TEST(ObservabilityObjectives, InPlaneBurnChangesNoElevation) {
  // ε = 0 and z = 0 in X_P0: the motion stays in the orbit plane, ε_m = atan(0/x) = 0.
  const SampledProblem s = sample(seed4());
  EXPECT_EQ(los_change(s, 0.0, -2.5).max_elevation_change_rad, 0.0);
  EXPECT_GT(los_change(s, 0.05, -2.5).max_elevation_change_rad, 1e-4);
}

TEST(ObservabilityObjectives, K0TermLimitAddsUnitDvDotLos) {
  ObservabilityProblem p = seed4();
  const double f0 = paper_objective(sample(p), 0.0, -3.0);
  p.k0 = K0Term::kLimit;
  const double f1 = paper_objective(sample(p), 0.0, -3.0);
  const Vec3 a0 = -p.x_chaser_p0.head<3>();
  EXPECT_NEAR(f1 - f0, a0.normalized().dot(dv_paper_from_angles(0.0, -3.0, 1.0)), 1e-12);
}

TEST(ObservabilityPaper004, PaperObjectiveOptimumNearPublishedTheta) {
  // Paper: optimum [ε, θ] = [0, −3.231], f = 100.9991. Ours (frame P, k = 0 term = 0):
  // θ ≈ −3.2453, f ≈ 96.498. The tolerance 0.02 rad is the acceptance bound; the
  // peak is flat (f drops by 0.009 from −3.2453 to −3.231), see docs/VALIDATION.md.
  const SampledProblem s = sample(seed4());
  const GridBest g = grid_search(s.problem, true, [&](double e, double t) { return paper_objective(s, e, t); });
  std::printf("paper objective: ours theta = %.5f eps = %.5f f = %.5f | paper theta = -3.231 f = 100.9991\n",
              g.theta, g.eps, g.value);
  EXPECT_NEAR(g.theta, test::kPaperThetaRad, 0.02);
  EXPECT_NEAR(g.eps, 0.0, 1e-3);
  // f cannot reach the paper's 100.9991: its early terms are ≈ cos 30°.
  EXPECT_LT(g.value, 97.0);
  EXPECT_GT(g.value, 96.0);
}

TEST(ObservabilityPaper004, OnlyTheOptimumKeepsAzimuthChangeSmall) {
  // Paper Fig. 6: only the optimum keeps |Δθ_m| below 0.01 rad over 1000 s; A and B do not.
  // Ours: optimum 4.8e-3, A 8.7e-3, B 1.13e-2 rad. The ordering and B > 0.01 reproduce; A
  // stays (just) below 0.01 in our model, contrary to the paper (docs/VALIDATION.md).
  const SampledProblem s = sample(seed4());
  const GridBest g = grid_search(s.problem, true, [&](double e, double t) { return paper_objective(s, e, t); });
  const double opt = los_change(s, g.eps, g.theta).max_azimuth_change_rad;
  const double a = los_change(s, 0.0, test::kThetaA).max_azimuth_change_rad;
  const double b = los_change(s, 0.0, test::kThetaB).max_azimuth_change_rad;
  std::printf("max |d azimuth|: optimum %.5f A %.5f B %.5f rad (paper: only the optimum < 0.01)\n", opt, a, b);
  EXPECT_LT(opt, 0.01);
  EXPECT_LT(opt, 0.6 * a);
  EXPECT_LT(a, b);
  EXPECT_GT(b, 0.01);
  EXPECT_LT(a, 0.01);  // the paper's claim fails for A in our reading (documented)
}

class IsresSeeds : public ::testing::TestWithParam<int> {};

TEST_P(IsresSeeds, PaperObjectiveReachesGridOptimum) {
  const SampledProblem s = sample(seed4());
  const GridBest g = grid_search(s.problem, true, [&](double e, double t) { return paper_objective(s, e, t); });
  IsresOptions o;
  o.seed = static_cast<std::uint64_t>(GetParam());
  const PlanResult r = plan_isres(s, ObjectiveKind::kPaper, EstimationConfig{}, o);
  // Polished result: within 1e-3 rad of the grid optimum (grid spacing 2e-5 rad).
  EXPECT_NEAR(r.theta_rad, g.theta, 1e-3);
  EXPECT_NEAR(r.eps_rad, g.eps, 1e-3);
  EXPECT_GE(r.value, g.value - 1e-9);
  // Raw ISRES (2400 evaluations, population 80), reported honestly: within 0.02 rad.
  std::printf("seed %d: raw ISRES theta %.6f (|err| %.2e) eps %.2e, polished %.6f, grid %.6f, evals %d\n",
              GetParam(), r.isres_theta_rad, std::abs(r.isres_theta_rad - g.theta), r.isres_eps_rad,
              r.theta_rad, g.theta, r.evaluations);
  EXPECT_NEAR(r.isres_theta_rad, g.theta, 0.02);
  EXPECT_EQ(static_cast<std::size_t>(r.evaluations), r.history.size());
  for (std::size_t i = 1; i < r.history.size(); ++i) EXPECT_GE(r.history[i], r.history[i - 1]);
}

TEST_P(IsresSeeds, LosChangeObjectiveReachesGridOptimum) {
  const SampledProblem s = sample(seed4());
  const GridBest g =
      grid_search(s.problem, false, [&](double e, double t) { return los_change(s, e, t).sum_rad; });
  IsresOptions o;
  o.seed = static_cast<std::uint64_t>(GetParam());
  const PlanResult r = plan_isres(s, ObjectiveKind::kLosChange, EstimationConfig{}, o);
  EXPECT_NEAR(r.theta_rad, g.theta, 1e-3);
  EXPECT_NEAR(r.eps_rad, g.eps, 1e-3);
  EXPECT_LE(r.value, g.value + 1e-12);
  for (std::size_t i = 1; i < r.history.size(); ++i) EXPECT_LE(r.history[i], r.history[i - 1]);
}

INSTANTIATE_TEST_SUITE_P(FiveSeeds, IsresSeeds, ::testing::Values(1, 2, 3, 42, 2024));

TEST(ObservabilityPlanner, DeterministicForAGivenSeed) {
  const SampledProblem s = sample(seed4());
  IsresOptions o;
  o.seed = 7;
  o.polish = LocalPolish::kNone;  // raw ISRES: its path depends on the RNG only
  const PlanResult a = plan_isres(s, ObjectiveKind::kPaper, EstimationConfig{}, o);
  const PlanResult b = plan_isres(s, ObjectiveKind::kPaper, EstimationConfig{}, o);
  EXPECT_EQ(a.theta_rad, b.theta_rad);
  EXPECT_EQ(a.eps_rad, b.eps_rad);
  EXPECT_EQ(a.value, b.value);
  EXPECT_EQ(a.history, b.history);
  o.seed = 8;
  const PlanResult c = plan_isres(s, ObjectiveKind::kPaper, EstimationConfig{}, o);
  EXPECT_NE(a.history, c.history);  // a different seed takes a different path
}

TEST(ObservabilityPlanner, NelderMeadPolishAlsoConverges) {
  const SampledProblem s = sample(seed4());
  IsresOptions o;
  o.polish = LocalPolish::kNelderMead;
  const PlanResult r = plan_isres(s, ObjectiveKind::kPaper, EstimationConfig{}, o);
  EXPECT_NEAR(r.theta_rad, -3.2453, 1e-3);  // the grid optimum of PaperObjectiveOptimum...
}

// ---- bad input ---------------------------------------------------------------------------

TEST(ObservabilityInput, RejectsZeroDv) {
  ObservabilityProblem p = seed4();
  p.dv_mps = 0.0;
  try {
    sample(p);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("dv_mps"), std::string::npos) << e.what();
  }
}

TEST(ObservabilityInput, RejectsInvertedBounds) {
  ObservabilityProblem p = seed4();
  p.theta_min_rad = -1.0;
  p.theta_max_rad = -2.0;
  EXPECT_THROW(sample(p), std::invalid_argument);
  try {
    sample(p);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("theta_min_rad"), std::string::npos) << e.what();
  }
}

TEST(ObservabilityInput, RejectsNaNState) {
  ObservabilityProblem p = seed4();
  p.x_chaser_p0(3) = std::nan("");
  try {
    sample(p);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("x_chaser_p0[3]"), std::string::npos) << e.what();
  }
}

TEST(ObservabilityInput, RejectsOtherBadFields) {
  auto bad = [](auto mutate) {
    ObservabilityProblem p = seed4();
    mutate(p);
    EXPECT_THROW(sample(p), std::invalid_argument);
  };
  bad([](ObservabilityProblem& p) { p.dv_mps = -3.0; });
  bad([](ObservabilityProblem& p) { p.dv_mps = INFINITY; });
  bad([](ObservabilityProblem& p) { p.n_radps = 0.0; });
  bad([](ObservabilityProblem& p) { p.dt_obs_s = 0.0; });
  bad([](ObservabilityProblem& p) { p.t_obs_s = 1.0; });
  bad([](ObservabilityProblem& p) { p.eps_max_rad = -0.1; });
  bad([](ObservabilityProblem& p) { p.x_chaser_p0.head<3>().setZero(); });
  bad([](ObservabilityProblem& p) { p.theta_min_rad = NAN; });
}

TEST(ObservabilityInput, PlannerRejectsBadOptionsAndUnsampledProblems) {
  const SampledProblem s = sample(seed4());
  IsresOptions o;
  o.max_evaluations = 0;
  EXPECT_THROW(plan_isres(s, ObjectiveKind::kPaper, EstimationConfig{}, o), std::invalid_argument);
  o = IsresOptions{};
  o.population = 2;
  EXPECT_THROW(plan_isres(s, ObjectiveKind::kPaper, EstimationConfig{}, o), std::invalid_argument);
  SampledProblem bad = s;
  bad.problem.dv_mps = 0.0;  // mutated after sampling: re-validated
  EXPECT_THROW(plan_isres(bad, ObjectiveKind::kPaper, EstimationConfig{}, IsresOptions{}), std::invalid_argument);
  SampledProblem empty;
  empty.problem = seed4();
  EXPECT_THROW(plan_isres(empty, ObjectiveKind::kPaper, EstimationConfig{}, IsresOptions{}), std::invalid_argument);
  EXPECT_THROW(parse_objective("paperr"), std::invalid_argument);
}

}  // namespace
}  // namespace evade::observability
