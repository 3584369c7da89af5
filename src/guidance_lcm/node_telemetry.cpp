// The guidance node's telemetry (docs/SECURITY.md TM-1..3): the acknowledgement of every
// authenticated command (evade_cmd_ack_t: the command's key id, ARSN and MAC, the outcome and
// its reason, the node's last accepted ARSN of that key, the plan in force, armed), published
// once what the command changed is on disk, and the status; both signed with the node's
// telemetry key (SigningPublisher: encoded into a buffer sized at construction, no allocation).
// Members of NodeCore (internal/node_core.hpp).
#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/internal/node_core.hpp"

namespace evade::guidance_lcm::internal {
namespace {

using Ack = evade_cmd_ack_t;

static_assert(static_cast<int>(auth::KeyState::kActive) == Ack::KEY_STATE_ACTIVE &&
                  static_cast<int>(auth::KeyState::kStandby) == Ack::KEY_STATE_STANDBY &&
                  static_cast<int>(auth::KeyState::kRetired) == Ack::KEY_STATE_RETIRED,
              "KeyState values are the acknowledgement's KEY_STATE_* codes");
static_assert(static_cast<int>(Reason::kReplayedArsn) == Ack::REASON_REPLAYED_ARSN &&
                  static_cast<int>(Reason::kNotPersisted) == Ack::REASON_NOT_PERSISTED &&
                  static_cast<int>(Reason::kStopped) == Ack::REASON_STOPPED &&
                  static_cast<int>(Reason::kFromFuture) == Ack::REASON_FROM_FUTURE &&
                  static_cast<int>(Reason::kTableFull) == Ack::REASON_TABLE_FULL &&
                  static_cast<int>(Reason::kNotApplicable) == Ack::REASON_NOT_APPLICABLE,
              "Reason values are the acknowledgement's REASON_* codes");
static_assert(static_cast<int>(auth::KeyRole::kTelemetry) ==
                  evade_guidance_status_t::KEY_ROLE_TELEMETRY,
              "KeyRole values are the status's KEY_ROLE_* codes");

}  // namespace

void NodeCore::fill_ack(Input in, std::int32_t key_id, std::int64_t arsn, const std::uint8_t* mac,
                        std::int8_t outcome, Reason r, std::int16_t detail, std::int64_t now_us,
                        evade_cmd_ack_t* a) const noexcept {
  a->utime = now_us;
  a->command = input_row(in).ack_command;
  a->cmd_key_id = key_id;
  a->cmd_arsn = arsn;
  for (std::size_t i = 0; i < auth::kMacBytes; ++i) a->cmd_mac[i] = static_cast<std::int8_t>(mac[i]);
  a->outcome = outcome;
  a->reason = static_cast<std::int16_t>(r);
  a->detail = detail;
  a->node_arsn = keys_.last_arsn(key_id, auth::ArsnSlot::kCommand);
  a->plan_id = plan_exec_.status().plan_id;
  a->armed = lcm_bool(armed_);
  const auth::KeyEntry* e = keys_.find(key_id);
  a->key_state = static_cast<std::int8_t>(e != nullptr ? e->state : auth::KeyState::kRetired);
}

// An authenticated command's outcome, queued until epoch is on disk (0: nothing to wait for).
// A command the policy let through unsigned has nobody to answer.
void NodeCore::ack(const CommandInbox::Slot& s, std::int8_t outcome, Reason r, std::int16_t detail,
                   std::uint64_t epoch, std::int64_t now_us) noexcept {
  if (!s.authenticated) return;
  AckOutbox::Entry* e = acks_.add(epoch);
  if (e == nullptr) {
    ++acks_unsent_;
    return;
  }
  fill_ack(s.input, s.key_id, s.arsn, s.mac.data(), outcome, r, detail, now_us, &e->ack);
}

// A command refused at receipt under a valid MAC of a command key (replayed, standby or retired
// key). A replay flood gets at most kCallbackAcksPerCycle answers per cycle; the others are
// counted unsent (the signed status carries every command key's last ARSN).
void NodeCore::ack_refused_in_callback(const InputRow& row, const auth::TrailerView& t,
                                       Reason r) noexcept {
  const auth::KeyEntry* e = keys_.find(t.key_id);
  if (e == nullptr || e->role != auth::KeyRole::kCommand) return;  // not the ground's
  AckOutbox::Entry* slot = callback_acks_left_ > 0 ? acks_.add(0) : nullptr;
  if (slot == nullptr) {
    ++acks_unsent_;
    return;
  }
  --callback_acks_left_;
  fill_ack(row.input, t.key_id, t.arsn, t.mac, Ack::OUTCOME_REFUSED, r, 0, last_cycle_us_,
           &slot->ack);
}

// After a failed write (AUTH-4) the acknowledgements waiting on it become refusals: what they
// announced is not on disk.
void NodeCore::fail_waiting_acks() noexcept {
  for (std::size_t i = 0; i < acks_.size(); ++i) {
    AckOutbox::Entry& e = acks_.at(i);
    if (e.epoch <= persisted_epoch_ || e.epoch > failed_epoch_) continue;
    e.ack.outcome = Ack::OUTCOME_REFUSED;
    e.ack.reason = static_cast<std::int16_t>(Reason::kNotPersisted);
    e.epoch = 0;
  }
}

void NodeCore::publish_acks() noexcept {
  while (!acks_.empty() && acks_.front().epoch <= persisted_epoch_) {
    evade_cmd_ack_t& a = acks_.front().ack;
    a.seq = ++ack_seq_;
    if (ack_pub_.publish(a) == 0) {
      ++acks_published_;
      last_ack_ = a;
    } else {
      ++acks_unsent_;
      ++publish_failures_;
    }
    acks_.pop();
  }
}

void NodeCore::fill_status_keys() noexcept {
  const std::size_t n = keys_.size();
  status_msg_.auth_n_keys = static_cast<std::int8_t>(n);  // <= KeyRing::kMaxKeys (8)
  for (std::size_t i = 0; i < auth::KeyRing::kMaxKeys; ++i) {
    const bool used = i < n;
    const auth::KeyEntry& e = keys_.entry(used ? i : 0);
    status_msg_.auth_key_id[i] = used ? e.id : 0;
    status_msg_.auth_key_role[i] = used ? static_cast<std::int8_t>(e.role) : 0;
    status_msg_.auth_key_state[i] = used ? static_cast<std::int8_t>(e.state) : 0;
    status_msg_.auth_key_arsn[i] =
        used && e.role == auth::KeyRole::kCommand
            ? e.arsn[static_cast<std::size_t>(auth::ArsnSlot::kCommand)]
            : 0;
  }
}

void NodeCore::fill_status(std::int64_t now_us) noexcept {
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
  fill_status_keys();
  status_msg_.n_acks = acks_published_;
  status_msg_.n_acks_unsent = acks_unsent_;
  if (status_pub_.publish(status_msg_) != 0) ++publish_failures_;
}

}  // namespace evade::guidance_lcm::internal
