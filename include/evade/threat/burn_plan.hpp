// Paper 001's evasive burn (evasion.hpp) as a BurnPlan (core/burn_plan.hpp), the form the
// ground publishes (evade_burn_plan_t) and the guidance node executes: the target's single
// impulse of magnitude V_E at t0 (paper 001 sec. 3.1, eq. 4: the evasion is one burn at the
// start of the threat window; plan t = 0 is that t0), Δv in RSW (the HCW frame of the
// solvers), source PlanSource::kThreatArea. The planner works in HCW about a circular
// reference and knows no inertial state, so no ECI Δv is given (dv_eci_valid = false): the
// node flies the RSW Δv with its own navigation.
#pragma once

#include <cstdint>

#include "evade/core/burn_plan.hpp"
#include "evade/threat/evasion.hpp"

namespace evade::threat {

/// The one-impulse plan of `evasion`, numbered plan_id. Throws std::invalid_argument naming
/// the field when evasion's Δv is not finite, or is zero (V_E = 0: nothing to fly), or does
/// not have the magnitude V_E (dv_mps) it claims.
BurnPlan make_burn_plan(const EvasionResult& evasion, std::int64_t plan_id);

}  // namespace evade::threat
