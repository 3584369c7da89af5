// Conversions between the LCM messages and the guidance law's plain structs
// (docs/GUIDANCE_NODE.md NODE-IF-2). Bit-exact for every double, so a lockstep run over LCM
// computes exactly what the in-process run computes. Call validate() (validate.hpp) on a
// received message before converting it. No allocation, no throw.
#pragma once

#include <cstdint>

#include "evade/evade_angles_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/evade_thrust_cmd_t.hpp"
#include "evade/guidance/guidance_law.hpp"
#include "evade/guidance/plan_executor.hpp"

namespace evade::guidance_lcm {

/// An LCM `boolean` field (lcm-gen declares it int8_t, 0 or 1) from a bool, without the
/// implicit bool -> signed char conversion.
constexpr std::int8_t lcm_bool(bool b) noexcept { return b ? std::int8_t{1} : std::int8_t{0}; }

void from_lcm(const evade_angles_t& m, guidance::AnglesMeasurement* out) noexcept;
void from_lcm(const evade_nav_state_t& m, guidance::NavState* out) noexcept;
void from_lcm(const evade_thrust_cmd_t& m, guidance::ThrustCommand* out) noexcept;
/// Fills the guidance-law part of GuidanceStatus (the node's counters have no place there).
void from_lcm(const evade_guidance_status_t& m, guidance::GuidanceStatus* out) noexcept;

/// seq is the transport sequence number (+1 per message on the channel).
void to_lcm(const guidance::AnglesMeasurement& a, std::int64_t seq, evade_angles_t* out) noexcept;
void to_lcm(const guidance::NavState& n, std::int64_t seq, evade_nav_state_t* out) noexcept;
/// input_utime: utime of the newest measurement used (-1 if none).
void to_lcm(const guidance::ThrustCommand& c, std::int64_t seq, std::int64_t input_utime,
            evade_thrust_cmd_t* out) noexcept;
/// Fills the guidance-law part of the status message; node counters are set by the node.
void to_lcm(const guidance::GuidanceStatus& s, evade_guidance_status_t* out) noexcept;
/// Fills the plan_* fields of *out from the plan executor's status (the rest unchanged).
void to_lcm(const guidance::PlanExecStatus& s, evade_guidance_status_t* out) noexcept;

}  // namespace evade::guidance_lcm
