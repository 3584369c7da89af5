// Only the ground commands the thrusters (docs/SECURITY.md AUTH-1..3, KEY-2): the node over
// memq:// against an attacker on the bus. Every attack is refused before anything in the
// message is used, counted under its reason, and leaves the node's state and its thrust
// unchanged; the accounting identity holds throughout. The genuine ground (the rig's publisher,
// signing with the command key) still flies its plans and rotates keys.
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "command_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

using S = evade_guidance_status_t;

// An attack on the plan channel: nothing flies, the reason is counted once, identity holds.
void expect_refused_plan(Rig& rig, Reason why, Verdict verdict = Verdict::kAuthFailed) {
  EXPECT_EQ(thrust_cycles(rig, 0, 100), 0);
  EXPECT_EQ(reason(rig, why), 1) << reason_name(why);
  EXPECT_EQ(verdict == Verdict::kReplayed ? rig.node.counts().replayed
                                          : rig.node.counts().auth_failed, 1);
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, 0);
  EXPECT_EQ(rig.node.last_status().plan_ack_id, 0);
  expect_accounted(rig);
}

TEST(NodeAuth, SignedPlanFliesAndIsAcknowledged) {
  Rig rig;
  rig.pub.send(kChanPlan, plan_msg(7));
  EXPECT_EQ(thrust_cycles(rig, 0, 100), 5);
  const S& s = rig.node.last_status();
  EXPECT_EQ(s.plan_ack_id, 7);
  EXPECT_EQ(s.plan_ack_result, S::PLAN_REJECT_NONE);
  EXPECT_EQ(s.auth_last_key_id, 1);
  EXPECT_EQ(s.auth_required, S::AUTH_PLAN | S::AUTH_ARM | S::AUTH_KEY_CMD | S::AUTH_CONJUNCTION |
                                S::AUTH_CAM_DECISION);
  EXPECT_EQ(s.n_auth_failed, 0);
  expect_accounted(rig);
}

TEST(NodeAuth, UnsignedPlanIsRefused) {
  Rig rig;
  rig.pub.set_signing(false);
  rig.pub.send(kChanPlan, plan_msg(1));
  rig.pub.set_signing(true);
  expect_refused_plan(rig, Reason::kUnsigned);
}

TEST(NodeAuth, PlanSignedWithAnUnknownKeyIsRefused) {
  Rig rig;
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, test_key(99, 0x77), 5));
  expect_refused_plan(rig, Reason::kUnknownKey);
}

TEST(NodeAuth, PlanWithTheGroundsKeyIdButAnotherKeyIsRefused) {
  Rig rig;
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, test_key(1, 0x77), 5));
  expect_refused_plan(rig, Reason::kBadMac);
}

TEST(NodeAuth, PlanSignedForAnotherChannelIsRefused) {
  Rig rig;
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanArm, test_command_key(), 5));
  expect_refused_plan(rig, Reason::kBadMac);
}

TEST(NodeAuth, PlanSignedWithTheSensorKeyIsRefused) {
  Rig rig;
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, test_sensor_key(), 5));
  expect_refused_plan(rig, Reason::kWrongKeyRole);
}

TEST(NodeAuth, ModifiedSignedPlanIsRefused) {
  Rig rig;
  std::vector<std::uint8_t> b = signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 5);
  b[30] ^= 0x01;  // inside impulse_t_s
  send(rig, kChanPlan, b);
  expect_refused_plan(rig, Reason::kBadMac);
}

// The bytes of NodePlan.OversizedAndUndecodablePlanBytesAreRejectedAndAccounted, with the
// plan channel's authentication on: refused before the decoder sees them.
TEST(NodeAuth, JunkAndTrailingBytesAreRefusedBeforeTheDecoder) {
  Rig rig;
  const std::uint8_t junk[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  rig.pub.send_bytes(kChanPlan, junk, sizeof(junk));
  std::vector<std::uint8_t> b = signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 5);
  b.push_back(0);  // one trailing byte after the MAC: the trailer read is shifted by a byte,
  send(rig, kChanPlan, b);  // its key id 00 00 01 00 = 256 is no key
  b.pop_back();
  b[20] ^= 0x40;  // a flipped bit in the body: the key id is right, the MAC is not
  send(rig, kChanPlan, b);
  EXPECT_EQ(thrust_cycles(rig, 0, 100), 0);
  EXPECT_EQ(reason(rig, Reason::kTooShortForTrailer), 1);
  EXPECT_EQ(reason(rig, Reason::kUnknownKey), 1);
  EXPECT_EQ(reason(rig, Reason::kBadMac), 1);
  EXPECT_EQ(reason(rig, Reason::kDecodeFailed), 0);
  expect_accounted(rig);
}

