// What the guidance node authenticates with (docs/SECURITY.md): its keys, where it persists
// their states and the command ARSNs, and the time base of sensor ARSNs. Built at start-up by
// the node's main (from --keys and --auth-state) or by a test; the policy of which channels
// must be signed is a parameter (NodeConfig::auth).
#pragma once

#include <cstdint>
#include <string>

#include "evade/auth/keyring.hpp"

namespace evade::guidance_lcm {

struct NodeSecurity {
  auth::KeyRing keys;              ///< loaded keys (auth::load_into), states restored
  std::string state_path;          ///< persisted state (auth::StateFile); empty: memory only
  /// Sensor ARSNs must exceed this [us]: the node's start time on CLOCK_REALTIME in the
  /// fixed-rate mode (the simulator signs with ARSN = utime), 0 in lockstep.
  std::int64_t sensor_arsn_floor_us = 0;
};

}  // namespace evade::guidance_lcm
