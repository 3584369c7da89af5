// The plan beside no burn and the paper's directions (paper 004 §3; comparison.hpp): eq. 23
// (objectives.hpp), the LOS-angle change of eq. 3 and the angles-only estimate per direction.
#include "evade/observability/comparison.hpp"

#include <stdexcept>

namespace evade::observability {

DirectionSummary describe_direction(const SampledProblem& s, ObjectiveKind k,
                                    const EstimationConfig& ec, const BurnDirection& d) {
  DirectionSummary r;
  r.direction = d;
  r.objective = k;
  const Vec3 dv_p =
      d.burn ? dv_paper_from_angles(d.eps_rad, d.theta_rad, s.problem.dv_mps) : Vec3::Zero();
  r.los_change = los_change_dv(s, dv_p);
  r.paper_f = d.burn ? paper_objective(s, d.eps_rad, d.theta_rad) : 0.0;
  r.estimation = estimate_angles_only(s, ec, dv_p);
  switch (k) {
    case ObjectiveKind::kPaper: r.value = r.paper_f; break;
    case ObjectiveKind::kLosChange: r.value = r.los_change.sum_rad; break;
    case ObjectiveKind::kEstimation: r.value = r.estimation.major_axis_m; break;
  }
  r.dv_lvlh_mps = rotation_rsw_to_paper() * dv_p;  // the rotation is its own inverse
  r.dv_paper_mps = dv_p;
  return r;
}

std::vector<ConvergencePoint> thin_history(const std::vector<double>& history,
                                           std::size_t every) {
  if (every < 1) throw std::invalid_argument("thin_history: every = 0, expected >= 1");
  std::vector<ConvergencePoint> out;
  for (std::size_t i = 0; i < history.size(); ++i) {
    if ((i + 1) % every == 0 || i + 1 == history.size()) out.push_back({i + 1, history[i]});
  }
  return out;
}

PlanComparison compare_with_paper(const SampledProblem& s, ObjectiveKind k,
                                  const EstimationConfig& ec, const PlanResult& res,
                                  const PaperDirections& paper) {
  PlanComparison c;
  c.optimum = describe_direction(s, k, ec, {"optimum", true, res.eps_rad, res.theta_rad});
  c.optimum.value = res.value;
  c.history = thin_history(res.history, 100);
  c.compare.push_back(describe_direction(s, k, ec, {"no-burn", false, 0.0, 0.0}));
  c.compare.push_back(describe_direction(
      s, k, ec, {"paper-optimum", true, paper.optimum_eps_rad, paper.optimum_theta_rad}));
  c.compare.push_back(describe_direction(s, k, ec, {"A", true, paper.a_eps_rad, paper.a_theta_rad}));
  c.compare.push_back(describe_direction(s, k, ec, {"B", true, paper.b_eps_rad, paper.b_theta_rad}));
  return c;
}

}  // namespace evade::observability
