// The real-time simulator's link to evade_guidance_node over LCM (sim::RealtimeLink): the
// node runs in its ordinary fixed-rate mode (no lockstep, no sim clock); the simulator
// publishes evade_nav_state_t and evade_angles_t stamped with their time of validity and
// keeps the newest evade_thrust_cmd_t (validated; a malformed one is never thrust).
//
// Clock (docs/VALIDATION.md, paper 000, "Real-time HIL"): the fixed-rate node stamps each
// cycle with CLOCK_REALTIME µs. The link's clock is CLOCK_REALTIME µs read once at
// construction and advanced by CLOCK_MONOTONIC, so the simulator's schedule is monotonic (an
// NTP step during a run cannot make truth jump) while its stamps share the node's time base;
// the two agree to within the NTP slew over the run (parts per million).
#pragma once

#include <memory>
#include <string>

#include "evade/guidance_lcm/signed_encode.hpp"
#include "evade/sim/realtime_link.hpp"

namespace evade::lcm_link {

/// Opens lcm_url (empty: LCM's default). With a sensor key (id != 0) nav and angles are signed
/// (docs/SECURITY.md AUTH-3). Throws std::runtime_error when LCM cannot be opened
/// or subscribed; wait_for_command throws std::runtime_error on an LCM receive failure.
std::unique_ptr<sim::RealtimeLink> make_realtime_lcm_link(
    const std::string& lcm_url, const guidance_lcm::SigningKey& sensor_key = {});

}  // namespace evade::lcm_link
