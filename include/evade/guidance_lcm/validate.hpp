// Field validation of received LCM messages at the node's edge (docs/GUIDANCE_NODE.md NODE-IN-2):
// NaN survives LCM encoding and the generated decode checks only the type fingerprint and
// the length, so every numeric field is checked here before anything reaches the law.
#pragma once

#include <cstdint>

#include "evade/evade_angles_t.hpp"
#include "evade/evade_arm_t.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/evade_sim_clock_t.hpp"
#include "evade/evade_thrust_cmd_t.hpp"
#include "evade/guidance_lcm/input_accounting.hpp"

namespace evade::guidance_lcm {

/// Allowed ranges (inclusive) of the fields the law does not see; a measurement's own
/// limits are guidance::MeasurementLimits.
struct Limits {
  static constexpr double kMaxPositionM = 1.0e9;
  static constexpr double kMaxVelocityMps = 1.0e5;
  static constexpr double kUnitTolerance = 1e-6;                  // | |u| - 1 |
  static constexpr double kMaxAccelMps2 = 1.0e3;
  /// Latest sim-clock tick utime [µs] (31,700 years after 1970): a lockstep cycle's time
  /// plus or minus the node's tolerances stays far inside int64 (found by fuzzing a tick at
  /// INT64_MAX: the future-utime check overflowed).
  static constexpr std::int64_t kMaxTickUtimeUs = 1000000000000000000;
};

/// Each returns Reason::kOk or why the message must be rejected. No allocation, no throw.
Reason validate(const evade_angles_t& m) noexcept;
Reason validate(const evade_nav_state_t& m) noexcept;
Reason validate(const evade_arm_t& m) noexcept;
/// A key command: op OP_ACTIVATE or OP_RETIRE and a key id > 0.
Reason validate(const evade_key_cmd_t& m) noexcept;
Reason validate(const evade_sim_clock_t& m) noexcept;
/// A command: mode in range, accel finite and >= 0, |u| = 1 when accel > 0 (u = 0 allowed
/// with accel = 0). Used by the simulator side of the link.
Reason validate(const evade_thrust_cmd_t& m) noexcept;

}  // namespace evade::guidance_lcm
