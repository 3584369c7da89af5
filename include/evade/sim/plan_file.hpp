// The old home of the burn-plan file: issue 41 moved the file format (JSON) to evade::commands
// (evade/commands/plan_file.hpp, linked with evade::commands), since the simulator knows no
// JSON. Kept, forwarding, for what still names this path and the sim:: names:
// docs/GUIDANCE_NODE.md and test/guidance_lcm/plan_file_lcm_test.cpp; delete it once they
// name the commands header.
#pragma once

#include "evade/commands/plan_file.hpp"

namespace evade::sim {
using commands::PlanFile;
using commands::read_plan_file;
using commands::write_plan_file;
}  // namespace evade::sim
