// Conversion between evade::BurnPlan (core/burn_plan.hpp) and the evade_burn_plan_t message,
// field by field and bit-exact for every double. The message carries one impulse today, so a
// plan with any other number of impulses is refused, never cut short. The message has no plan
// id: its seq (the publisher's plan number) carries it, so from_lcm sets plan_id = seq. |Δv|
// (dv_mps) is written as the norm of the impulse's RSW Δv and not read back (it is derived).
#pragma once

#include <cstdint>

#include "evade/core/burn_plan.hpp"
#include "evade/evade_burn_plan_t.hpp"

namespace evade::guidance_lcm {

/// Fills *out from plan, stamped with utime [us since the Unix epoch] and seq. Throws
/// std::invalid_argument naming the BurnPlan field when the message cannot carry the plan:
/// n_impulses != 1, an unknown source or objective code, an observability block that does
/// not match the source, or a non-finite number. *out is unchanged then.
void to_lcm(const BurnPlan& plan, std::int64_t utime, std::int64_t seq, evade_burn_plan_t* out);

/// Why a received message is not a valid plan (the name of the bad field and what is
/// allowed), or nullptr if it is one. No allocation, no throw.
const char* burn_plan_message_error(const evade_burn_plan_t& m) noexcept;

/// Fills *out from m (the inverse of to_lcm) if burn_plan_message_error(m) is nullptr and
/// returns true; otherwise returns false and leaves *out unchanged. No allocation, no throw.
bool from_lcm(const evade_burn_plan_t& m, BurnPlan* out) noexcept;

}  // namespace evade::guidance_lcm
