// The simulator's parameter table (keys from the scenario's top level: encounter.*,
// sensor.*, actuator.*, integrator.*): the one declaration of each SimConfig
// field's unit, range and meaning (evade/core/param.hpp). The guidance law's own parameters
// are guidance::guidance_params() under "guidance.".
#pragma once

#include "evade/core/param.hpp"
#include "evade/sim/sim_config.hpp"

namespace evade::sim {

ParamTable<SimConfig> sim_params() noexcept;

}  // namespace evade::sim
