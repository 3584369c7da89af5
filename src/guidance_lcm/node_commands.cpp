// The guidance node's command path (docs/SECURITY.md AUTH-2, AUTH-4, ARSN-1, TM-2, KEY-2;
// docs/GUIDANCE_NODE.md PLAN-IN-*): the commands of the inbox in arrival order. Admission (the
// cycle after arrival): the ARSN compared again, the bytes decoded, a plan's freshness, then the
// ARSN committed (a refused command changes nothing). Execution (once the committed ARSN is on
// disk): the plan loaded, the node armed or disarmed, a key activated or retired. Every
// authenticated command is answered with an acknowledgement naming it (node_telemetry.cpp).
// Members of NodeCore (internal/node_core.hpp).
#include <cstring>

#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/guidance_lcm/internal/node_core.hpp"
#include "evade/guidance_lcm/validate.hpp"

namespace evade::guidance_lcm::internal {
namespace {

using Stage = CommandInbox::Stage;
using Ack = evade_cmd_ack_t;

template <typename Msg>
bool decode_exact(const CommandInbox::Slot& s, Msg* m) noexcept {
  const int n = m->decode(s.data.data(), 0, static_cast<int>(s.size));
  return n >= 0 && n == static_cast<int>(s.size);  // wrong type, truncated or trailing bytes
}

std::int16_t detail_of(guidance::PlanReject r) noexcept { return static_cast<std::int16_t>(r); }

}  // namespace

// Pass 1 admits what arrived since the last cycle; pass 2 executes, in arrival order, what is on
// disk, and refuses what a failed write left behind (AUTH-4: commands take effect only once
// their ARSN is on disk).
void NodeCore::process_commands(std::int64_t now_us) noexcept {
  for (std::size_t i = 0; i < cmd_inbox_.size(); ++i) {
    CommandInbox::Slot& s = cmd_inbox_.at(i);
    if (s.stage == Stage::kReceived) admit_command(s, now_us);
  }
  if (state_file_ == nullptr) persisted_epoch_ = auth_epoch_;  // memory only: nothing to wait for
  for (std::size_t i = 0; i < cmd_inbox_.size(); ++i) {
    CommandInbox::Slot& s = cmd_inbox_.at(i);
    if (s.stage != Stage::kAdmitted) continue;
    if (s.epoch > persisted_epoch_) {
      if (!(persist_failed_ && s.epoch <= failed_epoch_)) break;  // waits for the next write
      refuse(s, Verdict::kRejected, Reason::kNotPersisted, 0, now_us);
      continue;
    }
    execute_command(s, now_us);
  }
  if (persist_failed_) fail_waiting_acks();
  persist_failed_ = false;
  cmd_inbox_.compact();
}

// Decodes the slot into its type's buffer. False (counted and answered) when it does not.
bool NodeCore::decode_command(CommandInbox::Slot& s) noexcept {
  switch (s.input) {
    case Input::kPlan: return decode_exact(s, &plan_msg_);
    case Input::kArm: return decode_exact(s, &arm_msg_);
    case Input::kConjunction: return decode_exact(s, &conj_msg_);
    case Input::kCamDecision: return decode_exact(s, &decision_msg_);
    default: return decode_exact(s, &key_msg_);  // the inbox holds only command rows
  }
}

void NodeCore::admit_command(CommandInbox::Slot& s, std::int64_t now_us) noexcept {
  if (s.authenticated && !(s.arsn > keys_.last_arsn(s.key_id, auth::ArsnSlot::kCommand))) {
    refuse(s, Verdict::kReplayed, Reason::kReplayedArsn, 0, now_us);  // a reordered copy
    return;
  }
  if (!decode_command(s)) {
    refuse(s, Verdict::kRejected, Reason::kDecodeFailed, 0, now_us);
    return;
  }
  // A plan's burn times are absolute in the node's time base: a plan stamped in the node's
  // future comes from a ground clock that is ahead, and its times would be wrong (refused, the
  // ARSN not advanced); so are a conjunction's (TCA, burn window, veto deadline). Arm, disarm,
  // key commands and the ground's decisions carry no such times: they are ordered by their ARSN
  // alone, so a ground with a wrong clock can still disarm or veto (issue 40, row 9).
  const std::int64_t stamped = s.input == Input::kPlan          ? plan_msg_.utime
                               : s.input == Input::kConjunction ? conj_msg_.utime
                                                                : now_us;
  if (stamped > now_us + future_us_) {
    refuse(s, Verdict::kRejected, Reason::kFromFuture, 0, now_us);
    return;
  }
  if (!s.authenticated) {  // the policy does not require it: nothing to commit, nobody to answer
    const bool ok = s.input != Input::kArm || admit_unsigned_arm(now_us);
    s.stage = ok ? Stage::kAdmitted : Stage::kDone;  // epoch 0: nothing to wait for
    return;
  }
  (void)keys_.commit(s.key_id, auth::ArsnSlot::kCommand, s.arsn);  // compared above: advances
  last_command_key_ = s.key_id;
  s.epoch = ++auth_epoch_;  // the state on disk must catch up before this command takes effect
  s.stage = Stage::kAdmitted;
}

// An arm the policy lets through unsigned is ordered like every input: not from the future, not
// stale, its seq after the last one (NODE-IN-2..4). Counted when refused.
bool NodeCore::admit_unsigned_arm(std::int64_t now_us) noexcept {
  if (arm_msg_.utime > now_us + future_us_) {
    counts_.add(Verdict::kRejected, Reason::kFromFuture);
    return false;
  }
  if (arm_msg_.utime < now_us - stale_us_) {
    counts_.add(Verdict::kStale, Reason::kStaleUtime);
    return false;
  }
  return admit_seq(Input::kArm, arm_msg_.seq, arm_msg_.utime);
}

void NodeCore::execute_command(CommandInbox::Slot& s, std::int64_t now_us) noexcept {
  // KEY-2: a key retired by a command executed just before (received in the same drain) no
  // longer commands, although its message was authentic when it arrived.
  const auth::KeyEntry* signer = s.authenticated ? keys_.find(s.key_id) : nullptr;
  if (signer != nullptr && signer->state != auth::KeyState::kActive) {
    refuse(s, Verdict::kAuthFailed,
           signer->state == auth::KeyState::kRetired ? Reason::kRetiredKey : Reason::kStandbyKey,
           0, now_us);
    return;
  }
  if (!decode_command(s)) {  // decoded at admission: the same bytes decode again
    refuse(s, Verdict::kRejected, Reason::kDecodeFailed, 0, now_us);
    return;
  }
  switch (s.input) {
    case Input::kPlan: execute_plan(s, now_us); break;
    case Input::kArm: execute_arm(s, now_us); break;
    case Input::kConjunction: execute_conjunction(s, now_us); break;
    case Input::kCamDecision: execute_decision(s, now_us); break;
    default: execute_key_cmd(s, now_us); break;
  }
  s.stage = Stage::kDone;
}

// One plan: the very plan in force sent again (a retransmission whose first copy was accepted)
// changes nothing and is answered as such; anything else goes through the message edge and the
// executor's validation. Every plan ends consumed (accepted), rejected, or stale (plan id not
// newer, or the plan in force again).
void NodeCore::execute_plan(CommandInbox::Slot& s, std::int64_t now_us) noexcept {
  const std::size_t body = s.size - (s.authenticated ? auth::kTrailerBytes : 0U);
  if (plan_in_force_size_ == s.size && plan_msg_.seq == plan_exec_.status().plan_id &&
      std::memcmp(plan_in_force_.data(), s.data.data(), body) == 0) {
    counts_.add(Verdict::kStale, Reason::kDuplicateSeq);
    ack(s, Ack::OUTCOME_ALREADY_IN_FORCE, Reason::kOk, 0, 0, now_us);
    return;
  }
  guidance::PlanReject r = burn_plan_message_reject(plan_msg_);
  if (r != guidance::PlanReject::kNone) {
    plan_exec_.count_rejection(r);
  } else if (from_lcm(plan_msg_, &plan_)) {
    r = plan_exec_.load(plan_, now_us, armed_, law_.status().dv_used_mps);
  }
  plan_ack_id_ = plan_msg_.seq;
  plan_ack_result_ = static_cast<std::int8_t>(r);  // PlanReject codes are the PLAN_REJECT_* values
  if (r == guidance::PlanReject::kNone) {
    std::memcpy(plan_in_force_.data(), s.data.data(), s.size);
    plan_in_force_size_ = s.size;
    counts_.add(Verdict::kConsumed);
    ack(s, Ack::OUTCOME_ACCEPTED, Reason::kOk, 0, 0, now_us);
    return;
  }
  const Reason why = r == guidance::PlanReject::kNotNewer    ? Reason::kOutOfOrderSeq
                     : r == guidance::PlanReject::kNotFinite ? Reason::kNotFinite
                                                             : Reason::kOutOfRange;
  counts_.add(r == guidance::PlanReject::kNotNewer ? Verdict::kStale : Verdict::kRejected, why);
  ack(s, Ack::OUTCOME_REFUSED, why, detail_of(r), 0, now_us);
}

void NodeCore::execute_arm(CommandInbox::Slot& s, std::int64_t now_us) noexcept {
  armed_ = arm_msg_.armed != 0;
  counts_.add(Verdict::kConsumed);
  ack(s, Ack::OUTCOME_ACCEPTED, Reason::kOk, 0, 0, now_us);
}

// KEY-2: activate or retire a key. The key command's own signer was checked at receipt. A change
// of a key's state is answered once it is on disk (its acknowledgement waits for the next write).
void NodeCore::execute_key_cmd(CommandInbox::Slot& s, std::int64_t now_us) noexcept {
  key_cmd_last_seq_ = key_msg_.seq;
  if (validate(key_msg_) != Reason::kOk) {
    key_cmd_last_result_ = auth::KeyCmdResult::kBadOp;
    counts_.add(Verdict::kRejected, Reason::kOutOfRange);
    ack(s, Ack::OUTCOME_REFUSED, Reason::kOutOfRange,
        static_cast<std::int16_t>(key_cmd_last_result_), 0, now_us);
    return;
  }
  key_cmd_last_result_ = key_msg_.op == evade_key_cmd_t::OP_ACTIVATE ? keys_.activate(key_msg_.key_id)
                                                                     : keys_.retire(key_msg_.key_id);
  const auto detail = static_cast<std::int16_t>(key_cmd_last_result_);
  if (key_cmd_last_result_ != auth::KeyCmdResult::kDone) {
    counts_.add(Verdict::kRejected, Reason::kOutOfRange);
    ack(s, Ack::OUTCOME_REFUSED, Reason::kOutOfRange, detail, 0, now_us);
    return;
  }
  counts_.add(Verdict::kConsumed);
  ack(s, Ack::OUTCOME_ACCEPTED, Reason::kOk, detail, keys_.dirty() ? ++auth_epoch_ : 0, now_us);
}

void NodeCore::refuse(CommandInbox::Slot& s, Verdict v, Reason r, std::int16_t detail,
                      std::int64_t now_us) noexcept {
  counts_.add(v, r);
  ack(s, Ack::OUTCOME_REFUSED, r, detail, 0, now_us);
  s.stage = Stage::kDone;
}

}  // namespace evade::guidance_lcm::internal
