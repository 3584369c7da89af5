// The avoidance planner's burn (cam_planner.hpp) as a BurnPlan (core/burn_plan.hpp) the
// guidance node can execute: one impulse at the plan's epoch (t_s = 0; the publisher stamps
// the epoch with the burn's UTC), Δv in RSW (= the primary's RTN) and in ECI (the planner
// has the inertial state), source PlanSource::kCollisionAvoidance.
#pragma once

#include <cstdint>

#include "evade/cam/cam_planner.hpp"
#include "evade/core/burn_plan.hpp"

namespace evade::cam {

/// plan_id: the publisher's plan number. Throws std::invalid_argument when the plan has no
/// burn (maneuver_needed false) or a non-finite Δv.
BurnPlan make_cam_burn_plan(const CamPlan& plan, std::int64_t plan_id);

/// Microseconds since the Unix epoch of an instant given in seconds since J2000 (UTC, no leap
/// seconds, as core/epoch.hpp).
std::int64_t unix_utime_from_j2000(double t_j2000_s);

}  // namespace evade::cam
