// The inputs of paper 003's planner (Duan, Su, Gao, Qi, Yang, "Collision avoidance of
// formation-flying satellites under multiple configuration constraints"): the formation, the
// threatened satellite, the conjunction, the manoeuvre timing and the propagation settings
// (PlanInputs), and the parameter tables of the formation's and the propagation's scalars
// as a scenario states them (the conjunction's and the timing's are decision.hpp's). The
// scenario reader is commands::read_plan_inputs (evade/commands/formation_scenario.hpp).
#pragma once

#include "evade/core/param.hpp"
#include "evade/formation/decision.hpp"
#include "evade/formation/formation_model.hpp"
#include "evade/formation/numerical_constraints.hpp"

namespace evade::formation {

/// The formation's scalars as the scenario states them (prefix "formation."; angles in
/// degrees, converted into FormationSpec's radians). No defaults: required keys.
struct FormationParams {
  double side_length_m = 0.0;        ///< L
  double box_delta_m = 0.0;          ///< Δ (also at most L/8: FormationSpec::validate)
  double raan_tolerance_deg = 0.0;   ///< Ω_max
  double phase_tolerance_deg = 0.0;  ///< Δφ_max
  double horizon_days = 0.0;         ///< T
};
ParamTable<FormationParams> formation_params() noexcept;

/// The propagation settings as the scenario states them (prefix "propagation."), defaults
/// those of PropagationSettings.
struct PropagationParams {
  double rel_tol = PropagationSettings{}.integrator.rel_tol;  ///< DOP853 relative tolerance
  double abs_tol_m = PropagationSettings{}.integrator.abs_tol;  ///< DOP853 absolute tolerance [m, m/s]
  int samples_per_rev = PropagationSettings{}.samples_per_rev;
};
ParamTable<PropagationParams> propagation_params() noexcept;

struct PlanInputs {
  FormationSpec spec;
  SatelliteId threatened;
  ConjunctionSpec conjunction;
  ManeuverTiming timing;
  PropagationSettings propagation;
};

}  // namespace evade::formation
