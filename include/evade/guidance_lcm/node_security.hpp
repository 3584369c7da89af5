// What the guidance node authenticates with (docs/SECURITY.md): its keys, where it persists
// their states and the command ARSNs and how it starts from that file, and the time base of
// sensor ARSNs. Built at start-up by the node's main (from --keys, --auth-state and
// --auth-init) or by a test; the policy of which channels must be signed is a parameter
// (NodeConfig::auth).
#pragma once

#include <cstdint>
#include <string>

#include "evade/auth/keyring.hpp"

namespace evade::guidance_lcm {

struct NodeSecurity {
  /// Loaded keys (auth::load_into): command keys standby, sensor and telemetry keys active; the
  /// state file then sets the persisted states.
  auth::KeyRing keys;
  /// Persisted key states and command ARSNs (auth::StateFile, AUTH-4). Empty: memory only, for
  /// tests and benches; evade_guidance_node refuses command keys without it.
  std::string state_path;
  /// First start (--auth-init KEY_ID): no state file may exist; key init_active_key becomes the
  /// active command key and every command ARSN starts at init_arsn_floor. 0: start from the file.
  std::int32_t init_active_key = 0;
  std::int64_t init_arsn_floor = 0;
  /// Sensor ARSNs must exceed this [us]: the node's start time on CLOCK_REALTIME in the
  /// fixed-rate mode (the simulator signs with ARSN = utime), 0 in lockstep.
  std::int64_t sensor_arsn_floor_us = 0;
};

}  // namespace evade::guidance_lcm
