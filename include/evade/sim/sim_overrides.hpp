// Run-time overrides of a simulation scenario (`evade sim --accel ... --noise-rad ...`,
// paper 000 sec. 4 and 5): each given value is written into the scenario as an override of
// its key, so it is range-checked by the same parameter table as the file
// (sim_params.hpp, guidance_params.hpp) and echoed in Scenario::used(). Sensor rule: an
// angle-noise override alone selects the angles-only sensor (the guidance filter estimates
// the LOS rates, paper 000 eq. 15–18); with a rate-noise override as well the sensor keeps
// its noisy rate-stabilised rates. no_rates always selects angles only.
#pragma once

#include <optional>

#include "evade/config/scenario.hpp"
#include "evade/sim/sim_config.hpp"

namespace evade::sim {

/// Values given for one run (empty: keep the scenario's). Finite numbers (the caller parses
/// and rejects NaN/Inf naming its own flag); ranges are checked when the scenario is read.
struct SimOverrides {
  std::optional<double> max_accel_mps2;       ///< guidance.max_accel_mps2
  std::optional<double> detect_before_tca_s;  ///< encounter.detect_before_tca_s
  std::optional<double> noise_rad;            ///< sensor.noise_rad
  std::optional<double> sensor_rate_hz;       ///< sensor.rate_hz
  std::optional<double> guidance_rate_hz;     ///< guidance.rate_hz
  std::optional<double> rate_noise_radps;     ///< sensor.rate_noise_radps
  bool no_rates = false;                      ///< angles only (sensor.has_rates = false)
};

/// Writes the overrides into sc (in the order of the fields above, then sensor.has_rates).
void apply_sim_overrides(const SimOverrides& o, config::Scenario* sc);

/// The SimConfig of sc: sim_config_from_scenario, then check_all_used() (no other keys are
/// read for a run) and SimConfig::validate(). Throws config::ConfigError or
/// std::invalid_argument naming the key.
SimConfig read_sim_config(const config::Scenario& sc);

}  // namespace evade::sim
