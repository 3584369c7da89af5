// The Earth model's parameter table (key prefix "earth."): the one place its ranges live.
// Every command that reads an Earth model reads it through config::read_earth (config module)
// with this table; the defaults are those of EarthModel (WGS-84 / EGM-96, constants.hpp).
#pragma once

#include "evade/core/constants.hpp"
#include "evade/core/param.hpp"

namespace evade {

/// mu_m3ps2, j2, re_m.
ParamTable<EarthModel> earth_params() noexcept;

}  // namespace evade
