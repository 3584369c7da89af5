// make_burn_plan (burn_plan.hpp): the planner's result as a one-impulse BurnPlan.
#include "evade/observability/burn_plan.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace evade::observability {
PlanObjective plan_objective(ObjectiveKind k) {
  switch (k) {
    case ObjectiveKind::kPaper: return PlanObjective::kPaper;
    case ObjectiveKind::kLosChange: return PlanObjective::kLosChange;
    case ObjectiveKind::kEstimation: return PlanObjective::kEstimation;
  }
  throw std::invalid_argument("PlanResult.objective: unknown objective");
}

std::string plan_objective_name(int code) {
  for (ObjectiveKind k : {ObjectiveKind::kPaper, ObjectiveKind::kLosChange, ObjectiveKind::kEstimation})
    if (static_cast<int>(plan_objective(k)) == code) return objective_name(k);
  throw std::invalid_argument("BurnPlan.observability.objective = " + std::to_string(code) +
                              " is not a known objective");
}

namespace {

void require_finite(const char* field, bool ok) {
  if (!ok) throw std::invalid_argument(std::string("PlanResult.") + field + " is not finite");
}

}  // namespace

BurnPlan make_burn_plan(const PlanResult& res, std::int64_t plan_id) {
  require_finite("dv_rsw_mps", res.dv_rsw_mps.allFinite());
  require_finite("eps_rad", std::isfinite(res.eps_rad));
  require_finite("theta_rad", std::isfinite(res.theta_rad));
  require_finite("value", std::isfinite(res.value));
  BurnPlan p;
  p.plan_id = plan_id;
  p.n_impulses = 1;
  p.impulses[0].t_s = 0.0;  // paper 004 burns at t0
  p.impulses[0].dv_rsw_mps = res.dv_rsw_mps;
  p.impulses[0].dv_eci_valid = false;
  p.source = static_cast<int>(PlanSource::kObservability);
  p.observability.valid = true;
  p.observability.eps_rad = res.eps_rad;
  p.observability.theta_rad = res.theta_rad;
  p.observability.objective = static_cast<int>(plan_objective(res.objective));
  p.observability.objective_value = res.value;
  p.observability.evaluations = res.evaluations;
  return p;
}

}  // namespace evade::observability
