// The ground's side of the authenticated command link (docs/SECURITY.md UPLINK-*): sign a
// command with a command key, send it, and, like the sender of CCSDS COP-1 (232.1-B-2), send
// it again until the node's status acknowledges it or a timeout. Each transmission is signed
// afresh with the next ARSN of the sender's clock (guidance_lcm::ArsnClock), so a copy the
// node already accepted is never mistaken for a replay and a copy lost on the way is made up
// by the next. The acknowledgement is read from evade_guidance_status_t: plan_ack_id /
// plan_ack_result for plans, armed for arm/disarm, key_cmd_last_seq / key_cmd_last_result for
// key commands. Ground code: allocates, throws std::invalid_argument / std::runtime_error.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "evade/auth/keyring.hpp"
#include "evade/core/burn_plan.hpp"
#include "evade/guidance_lcm/signed_encode.hpp"
#include "evade/lcm_link/burn_plan_publisher.hpp"

namespace evade::lcm_link {

/// The key of role in key_file: the one with key_id, or (key_id 0) its only key of that role.
/// Throws std::invalid_argument naming the file (never a key byte) when there is no such key
/// or the file is refused (auth::read_key_file).
guidance_lcm::SigningKey load_signing_key(const std::string& key_file, std::int32_t key_id,
                                          auth::KeyRole role);
/// load_signing_key for a command key.
guidance_lcm::SigningKey load_command_key(const std::string& key_file, std::int32_t key_id);

struct UplinkOptions {
  std::string lcm_url;                  ///< empty: LCM_DEFAULT_URL or LCM's default
  std::string status_channel = "EVADE_GUID_STATUS";
  double timeout_s = 5.0;               ///< give up after this long without an acknowledgement
  double retransmit_s = 0.25;           ///< send again after this long without one
};

enum class AckOutcome : std::uint8_t { kAccepted = 0, kRejected = 1, kTimeout = 2 };

struct UplinkResult {
  AckOutcome outcome = AckOutcome::kTimeout;
  int code = 0;              ///< plans: PLAN_REJECT_* (0 accepted); key commands: KEY_CMD_*
  std::string reason;        ///< the code's name ("accepted", "burn_in_past", "last_key", ...)
  int transmissions = 0;     ///< messages sent
  double ack_s = 0.0;        ///< from the first transmission to the acknowledgement [s]
  std::int64_t first_utime = 0;  ///< utime of the first transmission [us]
};

/// CLI exit code of an outcome: 0 accepted, 3 rejected with a named reason, 4 timeout.
int exit_code(const UplinkResult& r) noexcept;
const char* outcome_name(AckOutcome o) noexcept;

/// The JSON of an uplink's outcome (outcome, code, reason, key_id, transmissions, ack_s: null
/// on a timeout, exit_code), as `evade arm`, `evade key` and `evade plan ... --publish --key`
/// print it.
nlohmann::json to_json(const UplinkResult& r, std::int32_t key_id);

/// Uplinks plan as evade_burn_plan_t with id seq on channel, signed with key, until the node
/// acknowledges plan id seq.
UplinkResult uplink_plan(const UplinkOptions& o, const std::string& channel, const BurnPlan& plan,
                         std::int64_t seq, const PlanStamp& stamp,
                         const guidance_lcm::SigningKey& key);

/// Sends evade_arm_t (armed or disarmed) on EVADE_ARM until the node's status shows it.
UplinkResult uplink_arm(const UplinkOptions& o, bool armed, const guidance_lcm::SigningKey& key);

/// Sends evade_key_cmd_t (op OP_ACTIVATE or OP_RETIRE on target_key_id) on EVADE_KEY_CMD until
/// the node's status acknowledges it (key_cmd_last_seq).
UplinkResult uplink_key_cmd(const UplinkOptions& o, std::int8_t op, std::int32_t target_key_id,
                            const guidance_lcm::SigningKey& key);

}  // namespace evade::lcm_link
