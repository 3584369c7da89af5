// Conversion between evade::BurnPlan (core/burn_plan.hpp) and the evade_burn_plan_t message,
// field by field and bit-exact for every double. The message carries up to
// BurnPlan::kMaxImpulses impulses in fixed arrays (unused entries zero), the plan's epoch
// (utime of t = 0) and the frame the node flies (guidance::PlanFrame). The message has no
// separate plan id: its seq (the publisher's plan number) carries it, so from_lcm sets
// plan_id = seq. |Δv| (impulse_dv_mps) is written as the norm of each impulse's RSW Δv and
// not read back (it is derived).
#pragma once

#include <cstdint>

#include "evade/core/burn_plan.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/guidance/plan_executor.hpp"

namespace evade::guidance_lcm {

/// Fills *out from plan, stamped with utime [us since the Unix epoch] and seq, with the
/// plan's epoch epoch_utime [us] and frame. Throws std::invalid_argument naming the BurnPlan
/// field when the message cannot carry the plan: n_impulses outside 1..kMaxImpulses, an
/// unknown source or objective code, an observability block that does not match the source,
/// a non-finite number, or frame ECI with an impulse lacking its ECI Δv. *out is unchanged then.
void to_lcm(const BurnPlan& plan, std::int64_t utime, std::int64_t seq, std::int64_t epoch_utime,
            guidance::PlanFrame frame, evade_burn_plan_t* out);
/// Same with epoch_utime = utime and frame RSW.
void to_lcm(const BurnPlan& plan, std::int64_t utime, std::int64_t seq, evade_burn_plan_t* out);

/// Why a received message is not a valid plan (the name of the bad field and what is
/// allowed), or nullptr if it is one. No allocation, no throw.
const char* burn_plan_message_error(const evade_burn_plan_t& m) noexcept;
/// The same verdict as the executor's rejection reason (kNone if valid): impulse count,
/// not finite, unknown frame, or malformed (flags and codes).
guidance::PlanReject burn_plan_message_reject(const evade_burn_plan_t& m) noexcept;

/// Fills *out from m (the inverse of to_lcm) if burn_plan_message_error(m) is nullptr and
/// returns true; otherwise returns false and leaves *out unchanged. No allocation, no throw.
bool from_lcm(const evade_burn_plan_t& m, BurnPlan* out) noexcept;
/// Same, with the epoch and the frame (what the executor loads).
bool from_lcm(const evade_burn_plan_t& m, guidance::UplinkedPlan* out) noexcept;

}  // namespace evade::guidance_lcm
