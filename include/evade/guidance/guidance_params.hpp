// The guidance law's parameter table (key prefix "guidance."): the one declaration of each
// GuidanceConfig field's unit, range and meaning (evade/core/param.hpp). Read by
// GuidanceConfig::validate(), the simulator's scenario reader, the guidance node's flags and
// --config, and docs/PARAMETERS.md.
#pragma once

#include "evade/core/param.hpp"
#include "evade/guidance/guidance_law.hpp"

namespace evade::guidance {

ParamTable<GuidanceConfig> guidance_params() noexcept;

}  // namespace evade::guidance
