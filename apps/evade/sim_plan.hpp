// `evade sim --plan FILE`: a plan file (sim/plan_file.hpp) flown in the simulator by the
// in-process guidance law + plan executor (the executor the node runs), on the scenario's
// objects (sim::plan_run_config, sim::run_plan_simulation); prints planned vs delivered Δv
// per impulse. I/O only.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "evade/sim/sim_config.hpp"

namespace evade::cli {

struct SimPlanOptions {
  std::string plan_file;
  double epoch_s = 0.0;  ///< the plan's t = 0, seconds after the run starts
  double after_s = 0.0;  ///< extra run time after the last burn
};

/// Runs the plan; fills *j; returns the exit code (1 when not every impulse was delivered).
int run_sim_plan(const SimPlanOptions& o, const sim::SimConfig& cfg, nlohmann::json* j);

/// One line per impulse on stdout (the text form of *j).
void print_sim_plan(const nlohmann::json& j);

}  // namespace evade::cli
