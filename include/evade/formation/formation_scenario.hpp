// Reads paper 003's planning inputs (formation, conjunction, maneuver timing, propagation
// settings) from a scenario file: every scalar through a parameter table (the tables below,
// conjunction_spec_params() and maneuver_timing_params() in decision.hpp, the Earth table
// through config::read_earth), per-satellite elements, vectors and names through the typed
// getters of config::Scenario. Keys (SI units or degrees in their names):
//   earth.{mu_m3ps2, j2, re_m}                                   (optional, WGS-84 default)
//   formation.{side_length_m, box_delta_m, raan_tolerance_deg, phase_tolerance_deg,
//              horizon_days, reference_group}
//   formation.groups.N.{name, nominal_raan_offset_deg, nominal_phase_offset_deg,
//              chief|deputy1|deputy2.{a_m, e, i_deg, raan_deg, arg_lat_deg}}
//   conjunction.{group, satellite, tca_s, miss_rsw_m, v_rel_rsw_mps, required_miss_m}
//   maneuver.{burn_before_tca_s, restore_after_tca_s, restore}
//   propagation.{rel_tol, abs_tol_m, samples_per_rev}
// Every violation throws config::ConfigError naming the key, the value and the range.
#pragma once

#include "evade/config/scenario.hpp"
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

/// Reads and validates everything (does not call check_all_used()).
PlanInputs read_plan_inputs(const config::Scenario& sc);

}  // namespace evade::formation
