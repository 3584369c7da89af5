// The observability planner's result (planner.hpp) as a BurnPlan (core/burn_plan.hpp): one
// impulse at the epoch of the relative state (paper 004 burns at t0), Δv in RSW, no ECI Δv
// (the paper gives no inertial state), source PlanSource::kObservability, and (ε, θ), the
// objective, its value and the evaluations in the observability block.
#pragma once

#include <cstdint>
#include <string>

#include "evade/core/burn_plan.hpp"
#include "evade/observability/planner.hpp"

namespace evade::observability {

/// The BurnPlan code of an objective, and the objective's name ("paper", "los-change",
/// "estimation": objective_name) of a BurnPlan code (std::invalid_argument for another).
PlanObjective plan_objective(ObjectiveKind k);
std::string plan_objective_name(int code);

/// plan_id: the publisher's plan number. Throws std::invalid_argument if res holds a
/// non-finite Δv, angle or value (field named).
BurnPlan make_burn_plan(const PlanResult& res, std::int64_t plan_id);

}  // namespace evade::observability
