// Per-channel sequence-number policy (docs/GUIDANCE_NODE.md NODE-IN-4). A message is
// classified against the last accepted seq L of its channel:
//   seq == L                      duplicate (stale: we already have it)
//   1 <= seq - L <= max_jump + s  accepted; seq - L - 1 numbers were skipped (gaps); s is the
//                                 number of this channel's messages the node itself dropped
//                                 from its full queue since L (they were received: a burst the
//                                 node could not keep must not look like a sender's jump)
//   anything else                 a discontinuity: behind L (out of order, stale) or an
//                                 implausible jump ahead (rejected). It is not accepted, but
//                                 remembered as a restart candidate.
// A sender restart is confirmed by the message that follows the candidate: it continues
// the candidate's sequence (1 <= seq - candidate <= max_jump) and is newer in time than the
// last accepted message; it is then accepted and L restarts from it. So one spoofed or
// corrupted seq (L + 10^12, INT64_MIN, ...) cannot capture the channel: the genuine next
// message still continues L and is accepted; capturing it takes two consistent, newer
// messages in a row. A reordered late message never confirms (its time is older).
// Differences are taken in unsigned 64-bit arithmetic, so no seq value overflows.
#pragma once

#include <cstdint>

#include "evade/guidance_lcm/input_accounting.hpp"

namespace evade::guidance_lcm {

class SeqTracker {
 public:
  explicit SeqTracker(std::int64_t max_jump = 1000) noexcept
      : max_jump_(static_cast<std::uint64_t>(max_jump > 0 ? max_jump : 1)) {}

  /// Classifies (seq, utime) and, if accepted, remembers it. *gaps receives the number of
  /// sequence numbers skipped before this one (0 normally, and 0 on a confirmed restart).
  /// own_drops: this channel's messages the node dropped from its own queue since the last
  /// accepted one (they widen the plausible step: see the file comment).
  Reason check(std::int64_t seq, std::int64_t utime, std::int64_t* gaps,
               std::int64_t own_drops = 0) noexcept {
    *gaps = 0;
    if (!have_) return accept(seq, utime);
    const std::uint64_t d = distance(last_, seq);
    if (d == 0) return Reason::kDuplicateSeq;
    const std::uint64_t slack = own_drops > 0 ? static_cast<std::uint64_t>(own_drops) : 0U;
    if (d <= max_jump_ + slack) {
      *gaps = static_cast<std::int64_t>(d - 1);
      return accept(seq, utime);
    }
    if (have_candidate_ && utime > last_utime_) {
      const std::uint64_t dc = distance(candidate_, seq);
      if (dc >= 1 && dc <= max_jump_) {
        ++restarts_;
        return accept(seq, utime);
      }
    }
    have_candidate_ = true;
    candidate_ = seq;
    return seq < last_ ? Reason::kOutOfOrderSeq : Reason::kSeqJump;
  }
  bool has_last() const noexcept { return have_; }
  std::int64_t last() const noexcept { return last_; }
  /// Sender restarts confirmed so far.
  std::int64_t restarts() const noexcept { return restarts_; }

 private:
  static std::uint64_t distance(std::int64_t from, std::int64_t to) noexcept {
    return static_cast<std::uint64_t>(to) - static_cast<std::uint64_t>(from);  // mod 2^64
  }
  Reason accept(std::int64_t seq, std::int64_t utime) noexcept {
    have_ = true;
    last_ = seq;
    last_utime_ = utime;
    have_candidate_ = false;
    return Reason::kOk;
  }

  std::uint64_t max_jump_;
  bool have_ = false;
  std::int64_t last_ = 0;
  std::int64_t last_utime_ = 0;
  bool have_candidate_ = false;
  std::int64_t candidate_ = 0;
  std::int64_t restarts_ = 0;
};

}  // namespace evade::guidance_lcm
