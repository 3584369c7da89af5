// The guidance node's configuration (public: a flight-software integrator sets it; the node
// itself is guidance_node.hpp).
#pragma once

#include <string>

#include "evade/autonomy/response.hpp"
#include "evade/guidance/guidance_law.hpp"

namespace evade::guidance_lcm {

/// Which input channels must carry a valid security trailer (docs/SECURITY.md AUTH-2):
/// commands by default, sensors off (on a spacecraft they come over a trusted onboard bus; on a
/// shared HIL network set them required and sign them in the simulator). Key commands
/// (evade_key_cmd_t) are always required: there is no parameter to turn that off. The MAC
/// verifications of a cycle are bounded per channel (AUTH-5): a flood on one channel spends only
/// that channel's budget, so no sensor or forged flood can drop a genuine command.
struct AuthPolicy {
  bool plan_required = true;
  bool arm_required = true;
  bool nav_required = false;
  bool angles_required = false;
  bool clock_required = false;
  int verify_per_cycle_command = 512;  ///< per command channel (plan, arm, key command)
  int verify_per_cycle_sensor = 256;   ///< per sensor channel (nav, angles, sim clock)
};

/// Defaults here; unit, range and meaning in node_params.hpp. The staleness limit (edge,
/// law and watchdog) is the law's guidance.stale_limit_s: one knob.
struct NodeConfig {
  guidance::GuidanceConfig guidance;  ///< the law's parameters (validated by the law)
  double future_tolerance_s = 0.05;
  int queue_capacity = 16;
  int max_drain_per_cycle = 4096;
  double max_drain_s = 0.010;  ///< wall time one drain may take (bounds the cycle under a flood)
  int status_divider = 1;
  int max_seq_jump = 1000;
  int recv_buf_bytes = 8 * 1024 * 1024;  ///< udpm kernel receive buffer requested (NODE-IN-6)
  bool lockstep = false; ///< subscribe to the sim clock
  AuthPolicy auth;
  /// The onboard conjunction response (docs/AUTONOMY.md AUT-7): its policy at start
  /// (--autonomy off|veto|approve; the ground's evade_cam_decision_t changes it) and its
  /// settings (node.autonomy.*, autonomy::responder_params).
  autonomy::Policy autonomy = autonomy::Policy::kVeto;
  autonomy::ResponderConfig response;

  /// Empty when valid, else the parameter tables' error text (node.*, node.autonomy.*, then
  /// guidance.*).
  std::string validate() const;
};

}  // namespace evade::guidance_lcm