TEST(NodeAuth, SignedPlanResentByteForByteIsAReplay) {
  Rig rig;
  const std::vector<std::uint8_t> b = signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 5);
  send(rig, kChanPlan, b);
  EXPECT_EQ(thrust_cycles(rig, 0, 100), 5);
  send(rig, kChanPlan, b);
  EXPECT_EQ(thrust_cycles(rig, 100, 200), 0);
  EXPECT_EQ(reason(rig, Reason::kReplayedArsn), 1);
  EXPECT_EQ(rig.node.counts().replayed, 1);
  EXPECT_EQ(rig.node.last_status().n_replayed, 1);
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, 1);
  expect_accounted(rig);
}

TEST(NodeAuth, SignedPlanWithALowerArsnIsAReplay) {
  Rig rig;
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 50));
  EXPECT_EQ(thrust_cycles(rig, 0, 100), 5);
  send(rig, kChanPlan, signed_bytes(plan_msg(2, 3.0), kChanPlan, test_command_key(), 49));
  EXPECT_EQ(thrust_cycles(rig, 100, 200), 0);
  EXPECT_EQ(reason(rig, Reason::kReplayedArsn), 1);
  EXPECT_EQ(rig.node.last_status().plan_ack_id, 1);
  expect_accounted(rig);
}

// A forged plan with ARSN = INT64_MAX must not advance the ARSN (the MAC is checked first):
// the ground's next plan still flies.
TEST(NodeAuth, ForgedPlanWithMaximalArsnDoesNotLockOutTheGround) {
  Rig rig;
  evade_burn_plan_t forged = plan_msg(std::numeric_limits<std::int64_t>::max());
  send(rig, kChanPlan, signed_bytes(forged, kChanPlan, test_key(1, 0x99),
                                    std::numeric_limits<std::int64_t>::max()));
  EXPECT_EQ(thrust_cycles(rig, 0, 10), 0);
  EXPECT_EQ(reason(rig, Reason::kBadMac), 1);
  rig.pub.send(kChanPlan, plan_msg(3, 1.5));  // genuine, ARSN 1
  EXPECT_EQ(thrust_cycles(rig, 10, 120), 5);
  EXPECT_EQ(rig.node.last_status().plan_ack_id, 3);
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, 1);
  expect_accounted(rig);
}

TEST(NodeAuth, UnsignedArmAndDisarmAreRefused) {
  NodeConfig cfg;
  cfg.guidance.armed = false;
  Rig rig(cfg);
  evade_arm_t arm{};
  arm.utime = kT0;
  arm.seq = 1;
  arm.armed = 1;
  rig.pub.set_signing(false);
  rig.pub.send(kChanArm, arm);
  rig.pub.set_signing(true);
  nav_cycle(rig, 0);
  EXPECT_FALSE(rig.node.armed());
  rig.pub.send(kChanArm, arm);  // the ground's, signed
  nav_cycle(rig, 1);
  EXPECT_TRUE(rig.node.armed());
  arm.armed = 0;
  arm.seq = 2;
  arm.utime = kT0 + 2 * kPeriodUs;
  rig.pub.set_signing(false);
  rig.pub.send(kChanArm, arm);
  nav_cycle(rig, 2);
  EXPECT_TRUE(rig.node.armed()) << "an unsigned disarm must not cancel the ground's arm";
  EXPECT_EQ(reason(rig, Reason::kUnsigned), 2);
  expect_accounted(rig);
}

