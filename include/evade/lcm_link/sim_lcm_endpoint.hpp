// The simulator's link to evade_guidance_node over LCM: a sim::GuidanceEndpoint that
// publishes the sim clock, nav state and angle measurements on LCM and returns the thrust
// command in force received from the node.
#pragma once

#include <memory>
#include <string>

#include "evade/guidance_lcm/signed_encode.hpp"
#include "evade/sim/guidance_endpoint.hpp"

namespace evade::lcm_link {

/// Opens lcm_url (empty: LCM's default). With lockstep = true every exchange waits (up to
/// timeout_s) for the node's command for this cycle; otherwise it returns the latest command
/// received. Pacing: EVADE_SIM_LCM_REALTIME_FACTOR=F (> 0) sends tick k no earlier than
/// k*dt/F of wall time after the first (unset: unpaced). Throws std::invalid_argument on
/// timeout_s <= 0 or a bad EVADE_SIM_LCM_REALTIME_FACTOR, std::runtime_error when LCM cannot
/// be opened; exchange throws std::runtime_error on a timeout or an LCM failure.
/// With a sensor key (id != 0) nav, angles and the sim clock are signed (docs/SECURITY.md AUTH-3).
std::unique_ptr<sim::GuidanceEndpoint> make_lcm_endpoint(
    const std::string& lcm_url, bool lockstep, double timeout_s,
    const guidance_lcm::SigningKey& sensor_key = {});

}  // namespace evade::lcm_link
