// Builds a SimConfig from a scenario file (e.g. scenarios/seed0.yaml, paper 000 Table 1).
// Every key carries its unit; every value is range-checked by config::Scenario (NaN/Inf and
// out-of-range values throw config::ConfigError naming the key). The caller runs
// check_all_used() after any command-specific reads.
#pragma once

#include "evade/config/scenario.hpp"
#include "evade/sim/sim_config.hpp"

namespace evade::commands {

sim::SimConfig sim_config_from_scenario(const config::Scenario& sc);

}  // namespace evade::commands