// Sensors required: a spoofed nav (the genuine one with seq + 1 and a rotated orbit) and a
// single angles message from the attacker are refused; the law never sees them.
TEST(NodeAuth, SpoofedNavAndAnglesAreRefusedWhenSensorsAreRequired) {
  NodeConfig cfg;
  cfg.auth.nav_required = cfg.auth.angles_required = true;
  Rig rig(cfg);
  rig.pub.send(kChanPlan, plan_msg(1, 1.0));
  int thrust = 0;
  for (int k = 0; k < 100; ++k) {
    const std::int64_t t = kT0 + k * kPeriodUs;
    evade_nav_state_t nav{};
    rig.enc.nav_at(t, &nav);
    nav.seq = 2 * k + 1;
    rig.pub.send(kChanNav, nav);  // genuine, signed with the sensor key
    evade_nav_state_t spoof = nav;
    spoof.seq = nav.seq + 1;
    spoof.r_eci_m[0] = -nav.r_eci_m[0];  // rotated orbit
    spoof.v_eci_mps[1] = -nav.v_eci_mps[1];
    rig.pub.set_signing(false);
    rig.pub.send(kChanNav, spoof);
    if (k == 10) {
      evade_angles_t a{};
      rig.enc.angles_at(t, &a);
      a.seq = 1;
      rig.pub.send(kChanAngles, a);
    }
    rig.pub.set_signing(true);
    const evade_thrust_cmd_t& c = rig.cycle(t);
    EXPECT_NE(c.mode, evade_thrust_cmd_t::MODE_SAFE) << "cycle " << k;
    if (c.accel_mps2 > 0.0) {  // along +S of the genuine orbit, never the spoofed one's
      const Vec3 r(nav.r_eci_m[0], nav.r_eci_m[1], nav.r_eci_m[2]);
      const Vec3 v(nav.v_eci_mps[0], nav.v_eci_mps[1], nav.v_eci_mps[2]);
      const Vec3 s_axis = r.cross(v).cross(r).normalized();
      EXPECT_GT(s_axis.dot(Vec3(c.u_eci[0], c.u_eci[1], c.u_eci[2])), 1.0 - 1e-12) << "cycle " << k;
      ++thrust;
    }
  }
  EXPECT_EQ(thrust, 5);
  EXPECT_EQ(reason(rig, Reason::kUnsigned), 101);  // 100 navs + 1 angles
  EXPECT_EQ(rig.node.counts().auth_failed, 101);
  EXPECT_EQ(rig.node.last_status().plan_end, S::PLAN_END_COMPLETED);
  EXPECT_EQ(rig.node.watchdog_cycles(), 0);
  expect_accounted(rig);
}

TEST(NodeAuth, SensorMessagesSignedWithTheCommandKeyAreRefused) {
  NodeConfig cfg;
  cfg.auth.nav_required = true;
  Rig rig(cfg);
  evade_nav_state_t nav{};
  rig.enc.nav_at(kT0, &nav);
  nav.seq = 1;
  send(rig, kChanNav, signed_bytes(nav, kChanNav, test_command_key(), 9));
  rig.cycle(kT0);
  EXPECT_EQ(reason(rig, Reason::kWrongKeyRole), 1);
  expect_accounted(rig);
}

