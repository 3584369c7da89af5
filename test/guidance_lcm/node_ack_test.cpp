// The node answers every command it authenticated, naming that very command, and signs the
// answer (docs/SECURITY.md TM-1..3; issue 40 rows 1-3 and 13 seen from the node): the
// acknowledgement carries the command's key id, ARSN and MAC, the outcome and its reason, the
// node's last accepted ARSN of the key, the plan in force and armed, and verifies under the
// telemetry key. A forged command gets no answer; a replay flood gets a bounded number; an
// acknowledgement is published only once what it announces is on disk.
#include <sys/stat.h>

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "command_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

using S = evade_guidance_status_t;
using A = evade_cmd_ack_t;

TEST(NodeAck, AcknowledgementNamesTheCommandsKeyArsnAndMacAndIsSigned) {
  Rig rig;
  AckRecorder acks(rig.lcm.get());
  const std::vector<std::uint8_t> b = signed_bytes(plan_msg(7), kChanPlan, test_command_key(), 77);
  send(rig, kChanPlan, b);
  nav_cycle(rig, 0);
  rig.flush();
  ASSERT_EQ(acks.acks().size(), 1U);
  EXPECT_EQ(acks.unverified(), 0);
  const A& a = acks.acks()[0];
  EXPECT_EQ(a.command, A::COMMAND_PLAN);
  EXPECT_EQ(a.cmd_key_id, 1);
  EXPECT_EQ(a.cmd_arsn, 77);
  EXPECT_TRUE(names_mac(a, b));
  EXPECT_EQ(a.outcome, A::OUTCOME_ACCEPTED);
  EXPECT_EQ(a.reason, A::REASON_OK);
  EXPECT_EQ(a.node_arsn, 77);
  EXPECT_EQ(a.plan_id, 7);
  EXPECT_EQ(a.armed, 1);
  EXPECT_EQ(a.key_state, A::KEY_STATE_ACTIVE);
  EXPECT_EQ(a.utime, kT0);
  EXPECT_EQ(rig.node.acks_published(), 1);
  // Signed with another telemetry key, the same bytes do not verify: the recorder checks it.
  AckRecorder wrong(rig.lcm.get(), test_key(3, 0x99));
  send(rig, kChanPlan, signed_bytes(plan_msg(8), kChanPlan, test_command_key(), 78));
  nav_cycle(rig, 1);
  rig.flush();
  EXPECT_EQ(wrong.acks().size(), 0U);
  EXPECT_EQ(wrong.unverified(), 1);
  EXPECT_EQ(acks.acks().size(), 2U);
  expect_accounted(rig);
}

// Issue 40 row 1: a plan to a disarmed node is answered refused, naming the reason; the plan id
// chosen by the ground (0 here, the CLI's old default) plays no part in the answer.
TEST(NodeAck, PlanToADisarmedNodeIsAnsweredRefusedDisarmed) {
  NodeConfig cfg;
  cfg.guidance.armed = false;
  Rig rig(cfg);
  AckRecorder acks(rig.lcm.get());
  send(rig, kChanPlan, signed_bytes(plan_msg(0), kChanPlan, test_command_key(), 5));
  nav_cycle(rig, 0);
  rig.flush();
  const A* a = acks.find(1, 5);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->outcome, A::OUTCOME_REFUSED);
  EXPECT_EQ(a->reason, A::REASON_OUT_OF_RANGE);
  EXPECT_EQ(a->detail, S::PLAN_REJECT_DISARMED);
  EXPECT_EQ(a->armed, 0);
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, 0);
  expect_accounted(rig);
}

// Issue 40 row 2: another plan with the id in force is refused (not newer) and says which plan
// is in force; the very plan in force sent again (a retransmission) is answered as in force.
TEST(NodeAck, PlanWithTheIdInForceIsRefusedUnlessItIsThatVeryPlan) {
  Rig rig;
  AckRecorder acks(rig.lcm.get());
  send(rig, kChanPlan, signed_bytes(plan_msg(5, 1.0), kChanPlan, test_command_key(), 10));
  send(rig, kChanPlan, signed_bytes(plan_msg(5, 3.0), kChanPlan, test_command_key(), 11));
  send(rig, kChanPlan, signed_bytes(plan_msg(5, 1.0), kChanPlan, test_command_key(), 12));
  nav_cycle(rig, 0);
  rig.flush();
  ASSERT_EQ(acks.acks().size(), 3U);
  EXPECT_EQ(acks.find(1, 10)->outcome, A::OUTCOME_ACCEPTED);
  const A* other = acks.find(1, 11);
  EXPECT_EQ(other->outcome, A::OUTCOME_REFUSED);
  EXPECT_EQ(other->reason, A::REASON_OUT_OF_ORDER_SEQ);
  EXPECT_EQ(other->detail, S::PLAN_REJECT_NOT_NEWER);
  EXPECT_EQ(other->plan_id, 5);
  EXPECT_EQ(acks.find(1, 12)->outcome, A::OUTCOME_ALREADY_IN_FORCE);
  EXPECT_EQ(thrust_cycles(rig, 1, 100), 5) << "the first plan 5 flies, once";
  expect_accounted(rig);
}

