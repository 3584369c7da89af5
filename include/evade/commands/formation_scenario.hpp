// Reads paper 003's planning inputs (formation::PlanInputs: formation, conjunction, maneuver
// timing, propagation settings) from a scenario file: every scalar through a parameter table
// (formation_params() and propagation_params() in formation/plan_inputs.hpp,
// conjunction_spec_params() and maneuver_timing_params() in formation/decision.hpp, the
// Earth table through config::read_earth), per-satellite elements, vectors and names through
// the typed getters of config::Scenario. Keys (SI units or degrees in their names):
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
#include "evade/formation/plan_inputs.hpp"

namespace evade::commands {

/// Reads and validates everything (does not call check_all_used()).
formation::PlanInputs read_plan_inputs(const config::Scenario& sc);

}  // namespace evade::commands
