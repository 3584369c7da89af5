// The guidance node's cycle around the law (docs/GUIDANCE_NODE.md NODE-OUT-1, NODE-RT-3,
// NODE-IN-5): a drain handles at most max_drain_per_cycle messages, the status goes out every
// status_divider cycles with the loop's timing figures, commands and status go to the output
// LCM when one is given (replay into a log), and the end of a replayed log is reported as an
// LCM error (-1) by both the fixed-rate drain and the lockstep wait.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "node_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

void send_nav(Rig& rig, std::int64_t t_us, std::int64_t seq) {
  evade_nav_state_t n{};
  rig.enc.nav_at(t_us, &n);
  n.seq = seq;
  rig.pub.send(kChanNav, n);
}

// A drain bounded in time as well: with node.max_drain_s far below what 4,000 messages take to
// dispatch, one drain stops early (the clock is read every 16 messages: after 15, 31, ...) and
// the rest waits for the next.
TEST(NodeCycle, DrainStopsAtItsWallTimeBoundAndLeavesTheRestForTheNext) {
  NodeConfig cfg;
  cfg.max_drain_s = 1e-6;
  cfg.queue_capacity = 4096;
  Rig rig(cfg);
  for (std::int64_t s = 1; s <= 4000; ++s) send_nav(rig, 1000000, s);
  const int first = rig.node.drain();
  EXPECT_GE(first, 15);
  EXPECT_LT(first, 4000);
  int total = first;
  for (int i = 0; i < 4000 && total < 4000; ++i) total += rig.node.drain();
  EXPECT_EQ(total, 4000);
  EXPECT_EQ(rig.node.counts().received, 4000);
}

TEST(NodeCycle, DrainHandlesAtMostMaxDrainPerCycleAndLeavesTheRestForTheNext) {
  NodeConfig cfg;
  cfg.max_drain_per_cycle = 2;
  Rig rig(cfg);
  for (std::int64_t s = 1; s <= 5; ++s) send_nav(rig, 1000000, s);
  EXPECT_EQ(rig.node.drain(), 2);
  EXPECT_EQ(rig.node.counts().received, 2);
  EXPECT_EQ(rig.node.drain(), 2);
  EXPECT_EQ(rig.node.drain(), 1);
  EXPECT_EQ(rig.node.drain(), 0);
  EXPECT_EQ(rig.node.counts().received, 5);
}

TEST(NodeCycle, StatusGoesOutEveryStatusDividerCycles) {
  NodeConfig cfg;
  cfg.status_divider = 4;
  Rig rig(cfg);
  std::int64_t t = 1000000;
  for (int k = 1; k <= 11; ++k, t += kPeriodUs) {
    rig.good_cycle(t, k);
    const evade_guidance_status_t& s = rig.node.last_status();
    const int sent = k / 4;  // after cycles 4 and 8
    EXPECT_EQ(s.seq, sent) << "cycle " << k;
    if (sent > 0) {
      EXPECT_EQ(s.cycles, 4 * sent) << "cycle " << k;
      EXPECT_EQ(s.utime, 1000000 + (4 * sent - 1) * kPeriodUs) << "cycle " << k;
    }
  }
  EXPECT_EQ(rig.node.cycles(), 11);
}

// NODE-RT-3: what the loop records goes out in the next status: p50 and p99 over the
// window, the max since start, and the overruns.
TEST(NodeCycle, RecordedTimingFiguresGoOutInTheStatus) {
  Rig rig;
  for (double us : {120.0, 80.0, 100.0, 90.0, 400.0}) rig.node.record_compute_time(us);
  rig.node.record_wakeup_latency(35.0);
  rig.node.record_overrun();
  rig.node.record_overrun();
  rig.good_cycle(1000000, 1);
  const evade_guidance_status_t& s = rig.node.last_status();
  EXPECT_EQ(s.cycle_p50_us, 100.0);
  EXPECT_EQ(s.cycle_p99_us, 400.0);
  EXPECT_EQ(s.cycle_max_us, 400.0);
  EXPECT_EQ(s.overruns, 2);
  EXPECT_EQ(rig.node.compute_stats().count(), 5);
  EXPECT_EQ(rig.node.wakeup_stats().max_us(), 35.0);
  EXPECT_EQ(rig.node.wakeup_stats().count(), 1);
}

// Replay (NODE-IO-*): inputs read from one LCM, command and status published on another.
TEST(NodeCycle, CommandAndStatusGoToTheOutputLcmWhenGiven) {
  LcmPtr in(lcm_create("memq://"));
  LcmPtr out(lcm_create("memq://"));
  ASSERT_TRUE(in && out);
  GuidanceNode node(in.get(), NodeConfig{}, out.get());
  CommandRecorder on_in(in.get(), 16);
  CommandRecorder on_out(out.get(), 16);
  for (int k = 0; k < 3; ++k) node.run_cycle(1000000 + k * kPeriodUs);
  while (lcm_handle_timeout(out.get(), 0) > 0) {
  }
  EXPECT_EQ(node.drain(), 0) << "nothing published on the input LCM";
  EXPECT_TRUE(on_in.commands().empty());
  ASSERT_EQ(on_out.commands().size(), 3u);
  EXPECT_EQ(on_out.commands()[2].seq, 3);
  EXPECT_EQ(node.last_command().seq, 3);
  EXPECT_EQ(node.config().status_divider, 1);
}

// A log of `n` nav messages written with LCM's file provider.
std::string write_nav_log(const std::string& name, int n) {
  const std::string path = ::testing::TempDir() + name;
  std::remove(path.c_str());
  LcmPtr w(lcm_create(("file://" + path + "?mode=w").c_str()));
  EXPECT_TRUE(w);
  Encounter enc;
  std::uint8_t buf[512];
  for (int k = 0; k < n; ++k) {
    evade_nav_state_t m{};
    enc.nav_at(1000000 + k * kPeriodUs, &m);
    m.seq = k + 1;
    const int size = m.encode(buf, 0, sizeof(buf));
    EXPECT_EQ(lcm_publish(w.get(), kChanNav, buf, static_cast<unsigned>(size)), 0);
  }
  return path;
}

TEST(NodeCycle, EndOfAReplayedLogIsAnLcmErrorForDrainAndForTheLockstepWait) {
  const std::string path = write_nav_log("node_cycle_eol.log", 3);
  {
    LcmPtr r(lcm_create(("file://" + path + "?speed=0").c_str()));
    ASSERT_TRUE(r);
    GuidanceNode node(r.get(), NodeConfig{});
    int rc = 0;
    for (int i = 0; i < 100 && rc >= 0; ++i) rc = node.drain();
    EXPECT_EQ(rc, -1) << "end of log not reported";
    EXPECT_EQ(node.counts().received, 3) << "every logged message handled before the end";
  }
  {
    LcmPtr r(lcm_create(("file://" + path + "?speed=0").c_str()));
    ASSERT_TRUE(r);
    NodeConfig cfg;
    cfg.lockstep = true;
    GuidanceNode node(r.get(), cfg);
    std::int64_t tick_utime = -7;
    EXPECT_EQ(node.wait_for_tick(5000, &tick_utime), -1) << "a log without ticks ends";
    EXPECT_EQ(tick_utime, -7);
    EXPECT_EQ(node.counts().received, 3) << "inputs before the end are queued";
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace evade::guidance_lcm::test
