// `evade sim --lcm URL`: the guidance of a simulation run (sim_command.hpp) in
// evade_guidance_node over LCM (paper 000, Yao & Wang 2012, the law the node runs):
// lockstep exchanges through make_lcm_endpoint, or with realtime the node at its own fixed
// rate through make_realtime_lcm_link. With a sensor key file, nav, angles and the sim clock
// are signed (docs/SECURITY.md AUTH-3).
#pragma once

#include <string>

#include "evade/sim/sim_command.hpp"

namespace evade::lcm_link {

struct SimLcmOptions {
  std::string lcm_url;     ///< LCM URL of the node (empty: LCM's default)
  bool lockstep = true;    ///< wait for the node's command every cycle
  double timeout_s = 5.0;  ///< reply timeout [s]
  bool realtime = false;   ///< truth at wall-clock pace, the node at its own rate
  std::string key_file;    ///< sensor key file (empty: unsigned)
  int key_id = 0;          ///< which sensor key of key_file (0: its only one)
};

/// The run's guidance link: name "lcm" (or "lcm_realtime"), sensors_signed, and the factory
/// of the endpoint or the real-time link (opened when the run starts). Loads the sensor key
/// now: throws std::invalid_argument naming the file when it has no such key.
sim::SimGuidanceLink sim_lcm_guidance(const SimLcmOptions& o);

}  // namespace evade::lcm_link
