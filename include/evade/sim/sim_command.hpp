// The old home of what the caller of `evade sim` supplies: the run's guidance link and the
// Monte Carlo runner are evade/sim/run_hooks.hpp, the command itself (request, run, JSON,
// text) is evade/commands/sim_command.hpp (issue 41). Kept for lcm_link/sim_lcm_guidance.hpp,
// which includes this name; delete it once that header includes run_hooks.hpp.
#pragma once

#include "evade/sim/run_hooks.hpp"
