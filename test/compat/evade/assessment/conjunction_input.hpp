// The old home of the conjunction readers, kept for the test of test/lcm_link that still
// includes it and calls assessment::read_conjunction_scenario (issue 41 moved the readers to
// evade::commands: evade/commands/conjunction_input.hpp). Only that test sees this folder
// (test/CMakeLists.txt); delete it once the test includes the commands header.
#pragma once

#include "evade/commands/conjunction_input.hpp"

namespace evade::assessment {
using commands::read_conjunction_scenario;
}  // namespace evade::assessment
