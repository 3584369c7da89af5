// The ground's side of the authenticated command link (docs/SECURITY.md UPLINK-*, TM-*,
// ARSN-*): sign a command with a command key and the next ARSN of the ground's own counter
// (auth::ArsnCounter beside the key file: a persisted counter, never a clock), send it, and,
// like the sender of CCSDS COP-1 (232.1-B-2), send it again — signed afresh with the next ARSN —
// until the node answers or a timeout. The answer is the node's evade_cmd_ack_t, signed with
// the node's telemetry key and naming the exact transmission (its key id, ARSN and MAC): the
// ground acts on nothing else, and counts what it ignores (unsigned or forged telemetry, answers
// to other commands). An answer that the ARSN was a replay, from a node whose last accepted ARSN
// of the key is not one of ours, means the ground's counter is behind (a lost or restored
// counter file): the counter is raised above the node's and the command sent again, at most
// kMaxArsnRecoveries times. The signed status (its per-key ARSNs) raises it too.
// Ground code: allocates, throws std::invalid_argument / std::runtime_error.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "evade/auth/keyring.hpp"
#include "evade/autonomy/conjunction_event.hpp"
#include "evade/autonomy/responder.hpp"
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

/// The ground's ARSNs of its command key. The CLI's is auth::ArsnCounter (persisted beside the
/// key file, written before each transmission); tests may keep one in memory.
class ArsnSource {
 public:
  virtual ~ArsnSource() = default;
  /// The next ARSN, durable before it is returned.
  virtual std::int64_t next() = 0;
  /// The counter raised to at least floor (the next ARSN is above it).
  virtual void raise_to(std::int64_t floor) = 0;
  virtual std::int64_t last() const = 0;
};

/// What a ground command signs with and verifies with.
struct GroundKeys {
  guidance_lcm::SigningKey command;    ///< signs the command
  guidance_lcm::SigningKey telemetry;  ///< verifies the node's acknowledgements and status
};

struct UplinkOptions {
  std::string lcm_url;                  ///< empty: LCM_DEFAULT_URL or LCM's default
  std::string status_channel = "EVADE_GUID_STATUS";
  std::string ack_channel = "EVADE_CMD_ACK";
  std::string proposal_channel = "EVADE_CAM_PROPOSAL";  ///< the node's signed conjunction decisions
  double timeout_s = 5.0;               ///< give up after this long without an acknowledgement
  double retransmit_s = 0.25;           ///< send again after this long without one
  /// The node's time base for the utime the command is stamped with (a conjunction is refused
  /// when stamped in the node's future); empty: CLOCK_REALTIME, the node's clock in flight. A
  /// lockstep run gives the simulator's tick time (`evade cam hil`).
  std::function<std::int64_t()> clock_utime;
};

inline constexpr int kMaxArsnRecoveries = 3;

enum class AckOutcome : std::uint8_t { kAccepted = 0, kRejected = 1, kTimeout = 2 };

struct UplinkResult {
  AckOutcome outcome = AckOutcome::kTimeout;
  int code = 0;              ///< the node's REASON_* (evade_cmd_ack_t); 0 accepted
  int detail = 0;            ///< plans: PLAN_REJECT_*; key commands: KEY_CMD_*; CONJ_*, DECIDE_*
  std::string reason;        ///< "accepted", "already in force", "burn_in_past", "replayed_arsn", ...
  std::string note;          ///< what to do about it, when there is something ("" otherwise)
  int transmissions = 0;     ///< messages sent
  double ack_s = 0.0;        ///< from the first transmission to the acknowledgement [s]
  std::int64_t first_utime = 0;  ///< utime of the first transmission [us]
  std::int64_t plan_id = 0;  ///< plans: the id sent; the ack's plan in force for the others
  std::int64_t proposal_id = 0;  ///< decisions: the node's proposal the decision names (0: none)
  std::int64_t arsn = 0;     ///< the ARSN of the transmission the node answered (0: none)
  std::int64_t node_arsn = 0;  ///< the node's last accepted ARSN of the key, from its answer
  int arsn_recoveries = 0;   ///< times the counter was raised above the node's and resent
  int acks_verified = 0;     ///< acknowledgements that verified under the telemetry key
  int status_verified = 0;   ///< status messages that verified
  int ignored = 0;           ///< telemetry refused: unsigned, another key, a bad MAC, undecodable
  int unmatched = 0;         ///< verified acknowledgements of commands this uplink did not send
};

/// CLI exit code of an outcome: 0 accepted, 3 rejected with a named reason, 4 timeout.
int exit_code(const UplinkResult& r) noexcept;
const char* outcome_name(AckOutcome o) noexcept;

/// The JSON of an uplink's outcome, as `evade arm`, `evade key` and `evade plan ... --publish
/// --key` print it.
nlohmann::json to_json(const UplinkResult& r, std::int32_t key_id);

/// Uplinks plan as evade_burn_plan_t with id seq (0: one above the plan the node's verified
/// status shows in force) on channel, until the node answers that transmission.
UplinkResult uplink_plan(const UplinkOptions& o, const std::string& channel, const BurnPlan& plan,
                         std::int64_t seq, const PlanStamp& stamp, const GroundKeys& keys,
                         ArsnSource* arsn);

/// Sends evade_arm_t (armed or disarmed) on EVADE_ARM until the node answers it.
UplinkResult uplink_arm(const UplinkOptions& o, bool armed, const GroundKeys& keys,
                        ArsnSource* arsn);

/// Sends evade_key_cmd_t (op OP_ACTIVATE or OP_RETIRE on target_key_id) on EVADE_KEY_CMD until
/// the node answers it.
UplinkResult uplink_key_cmd(const UplinkOptions& o, std::int8_t op, std::int32_t target_key_id,
                            const GroundKeys& keys, ArsnSource* arsn);

/// Sends the conjunction e as evade_conjunction_t on EVADE_CONJUNCTION until the node answers
/// it (docs/AUTONOMY.md AUT-1): "accepted" when tracked or replacing an older version, "already
/// in force" for the very event tracked, else the CONJ_* reason ("not_newer", "table_full", ...).
UplinkResult uplink_conjunction(const UplinkOptions& o, const autonomy::ConjunctionEvent& e,
                                const GroundKeys& keys, ArsnSource* arsn);

/// Sends the decision d as evade_cam_decision_t on EVADE_CAM_DECISION until the node answers it
/// (AUT-7). A veto or an approval with proposal_id 0 names the proposal of the node's newest
/// verified evade_cam_proposal_t of the event, waited for within the timeout; when none comes,
/// or it proposes nothing, nothing is sent and the result says why (outcome kTimeout, reason
/// "no verified proposal", or kRejected "no_proposal" with the node's state in the note).
UplinkResult uplink_cam_decision(const UplinkOptions& o, autonomy::DecisionCommand d,
                                 const GroundKeys& keys, ArsnSource* arsn);

}  // namespace evade::lcm_link
