// The per-channel sequence policy (docs/GUIDANCE_NODE.md NODE-IN-4): duplicates, gaps, jumps, a
// confirmed restart, and no overflow at the ends of int64.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <set>

#include "evade/guidance_lcm/internal/seq_tracker.hpp"

namespace evade::guidance_lcm {
namespace {

TEST(SeqTracker, ClassifiesDuplicateOutOfOrderAndGaps) {
  SeqTracker s;
  std::int64_t gaps = -1;
  EXPECT_EQ(s.check(10, 100, &gaps), Reason::kOk);
  EXPECT_EQ(gaps, 0);
  EXPECT_EQ(s.check(10, 100, &gaps), Reason::kDuplicateSeq);
  EXPECT_EQ(s.check(9, 90, &gaps), Reason::kOutOfOrderSeq);
  EXPECT_EQ(s.check(11, 110, &gaps), Reason::kOk);
  EXPECT_EQ(s.check(15, 150, &gaps), Reason::kOk);
  EXPECT_EQ(gaps, 3);
  EXPECT_EQ(s.last(), 15);
}

// NODE-IN-4: one spoofed or corrupted seq far ahead is rejected and does not capture the
// channel: the genuine next message still continues the sequence and is accepted.
TEST(SeqTracker, OneSpoofedJumpCannotLockOutTheSender) {
  SeqTracker s(1000);
  std::int64_t gaps = 0;
  EXPECT_EQ(s.check(5, 50, &gaps), Reason::kOk);
  EXPECT_EQ(s.check(5 + 1000000000000LL, 60, &gaps), Reason::kSeqJump);
  for (std::int64_t k = 6; k < 20; ++k) {
    EXPECT_EQ(s.check(k, 10 * k + 10, &gaps), Reason::kOk) << "seq " << k;
    EXPECT_EQ(gaps, 0);
  }
  EXPECT_EQ(s.restarts(), 0);
}

// NODE-IN-4: a genuine sender restart (seq back to 0, time going on) is confirmed by the
// message after it and the channel follows the new sequence; one message is lost.
TEST(SeqTracker, GenuineRestartIsConfirmedByTheNextMessage) {
  SeqTracker s(1000);
  std::int64_t gaps = 0;
  for (std::int64_t k = 100; k < 110; ++k) ASSERT_EQ(s.check(k, 10 * k, &gaps), Reason::kOk);
  EXPECT_EQ(s.check(0, 2000, &gaps), Reason::kOutOfOrderSeq);  // candidate
  EXPECT_EQ(s.check(1, 2010, &gaps), Reason::kOk);             // confirms the restart
  EXPECT_EQ(gaps, 0);
  EXPECT_EQ(s.restarts(), 1);
  EXPECT_EQ(s.check(2, 2020, &gaps), Reason::kOk);
  EXPECT_EQ(s.last(), 2);
}

// A late (reordered) message never confirms a restart: its time is older.
TEST(SeqTracker, ReorderedLateMessagesNeverConfirmARestart) {
  SeqTracker s(1000);
  std::int64_t gaps = 0;
  for (std::int64_t k = 1; k <= 10; ++k) ASSERT_EQ(s.check(k, 10 * k, &gaps), Reason::kOk);
  EXPECT_EQ(s.check(7, 70, &gaps), Reason::kOutOfOrderSeq);
  EXPECT_EQ(s.check(8, 80, &gaps), Reason::kOutOfOrderSeq);
  EXPECT_EQ(s.restarts(), 0);
  EXPECT_EQ(s.check(11, 110, &gaps), Reason::kOk);
}

// Extreme values: differences are unsigned, so INT64_MIN then INT64_MAX is no overflow
// (it was undefined behaviour and gave -2 gaps) and no gap is ever negative.
TEST(SeqTracker, ExtremeSeqValuesNeitherOverflowNorGiveNegativeGaps) {
  SeqTracker s(1000);
  std::int64_t gaps = 0;
  const std::int64_t lo = std::numeric_limits<std::int64_t>::min();
  const std::int64_t hi = std::numeric_limits<std::int64_t>::max();
  EXPECT_EQ(s.check(lo, 1, &gaps), Reason::kOk);
  EXPECT_EQ(s.check(hi, 2, &gaps), Reason::kSeqJump);  // 2^64 - 1 ahead: implausible
  EXPECT_EQ(gaps, 0);
  EXPECT_EQ(s.check(lo + 3, 3, &gaps), Reason::kOk);
  EXPECT_EQ(gaps, 2);
  SeqTracker t(1000);
  EXPECT_EQ(t.check(hi - 1, 1, &gaps), Reason::kOk);
  EXPECT_EQ(t.check(hi, 2, &gaps), Reason::kOk);
  EXPECT_EQ(gaps, 0);
  EXPECT_EQ(t.check(lo, 3, &gaps), Reason::kOk);  // the sequence wraps modulo 2^64
  EXPECT_EQ(gaps, 0);
}

// NODE-IN-4: the messages the node dropped from its own full queue widen the plausible step: a
// burst the node could not keep (2,000 of one channel's messages dropped between two accepted
// ones) is not a sender's jump; without them the same step is one.
TEST(SeqTracker, OwnQueueDropsWidenThePlausibleStep) {
  std::int64_t gaps = 0;
  SeqTracker t(1000);
  EXPECT_EQ(t.check(1, 1, &gaps), Reason::kOk);
  EXPECT_EQ(t.check(2002, 2, &gaps, 2000), Reason::kOk);
  EXPECT_EQ(gaps, 2000);
  SeqTracker u(1000);
  EXPECT_EQ(u.check(1, 1, &gaps), Reason::kOk);
  EXPECT_EQ(u.check(2002, 2, &gaps), Reason::kSeqJump);
}

}  // namespace
}  // namespace evade::guidance_lcm
