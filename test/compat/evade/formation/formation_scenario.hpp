// The old home of paper 003's scenario reader, kept for the tests of test/guidance_lcm and
// test/lcm_link that still include it and call formation::read_plan_inputs (issue 41 moved
// the reader to evade::commands: evade/commands/formation_scenario.hpp). Only those tests see
// this folder (test/CMakeLists.txt); delete it once they include the commands header.
#pragma once

#include "evade/commands/formation_scenario.hpp"

namespace evade::formation {
using commands::read_plan_inputs;
}  // namespace evade::formation
