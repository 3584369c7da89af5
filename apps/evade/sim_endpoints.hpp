// Endpoints of `evade sim` that need I/O (the pure ones are in evade/sim/guidance_endpoint.hpp).
//
// make_lcm_endpoint is implemented by the guidance-lcm side in apps/evade/sim_lcm_endpoint.cpp:
// it publishes the sim clock, nav state and angle measurements on LCM (lcm_url), and returns
// the thrust command in force received from evade_guidance_node. With lockstep = true it waits
// (up to timeout_s) for the node's command for this cycle before returning; otherwise it
// returns the latest command received. Throws std::runtime_error on a timeout or LCM failure.
// cmd_sim.cpp only calls it when sim_lcm_endpoint.cpp is present in the build
// (EVADE_SIM_HAS_LCM_ENDPOINT, see cmd_sim.cpp).
#pragma once

#include <memory>
#include <string>

#include "evade/sim/guidance_endpoint.hpp"

std::unique_ptr<evade::sim::GuidanceEndpoint> make_lcm_endpoint(const std::string& lcm_url,
                                                                bool lockstep, double timeout_s);