// Issue 40 row 3: an arm (or disarm) signed with a standby key is refused at receipt and
// answered so, naming the key and its ARSN: the ground no longer infers success from the state.
TEST(NodeAck, ArmSignedWithAStandbyKeyIsAnsweredStandbyKey) {
  NodeSecurity sec = test_security();
  const SigningKey k4 = test_key(4, 0x44);
  ASSERT_EQ(sec.keys.add(k4.id, auth::KeyRole::kCommand, k4.key, auth::KeyState::kStandby), nullptr);
  Rig rig(NodeConfig{}, 100000, sec);
  AckRecorder acks(rig.lcm.get());
  evade_arm_t arm{};
  arm.utime = kT0;
  arm.seq = 1;
  arm.armed = 1;
  send(rig, kChanArm, signed_bytes(arm, kChanArm, k4, 30));
  arm.armed = 0;
  send(rig, kChanArm, signed_bytes(arm, kChanArm, k4, 31));
  nav_cycle(rig, 0);
  rig.flush();
  for (std::int64_t arsn : {30, 31}) {
    const A* a = acks.find(4, arsn);
    ASSERT_NE(a, nullptr) << arsn;
    EXPECT_EQ(a->command, A::COMMAND_ARM);
    EXPECT_EQ(a->outcome, A::OUTCOME_REFUSED);
    EXPECT_EQ(a->reason, A::REASON_STANDBY_KEY);
    EXPECT_EQ(a->key_state, A::KEY_STATE_STANDBY);
  }
  EXPECT_TRUE(rig.node.armed());
  EXPECT_EQ(reason(rig, Reason::kStandbyKey), 2);
  expect_accounted(rig);
}

// Issue 40 rows 9 and 13: a plan stamped an hour ahead of the node is answered from_future (the
// ground exits 3 naming it) and changes nothing: the node's ARSN of the key stays where it was,
// so the ground's next command, with a lower ARSN, is still accepted.
TEST(NodeAck, PlanFromTheFutureIsAnsweredAndLeavesTheArsnWhereItWas) {
  Rig rig;
  AckRecorder acks(rig.lcm.get());
  const std::int64_t hour_ahead = kT0 + 3'600'000'000LL;
  send(rig, kChanPlan, signed_bytes(plan_msg(1, 1.0, Vec3(0.0, 0.1, 0.0), hour_ahead), kChanPlan,
                                    test_command_key(), 100));
  nav_cycle(rig, 0);
  rig.flush();
  const A* a = acks.find(1, 100);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->outcome, A::OUTCOME_REFUSED);
  EXPECT_EQ(a->reason, A::REASON_FROM_FUTURE);
  EXPECT_EQ(a->node_arsn, 0);
  EXPECT_EQ(rig.node.keys().last_arsn(1, auth::ArsnSlot::kCommand), 0);
  send(rig, kChanPlan, signed_bytes(plan_msg(2, 2.0), kChanPlan, test_command_key(), 50));
  EXPECT_EQ(thrust_cycles(rig, 1, 150), 5);
  EXPECT_EQ(acks.find(1, 50)->outcome, A::OUTCOME_ACCEPTED);
  expect_accounted(rig);
}

// ARSN-3: a genuine command whose ARSN is behind the node's is answered replayed with the node's
// last accepted ARSN of the key, which is how a ground whose counter is behind recovers.
TEST(NodeAck, CommandBehindTheNodesArsnIsAnsweredWithTheNodesArsn) {
  Rig rig;
  AckRecorder acks(rig.lcm.get());
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 500));
  nav_cycle(rig, 0);
  send(rig, kChanPlan, signed_bytes(plan_msg(2, 3.0), kChanPlan, test_command_key(), 10));
  nav_cycle(rig, 1);
  rig.flush();
  const A* a = acks.find(1, 10);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->outcome, A::OUTCOME_REFUSED);
  EXPECT_EQ(a->reason, A::REASON_REPLAYED_ARSN);
  EXPECT_EQ(a->node_arsn, 500);
  expect_accounted(rig);
}

// TM-2: a message that fails its MAC is not the ground's: it gets no answer (an answer would
// let a forger make the ground believe its command was refused).
TEST(NodeAck, ForgedCommandsGetNoAnswer) {
  Rig rig;
  AckRecorder acks(rig.lcm.get());
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, test_key(1, 0x77), 5));   // bad MAC
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, test_key(99, 0x77), 6));  // unknown
  send(rig, kChanArm, signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 7));   // moved
  rig.pub.set_signing(false);
  evade_arm_t arm{};
  arm.utime = kT0;
  rig.pub.send(kChanArm, arm);  // unsigned
  rig.pub.set_signing(true);
  nav_cycle(rig, 0);
  rig.flush();
  EXPECT_TRUE(acks.acks().empty());
  EXPECT_EQ(rig.node.counts().auth_failed, 4);
  expect_accounted(rig);
}

