// The guidance node's command path (docs/SECURITY.md AUTH-*, KEY-*; docs/GUIDANCE_NODE.md
// PLAN-IN-*): authentication of every channel the policy requires, the command inbox, the
// anti-replay state's persistence, and the three commands (burn plan, arm/disarm, key
// command). Members of GuidanceNode (internal/node_core.hpp); the cycle is node_core.cpp.
#include <cmath>

#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/internal/node_core.hpp"
#include "evade/guidance_lcm/validate.hpp"

namespace evade::guidance_lcm {
namespace {

Reason auth_reason(auth::AuthResult r) noexcept {
  switch (r) {
    case auth::AuthResult::kMalformed: return Reason::kTooShortForTrailer;
    case auth::AuthResult::kUnsigned: return Reason::kUnsigned;
    case auth::AuthResult::kUnknownKey: return Reason::kUnknownKey;
    case auth::AuthResult::kBadMac: return Reason::kBadMac;
    case auth::AuthResult::kStandbyKey: return Reason::kStandbyKey;
    case auth::AuthResult::kRetiredKey: return Reason::kRetiredKey;
    case auth::AuthResult::kWrongRole: return Reason::kWrongKeyRole;
    case auth::AuthResult::kReplayed: return Reason::kReplayedArsn;
    case auth::AuthResult::kOk:
    case auth::AuthResult::kCount: break;
  }
  return Reason::kOk;
}

std::int8_t command_bit(int channel) noexcept {
  switch (channel) {
    case kCmdPlan: return evade_guidance_status_t::AUTH_PLAN;
    case kCmdArm: return evade_guidance_status_t::AUTH_ARM;
    default: return evade_guidance_status_t::AUTH_KEY_CMD;
  }
}

const char* command_channel_name(int channel) noexcept {
  switch (channel) {
    case kCmdPlan: return kChanPlan;
    case kCmdArm: return kChanArm;
    default: return kChanKeyCmd;
  }
}

}  // namespace

// AUTH-1..3: the message's trailer, within the cycle's verification budget. Every outcome but
// success is counted here (auth_failed, replayed, or dropped past the budget).
bool GuidanceNode::authenticate(auth::ArsnSlot slot, const char* channel,
                                const lcm_recv_buf_t* rbuf) noexcept {
  if (verify_budget_left_ <= 0) {
    counts_.add(Verdict::kDropped, Reason::kVerifyBudget);
    return false;
  }
  --verify_budget_left_;
  std::int32_t key_id = 0;
  const auth::AuthResult r = keys_.verify(slot, channel, static_cast<const std::uint8_t*>(rbuf->data),
                                          rbuf->data_size, &key_id);
  if (r == auth::AuthResult::kOk) {
    if (slot == auth::ArsnSlot::kCommand) {
      ++auth_epoch_;  // the state on disk must catch up before this command takes effect
      last_command_key_ = key_id;
    }
    return true;
  }
  counts_.add(r == auth::AuthResult::kReplayed ? Verdict::kReplayed : Verdict::kAuthFailed,
              auth_reason(r));
  return false;
}

// EVADE_BURN_PLAN, EVADE_ARM, EVADE_KEY_CMD (PLAN-IN-1, AUTH-2): counted like every input;
// authenticated, then the bytes into the command inbox with the persist epoch they wait for.
void GuidanceNode::on_command(const lcm_recv_buf_t* rbuf, const char*, void* user) noexcept {
  auto* ctx = static_cast<SubContext*>(user);
  GuidanceNode* self = ctx->node;
  ++self->counts_.received;
  if (rbuf->data_size > kMaxCommandBytes) {
    self->counts_.add(Verdict::kRejected, Reason::kOversize);
    return;
  }
  const bool required = (self->auth_required_mask_ & command_bit(ctx->channel)) != 0;
  if (required && !self->authenticate(auth::ArsnSlot::kCommand,
                                      command_channel_name(ctx->channel), rbuf)) {
    return;
  }
  if (!self->cmd_inbox_.push(ctx->channel, self->auth_epoch_, rbuf->data, rbuf->data_size)) {
    self->counts_.add(Verdict::kDropped);
  }
}

int GuidanceNode::persist_auth_state() noexcept {
  if (!state_file_.enabled()) {
    persisted_epoch_ = auth_epoch_;
    return 0;
  }
  if (!keys_.dirty() && persisted_epoch_ == auth_epoch_) return 0;
  const std::uint64_t epoch = auth_epoch_;
  const int rc = state_file_.save(keys_);
  if (rc != 0) {
    ++persist_failures_;
    persist_failed_ = true;
    return rc;
  }
  keys_.mark_persisted();
  persisted_epoch_ = epoch;
  return 0;
}

// Commands in arrival order, each once the state it advanced is on disk (AUTH-4). After a
// failed write, the commands waiting on it are refused (not_persisted) rather than flown.
void GuidanceNode::process_commands(std::int64_t now_us) noexcept {
  if (!state_file_.enabled()) persisted_epoch_ = auth_epoch_;
  while (!cmd_inbox_.empty()) {
    const CommandInbox::Slot& raw = cmd_inbox_.front();
    if (raw.epoch > persisted_epoch_) {
      if (!persist_failed_) break;  // waits for the loop's next persist_auth_state()
      counts_.add(Verdict::kRejected, Reason::kNotPersisted);
    } else if (raw.channel == kCmdPlan) {
      admit_plan(raw, now_us);
    } else if (raw.channel == kCmdArm) {
      admit_arm(raw, now_us);
    } else {
      admit_key_cmd(raw, now_us);
    }
    cmd_inbox_.pop();
  }
  persist_failed_ = false;
}

bool GuidanceNode::command_fresh(std::int64_t utime, std::int64_t now_us) noexcept {
  if (utime > now_us + future_us_) {
    counts_.add(Verdict::kRejected, Reason::kFromFuture);
    return false;
  }
  return true;
}

// One plan message: decode, time and field checks, then the executor's validation. Every
// message ends consumed (accepted), rejected or stale (plan id not newer). The outcome is the
// acknowledgement the ground waits for (status plan_ack_id / plan_ack_result), except for a
// repeat of the plan in force (a retransmission), which leaves its acceptance standing.
void GuidanceNode::admit_plan(const CommandInbox::Slot& raw, std::int64_t now_us) noexcept {
  const int n = plan_msg_.decode(raw.data.data(), 0, static_cast<int>(raw.size));
  if (n < 0 || n != static_cast<int>(raw.size)) {
    counts_.add(Verdict::kRejected, Reason::kDecodeFailed);
    return;
  }
  if (!command_fresh(plan_msg_.utime, now_us)) return;
  guidance::PlanReject r = burn_plan_message_reject(plan_msg_);
  if (r != guidance::PlanReject::kNone) {
    plan_exec_.count_rejection(r);
  } else if (from_lcm(plan_msg_, &plan_)) {
    r = plan_exec_.load(plan_, now_us, armed_, law_.status().dv_used_mps);
  }
  const bool repeat = r == guidance::PlanReject::kNotNewer && plan_msg_.seq == plan_ack_id_;
  if (!repeat) {
    plan_ack_id_ = plan_msg_.seq;
    plan_ack_result_ = static_cast<std::int8_t>(r);  // PlanReject codes are the PLAN_REJECT_* values
  }
  if (r == guidance::PlanReject::kNone) {
    counts_.add(Verdict::kConsumed);
  } else if (r == guidance::PlanReject::kNotNewer) {
    counts_.add(Verdict::kStale, Reason::kOutOfOrderSeq);
  } else {
    counts_.add(Verdict::kRejected, r == guidance::PlanReject::kNotFinite ? Reason::kNotFinite
                                                                          : Reason::kOutOfRange);
  }
}

// An authenticated arm is ordered by its ARSN (checked in the callback), so its seq is not
// tracked: the ground's seq need not continue the last one. An unauthenticated arm (policy
// off) goes through the seq and utime admission of every input.
void GuidanceNode::admit_arm(const CommandInbox::Slot& raw, std::int64_t now_us) noexcept {
  if ((auth_required_mask_ & evade_guidance_status_t::AUTH_ARM) == 0) {
    if (!admit(kInArm, raw.data.data(), raw.size, now_us, &arm_msg_)) return;
  } else {
    const int n = arm_msg_.decode(raw.data.data(), 0, static_cast<int>(raw.size));
    if (n < 0 || n != static_cast<int>(raw.size)) {
      counts_.add(Verdict::kRejected, Reason::kDecodeFailed);
      return;
    }
    if (!command_fresh(arm_msg_.utime, now_us)) return;
    if (arm_msg_.utime < now_us - stale_us_) {
      counts_.add(Verdict::kStale, Reason::kStaleUtime);
      return;
    }
  }
  counts_.add(Verdict::kConsumed);
  armed_ = arm_msg_.armed != 0;
}

// KEY-2: activate or retire a key. The key command's own signer was checked in the callback.
void GuidanceNode::admit_key_cmd(const CommandInbox::Slot& raw, std::int64_t now_us) noexcept {
  const int n = key_msg_.decode(raw.data.data(), 0, static_cast<int>(raw.size));
  if (n < 0 || n != static_cast<int>(raw.size)) {
    counts_.add(Verdict::kRejected, Reason::kDecodeFailed);
    return;
  }
  if (!command_fresh(key_msg_.utime, now_us)) return;
  key_cmd_last_seq_ = key_msg_.seq;
  if (validate(key_msg_) != Reason::kOk) {
    key_cmd_last_result_ = auth::KeyCmdResult::kBadOp;
    counts_.add(Verdict::kRejected, Reason::kOutOfRange);
    return;
  }
  key_cmd_last_result_ = key_msg_.op == evade_key_cmd_t::OP_ACTIVATE ? keys_.activate(key_msg_.key_id)
                                                                     : keys_.retire(key_msg_.key_id);
  counts_.add(key_cmd_last_result_ == auth::KeyCmdResult::kDone ? Verdict::kConsumed
                                                                : Verdict::kRejected,
              key_cmd_last_result_ == auth::KeyCmdResult::kDone ? Reason::kOk
                                                                : Reason::kOutOfRange);
}

void GuidanceNode::fill_status(std::int64_t now_us) noexcept {
  to_lcm(law_.status(), &status_msg_);
  status_msg_.utime = now_us;
  status_msg_.seq = ++status_seq_;
  status_msg_.armed = lcm_bool(armed_);
  status_msg_.n_received = counts_.received;
  status_msg_.n_consumed = counts_.consumed;
  status_msg_.n_rejected = counts_.rejected;
  status_msg_.n_stale = counts_.stale;
  status_msg_.n_superseded = counts_.superseded;
  status_msg_.n_dropped = counts_.dropped;
  status_msg_.n_seq_gaps = counts_.seq_gaps;
  status_msg_.cycles = cycles_;
  status_msg_.watchdog_cycles = law_.status().watchdog_cycles;
  status_msg_.overruns = compute_.overruns();
  status_msg_.cycle_p50_us = compute_.quantile(0.50);
  status_msg_.cycle_p99_us = compute_.quantile(0.99);
  status_msg_.cycle_max_us = compute_.max_us();
  to_lcm(plan_exec_.status(), &status_msg_);
  status_msg_.n_auth_failed = counts_.auth_failed;
  status_msg_.n_replayed = counts_.replayed;
  status_msg_.plan_ack_id = plan_ack_id_;
  status_msg_.plan_ack_result = plan_ack_result_;
  status_msg_.auth_required = auth_required_mask_;
  status_msg_.auth_active_command_keys = static_cast<std::int8_t>(keys_.active_command_keys());  // <= 8 keys
  status_msg_.auth_last_key_id = last_command_key_;
  status_msg_.auth_state_persist_failures = persist_failures_;
  status_msg_.key_cmd_last_seq = key_cmd_last_seq_;
  status_msg_.key_cmd_last_result = static_cast<std::int8_t>(key_cmd_last_result_);  // 0..5
  if (status_pub_.publish(status_msg_) != 0) ++publish_failures_;
}

}  // namespace evade::guidance_lcm
