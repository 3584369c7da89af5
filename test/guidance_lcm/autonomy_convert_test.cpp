// The ground's messages of the onboard conjunction response (docs/AUTONOMY.md AUT-1, AUT-7):
// to_lcm of an event and a decision is what the node's from_lcm reads back bit for bit, and
// encodes to the very bytes of the test harness's own field-by-field message; a retransmission
// of what is in force is answered ALREADY_IN_FORCE, not refused.
#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "conjunction_harness.hpp"
#include "evade/guidance_lcm/autonomy_convert.hpp"

namespace evade::guidance_lcm::test {
namespace {

template <typename Msg>
std::vector<std::uint8_t> bytes(const Msg& m) {
  std::vector<std::uint8_t> b(static_cast<std::size_t>(m.getEncodedSize()));
  EXPECT_EQ(m.encode(b.data(), 0, static_cast<int>(b.size())), static_cast<int>(b.size()));
  return b;
}

TEST(AutonomyConvert, TheGroundsConjunctionMessageIsTheEventBitForBit) {
  autonomy::ConjunctionEvent e = node_event(41, 3);
  e.cov1_eci(0, 1) = e.cov1_eci(1, 0) = 1.0 / 3.0;  // a term with every mantissa bit used
  e.x2_eci(4) = -7612.123456789012;
  evade_conjunction_t m{};
  to_lcm(e, kT0 + 5, 9, &m);
  EXPECT_EQ(bytes(m), bytes(conjunction_msg(e, 9, kT0 + 5)));
  autonomy::ConjunctionEvent back;
  from_lcm(m, &back);
  EXPECT_TRUE(autonomy::same_event(back, e));
  EXPECT_EQ(std::memcmp(back.cov1_eci.data(), e.cov1_eci.data(), sizeof(double) * 36), 0);
}

TEST(AutonomyConvert, TheGroundsDecisionMessageIsTheDecision) {
  using Kind = autonomy::DecisionCommand::Kind;
  for (const Kind k : {Kind::kVeto, Kind::kApprove, Kind::kSetAutonomy}) {
    autonomy::DecisionCommand d;
    d.kind = k;
    d.event_id = 123456789012LL;
    d.proposal_id = 77;
    d.autonomy = 2;
    evade_cam_decision_t m{};
    to_lcm(d, kT0, 4, &m);
    EXPECT_EQ(m.utime, kT0);
    EXPECT_EQ(m.seq, 4);
    autonomy::DecisionCommand back;
    from_lcm(m, &back);
    EXPECT_EQ(back.kind, k);
    EXPECT_EQ(back.event_id, d.event_id);
    EXPECT_EQ(back.proposal_id, d.proposal_id);
    EXPECT_EQ(back.autonomy, d.autonomy);
  }
}

TEST(AutonomyConvert, ARetransmissionIsInForceAndEveryOtherOutcomeIsNot) {
  const CommandOutcome again =
      conjunction_outcome(autonomy::EventResult::kAlreadyTracked, autonomy::EventProblem::kNone);
  EXPECT_TRUE(again.in_force);
  EXPECT_EQ(again.detail, evade_cmd_ack_t::CONJ_ALREADY_TRACKED);
  const CommandOutcome applied = decision_outcome(autonomy::DecisionResult::kAlreadyApplied);
  EXPECT_TRUE(applied.in_force);
  EXPECT_EQ(applied.detail, evade_cmd_ack_t::DECIDE_ALREADY_APPLIED);
  for (const autonomy::EventResult r :
       {autonomy::EventResult::kTracked, autonomy::EventResult::kReplaced,
        autonomy::EventResult::kNotNewer, autonomy::EventResult::kTableFull,
        autonomy::EventResult::kBadEvent}) {
    EXPECT_FALSE(conjunction_outcome(r, autonomy::EventProblem::kBadId).in_force);
  }
  for (int r = 0; r <= static_cast<int>(autonomy::DecisionResult::kAutonomyOff); ++r) {
    EXPECT_FALSE(decision_outcome(static_cast<autonomy::DecisionResult>(r)).in_force) << r;
  }
}

}  // namespace
}  // namespace evade::guidance_lcm::test
