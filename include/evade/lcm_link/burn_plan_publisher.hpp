// Publishing a BurnPlan (core/burn_plan.hpp) as evade_burn_plan_t on LCM: encode with
// guidance_lcm::to_lcm, stamp with the wall clock, send. For the ground side (the `evade`
// planners); flight code decodes with guidance_lcm::from_lcm and does not link this.
#pragma once

#include <cstdint>
#include <string>

#include <lcm/lcm.h>

#include "evade/core/burn_plan.hpp"

namespace evade::lcm_link {

/// Publishes plan on channel through lcm (an open LCM instance; memq:// delivers only within
/// one instance, so an in-process receiver must share it), with the given seq and utime = now
/// (CLOCK_REALTIME, µs since the Unix epoch). Returns that utime. Throws std::invalid_argument
/// on a null lcm, an empty channel or a plan the message cannot carry (to_lcm: e.g. more
/// than one impulse), std::runtime_error naming the channel when LCM fails to send.
std::int64_t publish_burn_plan(lcm_t* lcm, const std::string& channel, const BurnPlan& plan,
                               std::int64_t seq);

/// Same on a new LCM instance for lcm_url (empty: LCM_DEFAULT_URL or LCM's default), closed
/// before returning. Throws std::runtime_error naming the URL when it cannot be opened.
std::int64_t publish_burn_plan(const std::string& lcm_url, const std::string& channel,
                               const BurnPlan& plan, std::int64_t seq);

}  // namespace evade::lcm_link
