// The guidance node's parameter table (key prefix "node."): the one declaration of each
// NodeConfig field's unit, range and meaning (evade/core/param.hpp). The law's parameters
// are guidance::guidance_params() under "guidance.".
#pragma once

#include "evade/core/param.hpp"
#include "evade/guidance_lcm/node_config.hpp"

namespace evade::guidance_lcm {

ParamTable<NodeConfig> node_params() noexcept;

}  // namespace evade::guidance_lcm
