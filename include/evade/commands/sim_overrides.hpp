// Run-time overrides of a simulation scenario (`evade sim --max-accel-mps2 ... --noise-rad
// ...`, paper 000 sec. 4 and 5): each given value is given to the scenario typed
// (Scenario::set_value: the double itself, no text), so it is range-checked by the same
// parameter table as the file (sim_params.hpp, guidance_params.hpp) and echoed in
// Scenario::used(). Sensor rule: an
// angle-noise override alone selects the angles-only sensor (the guidance filter estimates
// the LOS rates, paper 000 eq. 15–18); with a rate-noise override as well the sensor keeps
// its noisy rate-stabilised rates. no_rates always selects angles only.
#pragma once

#include <string>
#include <vector>

#include "evade/config/scenario.hpp"
#include "evade/sim/sim_config.hpp"

namespace evade::commands {

/// What the command line gave for one run: the parameter flags' values (already checked
/// against their keys' declarations: evade/config/param_flags.hpp) and --no-rates. Ranges
/// are checked again when the scenario is read.
struct SimOverrides {
  std::vector<ParamValue> params;   ///< {"sensor.noise_rad", 5e-05}, ... in command-line order
  bool no_rates = false;            ///< angles only (sensor.has_rates = false)
};

/// Gives the values to sc (in order: a later one of a key wins), then the sensor rule's
/// sensor.has_rates.
void apply_sim_overrides(const SimOverrides& o, config::Scenario* sc);

/// The SimConfig of sc: sim_config_from_scenario, then check_all_used() (no other keys are
/// read for a run) and SimConfig::validate(). Throws config::ConfigError or
/// std::invalid_argument naming the key.
sim::SimConfig read_sim_config(const config::Scenario& sc);

}  // namespace evade::commands
