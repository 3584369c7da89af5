// Input accounting for the guidance node: every message received on an input channel is
// counted exactly once as consumed, rejected, stale, superseded, dropped, auth_failed or
// replayed (docs/GUIDANCE_NODE.md NODE-IN-1, docs/SECURITY.md AUTH-5). The invariant
// accounted() == received is what the fault and security tests check.
#pragma once

#include <cstdint>

namespace evade::guidance_lcm {

/// Why an input message was not used. Counted per reason for diagnosis.
enum class Verdict : std::uint8_t {
  kConsumed = 0,    ///< used by the guidance law this cycle
  kRejected,        ///< failed decode or field validation
  kStale,           ///< older than the stale limit, duplicated or out-of-order seq
  kSuperseded,      ///< a newer valid message on the same channel arrived before use
  kDropped,         ///< discarded because the bounded input queue was full (or the cycle's
                    ///< verification budget was spent)
  kAuthFailed,      ///< refused by authentication before anything in it was used
  kReplayed,        ///< authentic, but its ARSN was not above the last accepted one
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
  kUnsigned,          ///< auth: key id 0 on a channel that must be signed
  kUnknownKey,        ///< auth: no loaded key has the trailer's key id
  kBadMac,            ///< auth: MAC mismatch (forged, corrupted, or signed for another channel)
  kStandbyKey,        ///< auth: key loaded but not activated by the ground
  kRetiredKey,        ///< auth: key retired by the ground
  kWrongKeyRole,      ///< auth: sensor key on a command channel or command key on a sensor one
  kTooShortForTrailer,///< auth: shorter than a fingerprint and a security trailer
  kReplayedArsn,      ///< auth: ARSN not above the last accepted (verdict kReplayed)
  kVerifyBudget,      ///< the cycle's MAC verification budget was spent (verdict kDropped)
  kNotPersisted,      ///< a command whose ARSN could not be written to disk (verdict kRejected)
  kQueueFull,         ///< the bounded input queue was full: the oldest message made room (kDropped)
  kInboxFull,         ///< the command inbox was full: the oldest command made room (kDropped)
  kStopped,           ///< still queued or waiting when the node stopped (kDropped)
  kTableFull,         ///< a conjunction: every slot of the event table holds a live event
  kNotApplicable,     ///< a decision that does not apply to the node's state now
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
  std::int64_t auth_failed = 0;
  std::int64_t replayed = 0;
  /// Sequence numbers never received by the node: skipped between two accepted seqs of a
  /// channel, less the messages of that channel the node itself dropped from its queue.
  std::int64_t seq_gaps = 0;
  std::int64_t seq_restarts = 0;  ///< sender restarts confirmed (NODE-IN-4)
  std::int64_t by_reason[static_cast<int>(Reason::kCount)] = {};

  std::int64_t accounted() const noexcept {
    return consumed + rejected + stale + superseded + dropped + auth_failed + replayed;
  }
  void add(Verdict v) noexcept {
    switch (v) {
      case Verdict::kConsumed: ++consumed; break;
      case Verdict::kRejected: ++rejected; break;
      case Verdict::kStale: ++stale; break;
      case Verdict::kSuperseded: ++superseded; break;
      case Verdict::kDropped: ++dropped; break;
      case Verdict::kAuthFailed: ++auth_failed; break;
      case Verdict::kReplayed: ++replayed; break;
    }
  }
  void add(Verdict v, Reason r) noexcept {
    add(v);
    ++by_reason[static_cast<int>(r)];
  }
};

}  // namespace evade::guidance_lcm
