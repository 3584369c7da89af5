// The plan beside no burn and the paper's directions (comparison.hpp, paper 004 §3): each
// summary agrees with the objectives computed directly (eq. 23, the LOS-angle change of
// eq. 3, the angles-only estimate), the directions come in the documented order, and the
// convergence history keeps every 100th evaluation and the last.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "evade/observability/comparison.hpp"
#include "seed4_problem.hpp"

namespace evade::observability {
namespace {

using test::seed4;

TEST(ObservabilityComparison, NoBurnHasZeroDvAndZeroPaperValue) {
  const SampledProblem s = sample(seed4());
  const EstimationConfig ec;
  const DirectionSummary d = describe_direction(s, ObjectiveKind::kPaper, ec, {"no-burn", false, 0.3, -2.0});
  EXPECT_EQ(d.direction.name, "no-burn");
  EXPECT_FALSE(d.direction.burn);
  EXPECT_EQ(d.dv_paper_mps, Vec3::Zero());
  EXPECT_EQ(d.dv_lvlh_mps, Vec3::Zero());
  EXPECT_EQ(d.paper_f, 0.0);
  EXPECT_EQ(d.value, 0.0);
  EXPECT_EQ(d.los_change.sum_rad, 0.0);
  const EstimationResult est = estimate_angles_only(s, ec, Vec3::Zero());
  EXPECT_EQ(d.estimation.major_axis_m, est.major_axis_m);
}

TEST(ObservabilityComparison, SummaryAgreesWithTheObjectives) {
  const SampledProblem s = sample(seed4());
  const EstimationConfig ec;
  const double eps = 0.01;
  const double theta = test::kPaperThetaRad;
  const Vec3 dv_p = dv_paper_from_angles(eps, theta, s.problem.dv_mps);
  const LosChange lc = los_change_dv(s, dv_p);
  const EstimationResult est = estimate_angles_only(s, ec, dv_p);
  const BurnDirection dir{"paper-optimum", true, eps, theta};

  const DirectionSummary p = describe_direction(s, ObjectiveKind::kPaper, ec, dir);
  EXPECT_EQ(p.paper_f, paper_objective(s, eps, theta));
  EXPECT_EQ(p.value, p.paper_f);
  EXPECT_EQ(p.dv_paper_mps, dv_p);
  EXPECT_EQ(p.dv_lvlh_mps, rotation_rsw_to_paper() * dv_p);
  EXPECT_NEAR(p.dv_lvlh_mps.norm(), 3.0, 1e-12);
  EXPECT_EQ(p.dv_lvlh_mps.x(), -dv_p.x());  // P = RSW turned by π about the normal
  EXPECT_EQ(p.los_change.sum_rad, lc.sum_rad);
  EXPECT_EQ(p.los_change.max_azimuth_change_rad, lc.max_azimuth_change_rad);
  EXPECT_EQ(p.estimation.major_axis_m, est.major_axis_m);

  EXPECT_EQ(describe_direction(s, ObjectiveKind::kLosChange, ec, dir).value, lc.sum_rad);
  EXPECT_EQ(describe_direction(s, ObjectiveKind::kEstimation, ec, dir).value, est.major_axis_m);
}

TEST(ObservabilityComparison, ThinHistoryKeepsEveryHundredthAndTheLast) {
  std::vector<double> h(250);
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = static_cast<double>(i);
  const auto t = thin_history(h, 100);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].evaluations, 100u);
  EXPECT_EQ(t[0].best, 99.0);
  EXPECT_EQ(t[1].evaluations, 200u);
  EXPECT_EQ(t[2].evaluations, 250u);
  EXPECT_EQ(t[2].best, 249.0);
  EXPECT_EQ(thin_history(std::vector<double>(200, 1.0), 100).size(), 2u);
  EXPECT_TRUE(thin_history({}, 100).empty());
  EXPECT_THROW(thin_history(h, 0), std::invalid_argument);
}

TEST(ObservabilityComparison, PlanComesFirstThenNoBurnPaperAAndB) {
  const SampledProblem s = sample(seed4());
  const EstimationConfig ec;
  PlanResult res;
  res.eps_rad = 0.0;
  res.theta_rad = -3.0;
  res.value = 42.0;  // the planner's value is reported as is
  res.history.assign(150, 1.0);
  PaperDirections paper;
  paper.optimum_theta_rad = test::kPaperThetaRad;
  paper.a_theta_rad = test::kThetaA;
  paper.b_theta_rad = test::kThetaB;
  const PlanComparison c = compare_with_paper(s, ObjectiveKind::kPaper, ec, res, paper);
  EXPECT_EQ(c.optimum.direction.name, "optimum");
  EXPECT_EQ(c.optimum.value, 42.0);
  EXPECT_EQ(c.optimum.paper_f, paper_objective(s, 0.0, -3.0));
  ASSERT_EQ(c.history.size(), 2u);
  EXPECT_EQ(c.history[1].evaluations, 150u);
  ASSERT_EQ(c.compare.size(), 4u);
  EXPECT_EQ(c.compare[0].direction.name, "no-burn");
  EXPECT_FALSE(c.compare[0].direction.burn);
  EXPECT_EQ(c.compare[1].direction.name, "paper-optimum");
  EXPECT_EQ(c.compare[1].direction.theta_rad, test::kPaperThetaRad);
  EXPECT_EQ(c.compare[2].direction.name, "A");
  EXPECT_EQ(c.compare[2].value, paper_objective(s, 0.0, test::kThetaA));
  EXPECT_EQ(c.compare[3].direction.name, "B");
  EXPECT_EQ(c.compare[3].direction.theta_rad, test::kThetaB);
}

}  // namespace
}  // namespace evade::observability
