// The guidance node's inputs, one row each (docs/GUIDANCE_NODE.md NODE-IF-1, docs/SECURITY.md
// AUTH-2..5): the channel, the message type, its kind, the anti-replay slot its signer's ARSN
// advances, its bit in the status's auth_required mask, the policy flag that makes it required,
// its verification budget, the largest message accepted on it, and (commands) its code in the
// acknowledgement. The node's subscribe loop, its policy mask, its per-channel verification
// budgets and its accounting iterate this table; adding an input is adding a row here, its
// message type in lcm_types/, and its handler in the node (guidance_lcm/node_*.cpp).
//
// Three kinds, handled apart:
//   sensor   the newest valid message of the cycle feeds the law (older ones superseded);
//   tick     the lockstep clock: one cycle per tick (subscribed only with --lockstep);
//   command  each authenticated message is handled once, in arrival order, takes effect only
//            once its ARSN is on disk, and is acknowledged (evade_cmd_ack_t).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "evade/auth/keyring.hpp"
#include "evade/evade_cmd_ack_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/node_config.hpp"

namespace evade::guidance_lcm {

enum class Input : std::uint8_t {
  kAngles = 0, kNav, kClock, kPlan, kArm, kKeyCmd, kConjunction, kCamDecision, kCount
};
inline constexpr std::size_t kInputCount = static_cast<std::size_t>(Input::kCount);

enum class InputKind : std::uint8_t { kSensor = 0, kTick = 1, kCommand = 2 };

/// Largest sensor or tick message accepted (evade_angles_t encodes to about 120 B).
inline constexpr std::size_t kMaxInputBytes = 256;
/// Largest command accepted (evade_burn_plan_t encodes to 629 B, evade_conjunction_t to 808 B).
inline constexpr std::size_t kMaxCommandBytes = 1024;

struct InputRow {
  Input input;
  const char* name;              ///< the input's name in the stats JSON
  const char* channel;           ///< LCM channel
  const char* type;              ///< LCM type on it
  InputKind kind;
  auth::ArsnSlot slot;           ///< anti-replay slot of its signer
  std::int16_t auth_bit;         ///< evade_guidance_status_t::AUTH_*
  bool AuthPolicy::*required;    ///< policy flag; nullptr: always required (key commands, conjunctions, decisions)
  int AuthPolicy::*verify_budget;  ///< MAC verifications per cycle on this channel
  std::size_t max_bytes;
  std::int8_t ack_command;       ///< evade_cmd_ack_t::COMMAND_* (commands), 0 otherwise
};

inline constexpr std::array<InputRow, kInputCount> kInputRows = {{
    {Input::kAngles, "angles", kChanAngles, "evade_angles_t", InputKind::kSensor,
     auth::ArsnSlot::kAngles, evade_guidance_status_t::AUTH_ANGLES, &AuthPolicy::angles_required,
     &AuthPolicy::verify_per_cycle_sensor, kMaxInputBytes, 0},
    {Input::kNav, "nav", kChanNav, "evade_nav_state_t", InputKind::kSensor, auth::ArsnSlot::kNav,
     evade_guidance_status_t::AUTH_NAV, &AuthPolicy::nav_required, &AuthPolicy::verify_per_cycle_sensor,
     kMaxInputBytes, 0},
    {Input::kClock, "clock", kChanClock, "evade_sim_clock_t", InputKind::kTick,
     auth::ArsnSlot::kClock, evade_guidance_status_t::AUTH_CLOCK, &AuthPolicy::clock_required,
     &AuthPolicy::verify_per_cycle_sensor, kMaxInputBytes, 0},
    {Input::kPlan, "plan", kChanPlan, "evade_burn_plan_t", InputKind::kCommand,
     auth::ArsnSlot::kCommand, evade_guidance_status_t::AUTH_PLAN, &AuthPolicy::plan_required,
     &AuthPolicy::verify_per_cycle_command, kMaxCommandBytes, evade_cmd_ack_t::COMMAND_PLAN},
    {Input::kArm, "arm", kChanArm, "evade_arm_t", InputKind::kCommand, auth::ArsnSlot::kCommand,
     evade_guidance_status_t::AUTH_ARM, &AuthPolicy::arm_required, &AuthPolicy::verify_per_cycle_command,
     kMaxCommandBytes, evade_cmd_ack_t::COMMAND_ARM},
    {Input::kKeyCmd, "key_cmd", kChanKeyCmd, "evade_key_cmd_t", InputKind::kCommand,
     auth::ArsnSlot::kCommand, evade_guidance_status_t::AUTH_KEY_CMD, nullptr, &AuthPolicy::verify_per_cycle_command,
     kMaxCommandBytes, evade_cmd_ack_t::COMMAND_KEY_CMD},
    {Input::kConjunction, "conjunction", kChanConjunction, "evade_conjunction_t", InputKind::kCommand,
     auth::ArsnSlot::kCommand, evade_guidance_status_t::AUTH_CONJUNCTION, nullptr,
     &AuthPolicy::verify_per_cycle_command, kMaxCommandBytes, evade_cmd_ack_t::COMMAND_CONJUNCTION},
    {Input::kCamDecision, "cam_decision", kChanCamDecision, "evade_cam_decision_t", InputKind::kCommand,
     auth::ArsnSlot::kCommand, evade_guidance_status_t::AUTH_CAM_DECISION, nullptr,
     &AuthPolicy::verify_per_cycle_command, kMaxCommandBytes, evade_cmd_ack_t::COMMAND_CAM_DECISION},
}};

constexpr const InputRow& input_row(Input in) noexcept {
  return kInputRows[static_cast<std::size_t>(in)];
}

/// True when the policy requires the input to be signed.
inline bool input_required(const InputRow& row, const AuthPolicy& p) noexcept {
  return row.required == nullptr || p.*row.required;
}

/// The status's auth_required mask of a policy: the bits of every required input.
inline std::int16_t auth_required_mask(const AuthPolicy& p) noexcept {
  int m = 0;
  for (const InputRow& row : kInputRows) {
    if (input_required(row, p)) m |= row.auth_bit;
  }
  return static_cast<std::int16_t>(m);  // eight bits: fits in int16
}

}  // namespace evade::guidance_lcm
