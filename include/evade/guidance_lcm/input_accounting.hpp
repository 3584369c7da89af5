// Input accounting for the guidance node: every message received on an input channel is
// counted exactly once as consumed, rejected, stale, superseded or dropped (docs/GUIDANCE_NODE.md
// NODE-IN-1). The invariant total() == received is what the fault tests check.
#pragma once

#include <cstdint>

namespace evade::guidance_lcm {

/// Why an input message was not used. Counted per reason for diagnosis.
enum class Verdict : std::uint8_t {
  kConsumed = 0,    ///< used by the guidance law this cycle
  kRejected,        ///< failed decode or field validation
  kStale,           ///< older than the stale limit, duplicated or out-of-order seq
  kSuperseded,      ///< a newer valid message on the same channel arrived before use
  kDropped,         ///< discarded because the bounded input queue was full
};

/// Reject reasons (subset of kRejected / kStale), one counter each.
enum class Reason : std::uint8_t {
  kOk = 0,
  kDecodeFailed,      ///< wrong type (fingerprint), truncated or corrupt bytes
  kOversize,          ///< larger than any input type
  kNotFinite,         ///< NaN or Inf in a numeric field
  kOutOfRange,        ///< angle, sigma, range or flag outside its allowed range
  kFromFuture,        ///< utime later than now + tolerance
  kStaleUtime,        ///< utime older than now - stale limit
  kDuplicateSeq,      ///< seq equal to the last accepted seq on this channel
  kOutOfOrderSeq,     ///< seq lower than the last accepted seq on this channel
  kSeqJump,           ///< seq implausibly far ahead (more than node.max_seq_jump), unconfirmed
  kCount
};

const char* reason_name(Reason r) noexcept;

struct InputCounts {
  std::int64_t received = 0;
  std::int64_t consumed = 0;
  std::int64_t rejected = 0;
  std::int64_t stale = 0;
  std::int64_t superseded = 0;
  std::int64_t dropped = 0;
  /// Sequence numbers never received by the node: skipped between two accepted seqs of a
  /// channel, less the messages of that channel the node itself dropped from its queue.
  std::int64_t seq_gaps = 0;
  std::int64_t seq_restarts = 0;  ///< sender restarts confirmed (NODE-IN-4)
  std::int64_t by_reason[static_cast<int>(Reason::kCount)] = {};

  std::int64_t accounted() const noexcept {
    return consumed + rejected + stale + superseded + dropped;
  }
  void add(Verdict v) noexcept {
    switch (v) {
      case Verdict::kConsumed: ++consumed; break;
      case Verdict::kRejected: ++rejected; break;
      case Verdict::kStale: ++stale; break;
      case Verdict::kSuperseded: ++superseded; break;
      case Verdict::kDropped: ++dropped; break;
    }
  }
  void add(Verdict v, Reason r) noexcept {
    add(v);
    ++by_reason[static_cast<int>(r)];
  }
};

}  // namespace evade::guidance_lcm
