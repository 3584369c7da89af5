// Per-channel sequence-number check (docs/GUIDANCE_NODE.md NODE-IN-4): a seq equal to the last
// accepted one is a duplicate, a lower one is out of order (both stale: we already have
// newer data); a jump of more than one counts the missing messages as gaps (lost upstream,
// e.g. in the network) but the message itself is accepted.
#pragma once

#include <cstdint>

#include "evade/guidance_lcm/input_accounting.hpp"

namespace evade::guidance_lcm {

class SeqTracker {
 public:
  /// Classifies seq and, if accepted, remembers it. gaps receives the number of missing
  /// sequence numbers before this one (0 normally).
  Reason check(std::int64_t seq, std::int64_t* gaps) noexcept {
    *gaps = 0;
    if (have_) {
      if (seq == last_) return Reason::kDuplicateSeq;
      if (seq < last_) return Reason::kOutOfOrderSeq;
      if (seq > last_ + 1) *gaps = seq - last_ - 1;
    }
    have_ = true;
    last_ = seq;
    return Reason::kOk;
  }
  bool has_last() const noexcept { return have_; }
  std::int64_t last() const noexcept { return last_; }

 private:
  bool have_ = false;
  std::int64_t last_ = 0;
};

}  // namespace evade::guidance_lcm
