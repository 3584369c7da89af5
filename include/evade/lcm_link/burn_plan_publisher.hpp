// Publishing a BurnPlan (core/burn_plan.hpp) as evade_burn_plan_t on LCM: encode with
// guidance_lcm::to_lcm, stamp, send. For the ground side (the `evade` planners, the
// simulator's --plan); flight code decodes with guidance_lcm::from_lcm and does not link this.
#pragma once

#include <cstdint>
#include <string>

#include <lcm/lcm.h>

#include "evade/core/burn_plan.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "evade/guidance_lcm/signed_encode.hpp"

namespace evade::lcm_link {

/// Time stamps, frame and (optionally) the signing key of a published plan. One message, no
/// acknowledgement: the acknowledged uplink is command_uplink.hpp's uplink_plan.
struct PlanStamp {
  std::int64_t utime = 0;        ///< message utime [us]; 0: now (CLOCK_REALTIME)
  std::int64_t epoch_utime = 0;  ///< utime of the plan's t = 0 [us]; 0: the message utime
  guidance::PlanFrame frame = guidance::PlanFrame::kRsw;  ///< frame the node flies
  guidance_lcm::SigningKey key{};  ///< id != 0: sign with this command key (docs/SECURITY.md)
  std::int64_t arsn = 0;           ///< with key: the ARSN (> 0: the ground's counter, ARSN-2)
};

/// Publishes plan on channel through lcm (an open LCM instance; memq:// delivers only within
/// one instance, so an in-process receiver must share it), with the given seq and stamp.
/// Returns the message utime. Throws std::invalid_argument on a null lcm, an empty channel or
/// a plan the message cannot carry (to_lcm: e.g. more than 8 impulses), std::runtime_error
/// naming the channel when LCM fails to send.
std::int64_t publish_burn_plan(lcm_t* lcm, const std::string& channel, const BurnPlan& plan,
                               std::int64_t seq, const PlanStamp& stamp);
/// Same with the default stamp (utime = epoch = now, frame RSW).
std::int64_t publish_burn_plan(lcm_t* lcm, const std::string& channel, const BurnPlan& plan,
                               std::int64_t seq);

/// Same on a new LCM instance for lcm_url (empty: LCM_DEFAULT_URL or LCM's default), closed
/// before returning. Throws std::runtime_error naming the URL when it cannot be opened.
std::int64_t publish_burn_plan(const std::string& lcm_url, const std::string& channel,
                               const BurnPlan& plan, std::int64_t seq,
                               const PlanStamp& stamp = PlanStamp{});

}  // namespace evade::lcm_link
