// The guidance node's sensor inputs (docs/GUIDANCE_NODE.md NODE-IN-1..4): the queued nav and
// angles messages of a cycle, each decoded, validated, checked for freshness, its ARSN compared
// again and its seq checked, then committed (docs/SECURITY.md ARSN-1: a refused message changes
// nothing); the newest valid message of each sensor is the cycle's candidate and older ones are
// superseded. Members of NodeCore (internal/node_core.hpp).
#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/internal/node_core.hpp"
#include "evade/guidance_lcm/validate.hpp"

namespace evade::guidance_lcm::internal {

// NODE-IN-4: the row's sequence tracker. Counts the refusal (stale or rejected) and the gaps.
bool NodeCore::admit_seq(Input in, std::int64_t seq, std::int64_t utime) noexcept {
  std::int64_t gaps = 0;
  SeqTracker& tracker = seq_[index(in)];
  const std::int64_t restarts = tracker.restarts();
  std::int64_t& dropped = dropped_since_accept_[index(in)];
  const Reason s = tracker.check(seq, utime, &gaps, dropped);
  if (s != Reason::kOk) {
    counts_.add(s == Reason::kSeqJump ? Verdict::kRejected : Verdict::kStale, s);
    return false;
  }
  // Gaps are numbers never received: the ones this node dropped from its own queue were.
  counts_.seq_gaps += gaps > dropped ? gaps - dropped : 0;
  dropped = 0;
  counts_.seq_restarts += tracker.restarts() - restarts;
  return true;
}

template <typename Msg>
bool NodeCore::admit_sensor(const RawMessage& raw, std::int64_t now_us, Msg* msg) noexcept {
  const int n = msg->decode(raw.data.data(), 0, static_cast<int>(raw.size));
  if (n < 0 || n != static_cast<int>(raw.size)) {  // wrong type, truncated or trailing bytes
    counts_.add(Verdict::kRejected, Reason::kDecodeFailed);
    return false;
  }
  const Reason r = validate(*msg);
  if (r != Reason::kOk) {
    counts_.add(Verdict::kRejected, r);
    return false;
  }
  if (msg->utime > now_us + future_us_) {
    counts_.add(Verdict::kRejected, Reason::kFromFuture);
    return false;
  }
  if (msg->utime < now_us - stale_us_) {
    counts_.add(Verdict::kStale, Reason::kStaleUtime);
    return false;
  }
  const auth::ArsnSlot slot = input_row(raw.channel).slot;
  const bool signed_msg = raw.key_id != 0;
  if (signed_msg && !(raw.arsn > keys_.last_arsn(raw.key_id, slot))) {
    counts_.add(Verdict::kReplayed, Reason::kReplayedArsn);  // a reordered copy got there first
    return false;
  }
  if (!admit_seq(raw.channel, msg->seq, msg->utime)) return false;
  return !signed_msg || commit_arsn(raw.key_id, slot, raw.arsn);  // checked above: commits
}

void NodeCore::process_queue(std::int64_t now_us) noexcept {
  have_angles_cand_ = false;
  have_nav_cand_ = false;
  while (!queue_.empty()) {
    const RawMessage& raw = queue_.front();
    if (raw.channel == Input::kAngles) {
      evade_angles_t m{};
      if (admit_sensor(raw, now_us, &m)) {
        if (have_angles_cand_) counts_.add(Verdict::kSuperseded);
        cand_angles_ = m;
        have_angles_cand_ = true;
      }
    } else {  // the queue holds only sensor rows: angles and nav
      evade_nav_state_t m{};
      if (admit_sensor(raw, now_us, &m)) {
        if (have_nav_cand_) counts_.add(Verdict::kSuperseded);
        cand_nav_ = m;
        have_nav_cand_ = true;
      }
    }
    queue_.pop();
  }
  input_.has_measurement = false;
  if (have_angles_cand_) {
    counts_.add(Verdict::kConsumed);
    from_lcm(cand_angles_, &input_.meas);
    input_.has_measurement = true;
    if (cand_angles_.valid) {
      have_angles_ = true;
      last_angles_utime_ = cand_angles_.utime;
    }
  }
  if (have_nav_cand_) {
    counts_.add(Verdict::kConsumed);
    from_lcm(cand_nav_, &input_.nav);
  }
  input_.armed = armed_;
}

}  // namespace evade::guidance_lcm::internal
