// `evade sim --plan FILE` as a library call: a burn-plan file (plan_file.hpp) flown in the
// simulator by the in-process guidance law + plan executor (the executor the node runs), on
// a simulation scenario's objects (plan_run_config, run_plan_simulation); the result is the
// planned against the delivered Δv of every impulse. Times are seconds after the run starts
// (the scenario's epoch); planned Δv in RSW, delivered Δv in ECI (J2000 axes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/config/scenario.hpp"
#include "evade/core/state.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "evade/sim/sim_config.hpp"

namespace evade::commands {

struct SimPlanRequest {
  sim::SimConfig config;         ///< the scenario's simulation (read_sim_plan_request)
  std::string scenario_source;   ///< the scenario's name or file
  nlohmann::json scenario_used;  ///< every scenario key read, with its value
  std::string plan_file;         ///< the burn-plan file to fly
  double plan_epoch_s = 0.0;     ///< the plan's t = 0, seconds after the run starts
  double after_s = 0.0;          ///< run time after the last burn [s]
};

/// The SimConfig of sc (read_sim_config) and its echo; the plan fields are left default.
/// Throws config::ConfigError or std::invalid_argument naming the key.
SimPlanRequest read_sim_plan_request(const config::Scenario& sc);

/// One impulse of the plan: as planned, and as the actuator delivered it.
struct ImpulseFlown {
  double t_planned_s = 0.0;                ///< after the run starts [s]
  double dv_planned_mps = 0.0;             ///< |Δv| planned [m/s]
  Vec3 dv_planned_rsw_mps = Vec3::Zero();  ///< Δv planned in RSW [m/s]
  bool delivered = false;
  double t_start_s = 0.0;                  ///< the burn's start [s]
  double t_end_s = 0.0;                    ///< its end [s]
  double centre_offset_s = 0.0;            ///< burn centre minus planned time [s]
  double dv_delivered_mps = 0.0;           ///< |∫ a dt| [m/s]
  Vec3 dv_delivered_eci_mps = Vec3::Zero();  ///< ∫ a dt in ECI [m/s]
};

// clang-tidy 14's bugprone-exception-escape reports this aggregate's implicit special
// members without naming a throwing call; they only move or destroy std::string, std::vector
// and nlohmann::json members, whose moves are noexcept.
struct SimPlanResult {  // NOLINT(bugprone-exception-escape)
  std::string plan_file;
  std::int64_t plan_id = 0;
  guidance::PlanFrame frame = guidance::PlanFrame::kRsw;
  double plan_epoch_s = 0.0;          ///< the plan's t = 0 after the run starts [s]
  std::vector<ImpulseFlown> impulses;  ///< in plan order
  std::size_t burns_delivered = 0;
  bool all_delivered = false;         ///< one burn per impulse (else exit code 1)
  long cycles = 0;
  double duration_s = 0.0;            ///< the run's length [s]
  double guidance_rate_hz = 0.0;
  std::string scenario_source;
  nlohmann::json scenario_used;
  std::vector<std::string> warnings;  ///< for stderr (fewer burns than impulses)
};

/// Reads and flies req.plan_file. Throws std::invalid_argument for a bad plan file, a bad
/// epoch or run length, or the executor's rejection (naming the file and the epoch).
SimPlanResult run_sim_plan(const SimPlanRequest& req);

/// The command's JSON (the keys of `evade sim --plan FILE --json`).
nlohmann::json to_json(const SimPlanResult& r);

/// One line per impulse: planned and delivered |Δv| [m/s], burn interval [s after start].
std::string to_text(const SimPlanResult& r);

}  // namespace evade::commands
