// The old home of the simulation scenario reader, kept for the test of test/guidance_lcm that
// still includes it and calls sim::read_sim_config (issue 41 moved the reader to
// evade::commands: evade/commands/sim_overrides.hpp). Only that test sees this folder
// (test/CMakeLists.txt); delete it once the test includes the commands header.
#pragma once

#include "evade/commands/sim_overrides.hpp"

namespace evade::sim {
using commands::read_sim_config;
}  // namespace evade::sim
