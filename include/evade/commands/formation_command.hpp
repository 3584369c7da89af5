// `evade plan formation` as a library call (paper 003: Duan You, Su Peng, Gao Yan, Qi
// Yajiang, Yang Shiqi, "Collision avoidance of formation-flying satellites under multiple
// configuration constraints"): the drift coefficients K_Ω, K_φ, K_am (paper eqs. 2, 4),
// Table 1 (the largest raise / lower of the semi-major axis per constraint and overall), the
// decision (direction, Δa, burn times, vis-viva Δv) and its verification by two-body + J2
// propagation (the miss at the TCA, each constraint's minimum margin over T days);
// optionally Table 1 recomputed by bisection on propagated margins. Request -> run -> result;
// to_json is the command's JSON (the keys and number formatting of `evade plan formation
// --json`: angles in degrees there), to_text its human report (margins of angle constraints
// in radians, the others in metres, each with its unit). Times are seconds after the
// scenario's epoch (t = 0).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/config/scenario.hpp"
#include "evade/core/burn_plan.hpp"
#include "evade/commands/formation_scenario.hpp"
#include "evade/formation/limits.hpp"
#include "evade/formation/verification.hpp"

namespace evade::commands {

/// Text sink for progress lines (e.g. stderr); empty: silent.
using FormationTextSink = std::function<void(const std::string&)>;

struct FormationRequest {
  formation::PlanInputs inputs;   ///< formation, threatened satellite, conjunction, timing
  bool numerical_limits = false;  ///< also Table 1 by bisection on propagated margins (slower)
  nlohmann::json scenario_used = nlohmann::json::object();  ///< every scenario value read
  FormationTextSink progress;     ///< one line as each step starts; empty: none
};

/// Reads the planning inputs (read_plan_inputs) and rejects any key nobody read
/// (check_all_used). Throws config::ConfigError naming the key, its value and the range.
FormationRequest read_formation_request(const config::Scenario& sc);

struct FormationResult {
  formation::PlanInputs inputs;
  formation::LimitsResult limits;  ///< Table 1 (analytic)
  formation::Decision decision;
  formation::Verification verification;
  bool numerical = false;          ///< numerical_limits below were computed
  std::vector<formation::NumericalLimitRow> numerical_limits;  ///< one per row of limits.rows
  double runtime_s = 0.0;          ///< wall time of the whole plan [s]
  nlohmann::json scenario_used = nlohmann::json::object();
};

/// Limits, decision, verification (and the numerical limits when asked for). Throws
/// std::invalid_argument for bad inputs, std::runtime_error when a propagation fails.
FormationResult run_formation(const FormationRequest& req);

/// The decision's two burns as a plan numbered plan_id (formation::make_burn_plan of
/// formation/burn_plan.hpp).
/// Throws std::invalid_argument when there is nothing to fly (see there).
BurnPlan make_burn_plan(const FormationResult& r, std::int64_t plan_id);

/// The JSON of `evade plan formation --json` (same keys, order and numbers).
nlohmann::json to_json(const FormationResult& r);

/// The human report: K's, Table 1, the decision and its burns (t after the epoch, Δa in m,
/// tangential Δv in m/s), the verification with each constraint's minimum margin and unit.
std::string to_text(const FormationResult& r);

}  // namespace evade::commands
