// Every datagram the node reads is in `received` and in exactly one outcome (docs/GUIDANCE_NODE.md
// NODE-IN-1, docs/SECURITY.md AUTH-5; issue 40 row 12): sim-clock ticks included, whatever
// happens to them (taken, refused by authentication, undecodable, repeated), and the commands
// and inputs still waiting when the node stops.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "command_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

TEST(NodeAccounting, SimClockTicksAreCountedLikeEveryInput) {
  NodeConfig cfg;
  cfg.lockstep = true;
  cfg.auth.clock_required = true;
  Rig rig(cfg);
  evade_sim_clock_t tick{};
  tick.utime = kT0;
  tick.seq = 1;
  rig.pub.send(kChanClock, tick);  // genuine: taken
  rig.pub.send(kChanClock, tick);  // the same tick re-sent (new ARSN, same seq): stale
  rig.pub.set_signing(false);
  tick.seq = 2;
  rig.pub.send(kChanClock, tick);  // unsigned: auth_failed
  rig.pub.set_signing(true);
  send(rig, kChanClock, signed_bytes(tick, kChanClock, test_key(2, 0x99), 50));  // bad MAC
  std::vector<std::uint8_t> junk(70, 0x05);  // key id 0x05050505: no such key
  rig.pub.send_bytes(kChanClock, junk.data(), static_cast<unsigned>(junk.size()));
  const std::vector<std::uint8_t> big(kMaxInputBytes + 1, 0);
  rig.pub.send_bytes(kChanClock, big.data(), static_cast<unsigned>(big.size()));  // oversize
  std::int64_t t = 0;
  ASSERT_EQ(rig.node.wait_for_tick(1000, &t), 1);
  rig.node.run_cycle(t);
  rig.node.drain();
  EXPECT_EQ(rig.node.received(Input::kClock), 6);
  EXPECT_EQ(rig.node.ticks_received(), 1);
  EXPECT_EQ(reason(rig, Reason::kDuplicateSeq), 1);
  EXPECT_EQ(reason(rig, Reason::kUnsigned), 1);
  EXPECT_EQ(reason(rig, Reason::kBadMac), 1);
  EXPECT_EQ(reason(rig, Reason::kUnknownKey), 1);
  EXPECT_EQ(reason(rig, Reason::kOversize), 1);
  EXPECT_EQ(rig.node.counts().consumed, 1);
  expect_accounted(rig);
}

// A command admitted but still waiting for its ARSN to reach the disk, and inputs queued after
// the last cycle, when the node stops: counted dropped (stopped), so the final report's
// identity holds.
TEST(NodeAccounting, CommandsAndInputsWaitingAtStopAreCounted) {
  TempDir dir;
  ASSERT_FALSE(dir.path.empty());
  NodeSecurity sec = test_security();
  sec.state_path = dir.path + "/state";
  sec.init_active_key = 1;
  Rig rig(NodeConfig{}, 100000, sec);
  rig.pub.send(kChanPlan, plan_msg(1));
  nav_cycle(rig, 0);  // admitted: waits for the write that never comes
  rig.send_good(kT0 + kPeriodUs, 2);
  rig.pub.send(kChanPlan, plan_msg(2, 2.0));
  rig.node.drain();  // received, not yet cycled
  EXPECT_NE(rig.node.counts().received, rig.node.counts().accounted());
  rig.node.stop();
  EXPECT_EQ(reason(rig, Reason::kStopped), 4);  // two commands, nav and angles
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, 0);
  expect_accounted(rig);
}

}  // namespace
}  // namespace evade::guidance_lcm::test
