// Signed commands with acknowledgement and retransmission (include/evade/lcm_link/
// command_uplink.hpp): the keys, the plan, arm and key commands, and the outcome's JSON; the
// transmissions and answers are the session's (internal/uplink_session.hpp).
#include "evade/lcm_link/command_uplink.hpp"

#include <memory>
#include <stdexcept>
#include <vector>

#include "evade/auth/key_file.hpp"
#include "evade/evade_arm_t.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/lcm_link/internal/uplink_session.hpp"

namespace evade::lcm_link {

guidance_lcm::SigningKey load_command_key(const std::string& key_file, std::int32_t key_id) {
  return load_signing_key(key_file, key_id, auth::KeyRole::kCommand);
}

guidance_lcm::SigningKey load_signing_key(const std::string& key_file, std::int32_t key_id,
                                          auth::KeyRole role) {
  std::vector<auth::KeyRecord> keys;
  try {
    keys = auth::read_key_file(key_file);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // a refused key file is bad input (exit 2)
  }
  const auth::KeyRecord* pick = nullptr;
  int n_role = 0;
  for (const auth::KeyRecord& k : keys) {
    if (k.role != role) continue;
    ++n_role;
    if (key_id == 0 || k.id == key_id) pick = &k;
  }
  const std::string role_text = auth::role_name(role);
  if (pick == nullptr || (key_id == 0 && n_role > 1)) {
    throw std::invalid_argument("key file '" + key_file + "': " +
                             (key_id == 0 ? "holds no single " + role_text + " key; give --key-id"
                                          : "no " + role_text + " key with id " + std::to_string(key_id)));
  }
  guidance_lcm::SigningKey k;
  k.id = pick->id;
  k.key = pick->key;
  for (auth::KeyRecord& r : keys) auth::wipe(r.key.data(), r.key.size());
  return k;
}

int exit_code(const UplinkResult& r) noexcept {
  switch (r.outcome) {
    case AckOutcome::kAccepted: return 0;
    case AckOutcome::kRejected: return 3;
    case AckOutcome::kTimeout: break;
  }
  return 4;
}

const char* outcome_name(AckOutcome o) noexcept {
  switch (o) {
    case AckOutcome::kAccepted: return "accepted";
    case AckOutcome::kRejected: return "rejected";
    case AckOutcome::kTimeout: break;
  }
  return "timeout";
}

UplinkResult uplink_plan(const UplinkOptions& o, const std::string& channel, const BurnPlan& plan,
                         std::int64_t seq, const PlanStamp& stamp, const GroundKeys& keys,
                         ArsnSource* arsn) {
  if (channel.empty()) throw std::invalid_argument("uplink_plan: channel is empty");
  UplinkSession up(o, keys, arsn);
  if (seq == 0) {  // one above the plan in force, from the node's verified status
    evade_guidance_status_t s{};
    if (!up.wait_status(&s)) {
      UplinkResult r;
      r.reason = "no verified status";
      r.note = "no status verified under telemetry key " + std::to_string(keys.telemetry.id) +
               " to take the next plan id from; give --seq N";
      return r;
    }
    seq = s.plan_id + 1;
  }
  const std::int64_t utime = stamp.utime != 0 ? stamp.utime : uplink_realtime_us();
  evade_burn_plan_t m{};
  guidance_lcm::to_lcm(plan, utime, seq, stamp.epoch_utime != 0 ? stamp.epoch_utime : utime,
                       stamp.frame, &m);
  UplinkResult r = up.run(channel.c_str(), m);
  r.plan_id = seq;
  return r;
}

UplinkResult uplink_arm(const UplinkOptions& o, bool armed, const GroundKeys& keys,
                        ArsnSource* arsn) {
  UplinkSession up(o, keys, arsn);
  evade_arm_t m{};
  m.utime = uplink_realtime_us();  // informational: an arm is ordered by its ARSN (docs/SECURITY.md)
  m.seq = arsn->last() + 1;  // unique per command: the ARSN of its first transmission
  m.armed = armed ? 1 : 0;
  return up.run(guidance_lcm::kChanArm, m);
}

UplinkResult uplink_key_cmd(const UplinkOptions& o, std::int8_t op, std::int32_t target_key_id,
                            const GroundKeys& keys, ArsnSource* arsn) {
  UplinkSession up(o, keys, arsn);
  evade_key_cmd_t m{};
  m.utime = uplink_realtime_us();
  m.seq = arsn->last() + 1;  // unique per command: the ARSN of its first transmission
  m.op = op;
  m.key_id = target_key_id;
  return up.run(guidance_lcm::kChanKeyCmd, m);
}

nlohmann::json to_json(const UplinkResult& r, std::int32_t key_id) {
  nlohmann::json j = {{"outcome", outcome_name(r.outcome)},
                      {"code", r.code},
                      {"detail", r.detail},
                      {"reason", r.reason},
                      {"key_id", key_id},
                      {"transmissions", r.transmissions},
                      {"ack_s", r.outcome == AckOutcome::kTimeout ? nlohmann::json(nullptr)
                                                                  : nlohmann::json(r.ack_s)},
                      {"arsn", r.arsn},
                      {"node_arsn", r.node_arsn},
                      {"arsn_recoveries", r.arsn_recoveries},
                      {"telemetry", {{"acks_verified", r.acks_verified},
                                     {"status_verified", r.status_verified},
                                     {"ignored", r.ignored},
                                     {"unmatched", r.unmatched}}},
                      {"exit_code", exit_code(r)}};
  if (r.proposal_id != 0) j["proposal_id"] = r.proposal_id;
  if (!r.note.empty()) j["note"] = r.note;
  return j;
}

}  // namespace evade::lcm_link