// KEY-2: the ground activates its second key with the first, retires the first with the
// second; the retired key's plans are refused, the new key's fly.
TEST(NodeAuth, KeyRotationRetiresTheOldKey) {
  NodeSecurity sec = test_security();
  const SigningKey k3 = test_key(4, 0x44);
  ASSERT_EQ(sec.keys.add(k3.id, auth::KeyRole::kCommand, k3.key, auth::KeyState::kStandby), nullptr);
  Rig rig(NodeConfig{}, 100000, sec);
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, k3, 10));  // standby: refused
  nav_cycle(rig, 0);
  EXPECT_EQ(reason(rig, Reason::kStandbyKey), 1);
  evade_key_cmd_t kc{};
  kc.utime = kT0;
  kc.seq = 1;
  kc.op = evade_key_cmd_t::OP_ACTIVATE;
  kc.key_id = 4;
  rig.pub.send(kChanKeyCmd, kc);  // signed with key 1
  nav_cycle(rig, 1);
  EXPECT_EQ(rig.node.last_status().key_cmd_last_result, S::KEY_CMD_DONE);
  EXPECT_EQ(rig.node.last_status().auth_active_command_keys, 2);
  kc.seq = 2;
  kc.op = evade_key_cmd_t::OP_RETIRE;
  kc.key_id = 1;
  send(rig, kChanKeyCmd, signed_bytes(kc, kChanKeyCmd, k3, 11));
  nav_cycle(rig, 2);
  EXPECT_EQ(rig.node.last_status().key_cmd_last_seq, 2);
  EXPECT_EQ(rig.node.last_status().key_cmd_last_result, S::KEY_CMD_DONE);
  EXPECT_EQ(rig.node.last_status().auth_active_command_keys, 1);
  rig.pub.send(kChanPlan, plan_msg(2, 1.0));  // key 1, now retired
  EXPECT_EQ(thrust_cycles(rig, 3, 80), 0);
  EXPECT_EQ(reason(rig, Reason::kRetiredKey), 1);
  send(rig, kChanPlan, signed_bytes(plan_msg(3, 2.0), kChanPlan, k3, 12));
  EXPECT_EQ(thrust_cycles(rig, 80, 160), 5);
  EXPECT_EQ(rig.node.last_status().plan_ack_id, 3);
  // Retiring the last active command key is refused.
  kc.seq = 3;
  kc.key_id = 4;
  send(rig, kChanKeyCmd, signed_bytes(kc, kChanKeyCmd, k3, 13));
  nav_cycle(rig, 160);
  EXPECT_EQ(rig.node.last_status().key_cmd_last_result, S::KEY_CMD_LAST_KEY);
  expect_accounted(rig);
}

// Undecodable bytes that pass authentication (signed by the ground, but not a command of the
// channel's type) are refused at decode on every command channel.
TEST(NodeAuth, SignedBytesThatAreNotTheChannelsTypeFailToDecode) {
  Rig rig;
  evade_nav_state_t nav{};
  rig.enc.nav_at(kT0, &nav);
  send(rig, kChanPlan, signed_bytes(nav, kChanPlan, test_command_key(), 10));
  send(rig, kChanArm, signed_bytes(nav, kChanArm, test_command_key(), 11));
  send(rig, kChanKeyCmd, signed_bytes(nav, kChanKeyCmd, test_command_key(), 12));
  nav_cycle(rig, 0);
  EXPECT_EQ(reason(rig, Reason::kDecodeFailed), 3);
  expect_accounted(rig);
}

// KEY-2: a retire command and a plan signed with the key it retires, arriving in the same drain
// in that order: the plan was authentic when it arrived, but the key no longer commands when
// the plan's turn comes.
TEST(NodeAuth, PlanOfAKeyRetiredJustBeforeItIsRefused) {
  NodeSecurity sec = test_security();
  const SigningKey k4 = test_key(4, 0x44);
  ASSERT_EQ(sec.keys.add(k4.id, auth::KeyRole::kCommand, k4.key, auth::KeyState::kActive), nullptr);
  Rig rig(NodeConfig{}, 100000, sec);
  evade_key_cmd_t kc{};
  kc.utime = kT0;
  kc.seq = 1;
  kc.op = evade_key_cmd_t::OP_RETIRE;
  kc.key_id = 4;
  rig.pub.send(kChanKeyCmd, kc);  // signed with key 1
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, k4, 5));
  EXPECT_EQ(thrust_cycles(rig, 0, 100), 0);
  EXPECT_EQ(rig.node.last_status().key_cmd_last_result, S::KEY_CMD_DONE);
  EXPECT_EQ(reason(rig, Reason::kRetiredKey), 1);
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, 0);
  expect_accounted(rig);
}

