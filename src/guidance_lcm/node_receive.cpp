// The guidance node's receive side (docs/SECURITY.md AUTH-1..5, docs/GUIDANCE_NODE.md NODE-IN-1):
// one LCM callback for every row of the input table (node_inputs.hpp). Each message is counted
// received, checked for size, authenticated when the policy requires its row (within the row's
// verification budget: MAC first, then key state and role, then the ARSN compared, nothing
// advanced), and handed to its kind: a sensor is queued, a tick taken, a command put in the
// inbox. Members of NodeCore (internal/node_core.hpp).
#include <cmath>

#include "evade/guidance_lcm/internal/node_core.hpp"
#include "evade/guidance_lcm/validate.hpp"

namespace evade::guidance_lcm::internal {
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

// Refusals of a message that verified under a command key: the ground sent it (or a replayer
// resent the ground's bytes), so the node answers it (TM-2).
bool answerable(auth::AuthResult r) noexcept {
  return r == auth::AuthResult::kReplayed || r == auth::AuthResult::kStandbyKey ||
         r == auth::AuthResult::kRetiredKey;
}

}  // namespace

void NodeCore::on_message(const lcm_recv_buf_t* rbuf, const char*, void* user) noexcept {
  const auto* ctx = static_cast<const SubContext*>(user);
  ctx->node->receive(input_row(ctx->input), static_cast<const std::uint8_t*>(rbuf->data),
                     rbuf->data_size);
}

void NodeCore::receive(const InputRow& row, const std::uint8_t* data, std::uint32_t size) noexcept {
  ++counts_.received;
  ++received_[index(row.input)];
  if (size > row.max_bytes) {  // no message of the row's type is this large: corrupt
    counts_.add(Verdict::kRejected, Reason::kOversize);
    return;
  }
  switch (row.kind) {
    case InputKind::kSensor: receive_sensor(row, data, size); break;
    case InputKind::kTick: receive_tick(row, data, size); break;
    case InputKind::kCommand: receive_command(row, data, size); break;
  }
}

// AUTH-1..3, AUTH-5: the message's trailer, within its channel's budget. Every outcome but
// success is counted here (auth_failed, replayed, or dropped past the budget); an authentic
// command refused here (replayed, standby or retired key) is answered.
bool NodeCore::authenticate(const InputRow& row, const std::uint8_t* data, std::uint32_t size,
                            auth::TrailerView* t) noexcept {
  if (!budget_.take(row.input)) {
    counts_.add(Verdict::kDropped, Reason::kVerifyBudget);
    return false;
  }
  const auth::AuthResult r = keys_.check(row.slot, row.channel, data, size, t);
  if (r == auth::AuthResult::kOk) return true;
  counts_.add(r == auth::AuthResult::kReplayed ? Verdict::kReplayed : Verdict::kAuthFailed,
              auth_reason(r));
  if (row.kind == InputKind::kCommand && answerable(r)) {
    ack_refused_in_callback(row, *t, auth_reason(r));
  }
  return false;
}

void NodeCore::receive_sensor(const InputRow& row, const std::uint8_t* data,
                              std::uint32_t size) noexcept {
  auth::TrailerView t;
  if (input_required(row, cfg_.auth) && !authenticate(row, data, size, &t)) return;
  Input dropped = Input::kAngles;
  if (!queue_.push(row.input, t.key_id, t.arsn, data, size, &dropped)) {
    counts_.add(Verdict::kDropped, Reason::kQueueFull);  // the oldest queued message made room
    ++dropped_since_accept_[index(dropped)];
  }
}

// The lockstep clock: one cycle per accepted tick. Every tick is counted (NODE-IN-1): consumed
// when it is accepted, rejected, stale (a repeated or older seq: the simulator re-sends a tick
// it got no answer to) or refused by authentication; its ARSN is committed only when accepted.
void NodeCore::receive_tick(const InputRow& row, const std::uint8_t* data,
                            std::uint32_t size) noexcept {
  auth::TrailerView t;
  const bool required = input_required(row, cfg_.auth);
  if (required && !authenticate(row, data, size, &t)) return;
  evade_sim_clock_t tick{};
  if (tick.decode(data, 0, static_cast<int>(size)) != static_cast<int>(size)) {
    counts_.add(Verdict::kRejected, Reason::kDecodeFailed);
    return;
  }
  const Reason v = validate(tick);
  if (v != Reason::kOk) {
    counts_.add(Verdict::kRejected, v);
    return;
  }
  if (required && !(t.arsn > keys_.last_arsn(t.key_id, row.slot))) {
    counts_.add(Verdict::kReplayed, Reason::kReplayedArsn);
    return;
  }
  if (!admit_seq(row.input, tick.seq, tick.utime)) return;
  if (required && !commit_arsn(t.key_id, row.slot, t.arsn)) return;  // checked above: commits
  counts_.add(Verdict::kConsumed);
  ++ticks_received_;
  if (tick_pending_) ++ticks_missed_;  // the previous tick never got its cycle
  tick_pending_ = true;
  tick_utime_ = tick.utime;
}

// EVADE_BURN_PLAN, EVADE_ARM, EVADE_KEY_CMD (PLAN-IN-1, AUTH-2): authenticated, then the bytes
// and the trailer into the command inbox; the cycle admits, executes and answers it.
void NodeCore::receive_command(const InputRow& row, const std::uint8_t* data,
                               std::uint32_t size) noexcept {
  auth::TrailerView t;
  const bool required = input_required(row, cfg_.auth);
  if (required && !authenticate(row, data, size, &t)) return;
  bool evicted = false;
  CommandInbox::Slot& s = cmd_inbox_.push(row.input, data, size, &evicted);
  if (evicted) counts_.add(Verdict::kDropped, Reason::kInboxFull);
  s.authenticated = required;
  if (required) {
    s.key_id = t.key_id;
    s.arsn = t.arsn;
    for (std::size_t i = 0; i < s.mac.size(); ++i) s.mac[i] = t.mac[i];
  }
}

// ARSN-1: the ARSN advances only for a message accepted in full. The check in the callback
// compared it with the last accepted one; a message admitted since (a reordered copy of the
// same key) may have moved that, and then this one is a replay after all.
bool NodeCore::commit_arsn(std::int32_t key_id, auth::ArsnSlot slot, std::int64_t arsn) noexcept {
  if (keys_.commit(key_id, slot, arsn)) return true;
  counts_.add(Verdict::kReplayed, Reason::kReplayedArsn);
  return false;
}

}  // namespace evade::guidance_lcm::internal
