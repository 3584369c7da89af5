// Paper 003's avoidance decision (decision.hpp) as a BurnPlan (core/burn_plan.hpp), the form
// the ground publishes (evade_burn_plan_t) and the guidance node executes: one impulse per
// burn of Decision::burn_plan() (the Δa burn `burn_before_tca_s` before the TCA, and the
// restore burn −Δa `restore_after_tca_s` after it), at its time from the scenario epoch
// (plan t = 0 is the scenario's t = 0), source PlanSource::kFormation.
//
// Δv: the burns are tangential (along the velocity) with the vis-viva magnitude of
// burn_propagation.hpp. The state at each burn comes from the verifier's propagation
// (propagate_with_burns: two-body + J2, DOP853, the earlier burns applied), so
//   Δv_eci = Δv v̂(t_b),   Δv_rsw = C_rsw←eci(t_b) Δv_eci
// (RSW of the osculating orbit at the burn; a tangential burn changes neither r̂ nor ĥ, so
// the pre- and post-burn frames agree). Both are filled (dv_eci_valid = true): the node may
// fly the RSW Δv (turned with its own navigation, robust to a timing error of the ground's
// prediction) or the ECI Δv.
#pragma once

#include <cstdint>

#include "evade/core/burn_plan.hpp"
#include "evade/formation/decision.hpp"
#include "evade/formation/formation_model.hpp"
#include "evade/formation/numerical_constraints.hpp"

namespace evade::formation {

/// The plan of `decision` for satellite `threatened`, numbered plan_id. Throws
/// std::invalid_argument when there is nothing to fly (no maneuver needed, or the decision
/// is not feasible: the best trade-off is never published as a plan) or more burns than a
/// plan holds; std::runtime_error when the propagation fails.
BurnPlan make_burn_plan(const FormationSpec& spec, const SatelliteId& threatened,
                        const Decision& decision, const PropagationSettings& settings,
                        std::int64_t plan_id);

}  // namespace evade::formation