// AUTH-2 with the arm channel's policy off (a bench without keys): arms are admitted through the
// seq and utime rules of every input. With it on, a signed arm is ordered by its ARSN alone:
// one stamped an hour ahead of the node's clock or 0.7 s behind it is accepted (issue 40,
// row 9: a ground whose clock is wrong can still disarm, and one slightly behind can arm).
TEST(NodeAuth, ArmWithThePolicyOffUsesTheSeqRulesAndSignedArmsIgnoreTheGroundsClock) {
  NodeConfig cfg;
  cfg.auth.arm_required = false;
  Rig rig(cfg);
  evade_arm_t arm{};
  arm.utime = kT0;
  arm.seq = 5;
  arm.armed = 0;
  rig.pub.set_signing(false);
  rig.pub.send(kChanArm, arm);
  nav_cycle(rig, 0);
  EXPECT_FALSE(rig.node.armed());
  rig.pub.send(kChanArm, arm);  // the same seq again: stale, not used
  arm.armed = 1;
  rig.pub.send(kChanArm, arm);
  nav_cycle(rig, 1);
  EXPECT_FALSE(rig.node.armed());
  EXPECT_EQ(reason(rig, Reason::kDuplicateSeq), 2);
  arm.seq = 6;
  arm.utime = kT0 + 10'000'000;  // unsigned and from the future: refused
  rig.pub.send(kChanArm, arm);
  arm.seq = 7;
  arm.utime = kT0 - 10'000'000;  // unsigned and stale: refused
  rig.pub.send(kChanArm, arm);
  nav_cycle(rig, 2);
  EXPECT_FALSE(rig.node.armed());
  EXPECT_EQ(reason(rig, Reason::kFromFuture), 1);
  EXPECT_EQ(reason(rig, Reason::kStaleUtime), 1);
  rig.pub.set_signing(true);
  expect_accounted(rig);

  Rig on;  // policy on: signed disarm an hour ahead, signed arm 0.7 s behind
  arm.armed = 0;
  arm.utime = kT0 + 3'600'000'000LL;
  on.pub.send(kChanArm, arm);
  nav_cycle(on, 0);
  EXPECT_FALSE(on.node.armed());
  arm.armed = 1;
  arm.utime = kT0 + kPeriodUs - 700'000;
  on.pub.send(kChanArm, arm);
  nav_cycle(on, 1);
  EXPECT_TRUE(on.node.armed());
  EXPECT_EQ(reason(on, Reason::kFromFuture), 0);
  EXPECT_EQ(reason(on, Reason::kStaleUtime), 0);
  expect_accounted(on);
}

// KEY-2: a key command with an unknown op, one naming a key that is not loaded, one stamped far
// ahead (ordered by its ARSN, like an arm: applied), oversize bytes on a command channel;
// persisting with nothing to write is a no-op.
TEST(NodeAuth, MalformedKeyCommandsAreRefusedAndCounted) {
  NodeSecurity sec = test_security();
  const SigningKey k4 = test_key(4, 0x44);
  ASSERT_EQ(sec.keys.add(k4.id, auth::KeyRole::kCommand, k4.key, auth::KeyState::kStandby), nullptr);
  Rig rig(NodeConfig{}, 100000, sec);
  evade_key_cmd_t kc{};
  kc.utime = kT0;
  kc.seq = 1;
  kc.op = 9;
  kc.key_id = 1;
  rig.pub.send(kChanKeyCmd, kc);
  nav_cycle(rig, 0);
  EXPECT_EQ(rig.node.last_status().key_cmd_last_result, S::KEY_CMD_BAD_OP);
  kc.seq = 2;
  kc.op = evade_key_cmd_t::OP_ACTIVATE;
  kc.key_id = 42;
  rig.pub.send(kChanKeyCmd, kc);
  nav_cycle(rig, 1);
  EXPECT_EQ(rig.node.last_status().key_cmd_last_seq, 2);
  EXPECT_EQ(rig.node.last_status().key_cmd_last_result, S::KEY_CMD_UNKNOWN_KEY);
  kc.seq = 3;
  kc.key_id = 4;
  kc.utime = kT0 + 3'600'000'000LL;
  rig.pub.send(kChanKeyCmd, kc);
  nav_cycle(rig, 2);
  EXPECT_EQ(reason(rig, Reason::kFromFuture), 0);
  EXPECT_EQ(rig.node.last_status().key_cmd_last_seq, 3);
  EXPECT_EQ(rig.node.last_status().key_cmd_last_result, S::KEY_CMD_DONE);
  const std::vector<std::uint8_t> big(kMaxCommandBytes + 1, 0x11);
  rig.pub.send_bytes(kChanKeyCmd, big.data(), static_cast<unsigned>(big.size()));
  nav_cycle(rig, 3);
  EXPECT_EQ(reason(rig, Reason::kOversize), 1);
  EXPECT_EQ(rig.node.persist_auth_state(), 0);  // memory only: nothing to write
  expect_accounted(rig);
}

}  // namespace
}  // namespace evade::guidance_lcm::test
