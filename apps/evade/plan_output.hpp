// What `evade plan observability|threat-area|formation` do with the plan they made (a
// BurnPlan from the planner's library): --publish sends it as evade_burn_plan_t on LCM
// (lcm_link::publish_burn_plan, the same path for every planner); --plan-out writes it as a
// plan file (sim/plan_file.hpp) that `evade sim --plan FILE` flies. Shared options, no domain
// logic.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "evade/core/burn_plan.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "uplink_options.hpp"

namespace evade::cli {

struct PlanOutputOptions {
  bool publish = false;
  std::string lcm_url;                        ///< empty: LCM default (LCM_DEFAULT_URL or udpm)
  std::string channel = "EVADE_BURN_PLAN";
  long seq = 0;                               ///< message seq = plan id
  long long epoch_utime_us = 0;               ///< utime of plan t = 0; 0: the publish time
  std::string frame = "rsw";                  ///< frame the node flies: rsw | eci
  std::string plan_out;                       ///< plan file to write; empty: none
  SigningFlags sign;                          ///< --key (sign, wait for the ack) and its flags
};

/// Adds --publish, --lcm-url, --channel, --seq, --epoch-utime, --frame, --plan-out, --key,
/// --key-id, --ack-timeout-s, --retransmit-s.
void add_plan_output_options(CLI::App& app, PlanOutputOptions& o);

/// True when the options ask for the plan (--publish or --plan-out).
bool plan_wanted(const PlanOutputOptions& o);

/// The plan number the options give (--seq).
std::int64_t plan_id(const PlanOutputOptions& o);

/// With --plan-out: writes the plan file and adds "plan_file" to *j. With --publish:
/// publishes plan and adds "published" (channel, seq, utime, epoch_utime, frame, impulses)
/// to *j; with --key as well, signs it and retransmits until the node acknowledges it
/// (lcm_link::uplink_plan) and adds "uplink" (outcome, reason, transmissions, ack_s). Returns
/// the exit code: 0, or with --key 3 (rejected, reason named) or 4 (no acknowledgement). Throws std::invalid_argument for a plan the file or the message cannot carry (e.g.
/// --frame eci without ECI Δv) or a file that cannot be written, std::runtime_error when LCM
/// fails.
int output_plan(const PlanOutputOptions& o, const BurnPlan& plan, nlohmann::json* j);


}  // namespace evade::cli