// A flood of replayed genuine commands gets at most kCallbackAcksPerCycle answers a cycle, the
// rest counted unsent in the status: answering costs one HMAC, and its work stays bounded.
TEST(NodeAck, RefusalsAtReceiptAreAnsweredAtMostAFewPerCycleAndTheRestCounted) {
  Rig rig;
  AckRecorder acks(rig.lcm.get());
  const std::vector<std::uint8_t> b = signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 9);
  send(rig, kChanPlan, b);
  nav_cycle(rig, 0);
  for (int i = 0; i < 20; ++i) send(rig, kChanPlan, b);
  nav_cycle(rig, 1);
  rig.flush();
  EXPECT_EQ(acks.acks().size(), 1U + static_cast<std::size_t>(kCallbackAcksPerCycle));
  EXPECT_EQ(rig.node.acks_unsent(), 20 - kCallbackAcksPerCycle);
  EXPECT_EQ(rig.node.last_status().n_acks_unsent, 20 - kCallbackAcksPerCycle);
  EXPECT_EQ(rig.node.counts().replayed, 20);
  expect_accounted(rig);
}

// AUTH-4 with TM-2: with a state file, the answer to a plan comes after the write that put its
// ARSN on disk, and the answer to a key command after the write that put the key's new state
// there: the ground is never told of a change a crash could undo.
TEST(NodeAck, AnswersWaitUntilWhatTheyAnnounceIsOnDisk) {
  TempDir dir;
  ASSERT_FALSE(dir.path.empty());
  NodeSecurity sec = test_security();
  const SigningKey k4 = test_key(4, 0x44);
  ASSERT_EQ(sec.keys.add(k4.id, auth::KeyRole::kCommand, k4.key, auth::KeyState::kStandby), nullptr);
  sec.state_path = dir.path + "/state";
  sec.init_active_key = 1;
  Rig rig(NodeConfig{}, 100000, sec);
  AckRecorder acks(rig.lcm.get());
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 40));
  nav_cycle(rig, 0);  // admitted: its ARSN committed, waiting for the write
  rig.flush();
  EXPECT_TRUE(acks.acks().empty());
  ASSERT_EQ(rig.node.persist_auth_state(), 0);
  nav_cycle(rig, 1);  // executed and answered
  rig.flush();
  ASSERT_NE(acks.find(1, 40), nullptr);
  evade_key_cmd_t kc{};
  kc.utime = kT0;
  kc.seq = 41;
  kc.op = evade_key_cmd_t::OP_ACTIVATE;
  kc.key_id = 4;
  send(rig, kChanKeyCmd, signed_bytes(kc, kChanKeyCmd, test_command_key(), 41));
  nav_cycle(rig, 2);
  ASSERT_EQ(rig.node.persist_auth_state(), 0);
  nav_cycle(rig, 3);  // executed: key 4 active in memory, its answer waits for the write
  rig.flush();
  EXPECT_EQ(acks.find(1, 41), nullptr);
  ASSERT_EQ(rig.node.persist_auth_state(), 0);
  nav_cycle(rig, 4);
  rig.flush();
  const A* a = acks.find(1, 41);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->outcome, A::OUTCOME_ACCEPTED);
  EXPECT_EQ(a->detail, S::KEY_CMD_DONE);
  expect_accounted(rig);
}

// AUTH-4: when the state cannot be written, the commands waiting on it are answered
// not_persisted (the ground exits 3 with that reason) instead of being flown.
TEST(NodeAck, CommandsOfAFailedWriteAreAnsweredNotPersisted) {
  TempDir dir;
  ASSERT_FALSE(dir.path.empty());
  NodeSecurity sec = test_security();
  sec.state_path = dir.path + "/state";
  sec.init_active_key = 1;
  Rig rig(NodeConfig{}, 100000, sec);
  AckRecorder acks(rig.lcm.get());
  // A directory where the temporary file goes: no write can replace it, root's neither.
  ASSERT_EQ(mkdir((dir.path + "/state.tmp").c_str(), 0700), 0);
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 60));
  nav_cycle(rig, 0);
  EXPECT_LT(rig.node.persist_auth_state(), 0);
  EXPECT_EQ(thrust_cycles(rig, 1, 100), 0);
  rig.flush();
  const A* a = acks.find(1, 60);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->outcome, A::OUTCOME_REFUSED);
  EXPECT_EQ(a->reason, A::REASON_NOT_PERSISTED);
  EXPECT_EQ(rig.node.last_status().auth_state_persist_failures, 1);
  expect_accounted(rig);
}

}  // namespace
}  // namespace evade::guidance_lcm::test
