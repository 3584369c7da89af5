// NODE-RT-1: after initialization the node cycle allocates nothing. Global operator new is
// replaced by a counting version; over 10,000 cycles on memq:// (publish nav + angles with
// preallocated buffers, drain, validate, step the law, encode, publish command and status,
// the test's own command subscriber handles them) the count must stay 0.
// Scope: C++ operator new only. LCM's C library mallocs a copy of each message inside the
// memq/udpm providers; that is outside our code (see docs/GUIDANCE_NODE.md).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <limits>
#include <new>
#include <vector>

#include <unistd.h>

#include <cstdio>
#include <string>

#include "evade/evade_burn_plan_t.hpp"
#include "conjunction_harness.hpp"

namespace {
std::atomic<long> g_news{0};
std::atomic<bool> g_counting{false};
}  // namespace

void* operator new(std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_news.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
// GCC warns that free() does not match new; here they do match (our new uses malloc).
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new[](std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_news.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  if (g_counting.load(std::memory_order_relaxed)) g_news.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n == 0 ? 1 : n);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  if (g_counting.load(std::memory_order_relaxed)) g_news.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n == 0 ? 1 : n);
}
void* operator new(std::size_t n, std::align_val_t a) {
  if (g_counting.load(std::memory_order_relaxed)) g_news.fetch_add(1, std::memory_order_relaxed);
  const std::size_t al = static_cast<std::size_t>(a);
  if (void* p = std::aligned_alloc(al, (n + al - 1) / al * al)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n, std::align_val_t a) { return operator new(n, a); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace evade::guidance_lcm::test {
namespace {

TEST(NodeAllocation, TenThousandCyclesAllocateNothing) {
  constexpr int kCycles = 10000;
  Rig rig(NodeConfig{}, kCycles + 100);
  std::int64_t t = 1000000;
  std::int64_t seq = 1;
  for (int k = 0; k < 20; ++k, t += kPeriodUs) rig.good_cycle(t, seq++);  // warm-up

  // The hook itself works (else the test below could not fail).
  g_news = 0;
  g_counting = true;
  {
    std::vector<double> probe(100);
    volatile double* keep = probe.data();
    (void)keep;
  }
  g_counting = false;
  ASSERT_EQ(g_news.load(), 1) << "counting operator new is not in effect";

  g_news = 0;
  g_counting = true;
  long thrusting = 0;
  for (int k = 0; k < kCycles; ++k, t += kPeriodUs) {
    // Mix in the fault paths too: a NaN message and a wrong-type message now and then.
    if (k % 50 == 7) {
      evade_angles_t a{};
      rig.enc.angles_at(t, &a);
      a.seq = 1;
      a.elevation_rad = std::numeric_limits<double>::quiet_NaN();
      rig.pub.send(kChanAngles, a);
    }
    if (k % 50 == 9) {
      evade_nav_state_t n{};
      rig.enc.nav_at(t, &n);
      rig.pub.send(kChanAngles, n);
    }
    if (rig.good_cycle(t, seq++).accel_mps2 > 0.0) ++thrusting;
  }
  g_counting = false;
  EXPECT_EQ(g_news.load(), 0) << "operator new called in the node cycle";
  EXPECT_EQ(rig.node.cycles(), 20 + kCycles);
  EXPECT_EQ(rig.node.counts().accounted(), rig.pub.published());
  EXPECT_GT(rig.node.counts().rejected, 0);
  EXPECT_GT(thrusting, 0) << "the cycles exercised the evading path";
}

// NODE-RT-1 with authentication (docs/SECURITY.md AUTH-6, TM-1): every sensor message signed
// and verified, signed plans, key commands, replays and forgeries now and then, every
// acknowledgement and every status signed with the telemetry key, and the persisted state
// written between cycles (into a scratch file): still no allocation.
TEST(NodeAllocation, AuthenticatedCyclesAndTheStateWriteAllocateNothing) {
  constexpr int kCycles = 5000;
  char dir_tmpl[] = "/tmp/evade-alloc-XXXXXX";
  ASSERT_NE(mkdtemp(dir_tmpl), nullptr);
  const std::string state = std::string(dir_tmpl) + "/state";
  NodeConfig cfg;
  cfg.auth.nav_required = cfg.auth.angles_required = true;
  NodeSecurity sec = test_security();
  sec.state_path = state;
  sec.init_active_key = 1;
  Rig rig(cfg, kCycles + 100, sec);
  std::uint8_t replay[1024];
  int replay_size = 0;
  std::int64_t t = 1000000;
  std::int64_t seq = 1;
  for (int k = 0; k < 20; ++k, t += kPeriodUs) rig.good_cycle(t, seq++);  // warm-up
  evade_burn_plan_t plan{};
  plan.n_impulses = 1;
  plan.impulse_dv_rsw_mps[0][1] = 0.01;
  g_news = 0;
  g_counting = true;
  for (int k = 0; k < kCycles; ++k, t += kPeriodUs) {
    if (k % 100 == 3) {  // a signed plan (rejected or accepted: the path is what counts)
      plan.utime = plan.epoch_utime = t;
      plan.seq = k;
      plan.impulse_t_s[0] = 0.5;
      rig.pub.send(kChanPlan, plan);
    }
    if (k % 100 == 5) {  // a forged one: signing off
      rig.pub.set_signing(false);
      rig.pub.send(kChanPlan, plan);
      rig.pub.send(kChanNav, plan);  // wrong type, unsigned, on a sensor channel
      rig.pub.set_signing(true);
    }
    if (k % 100 == 7) {  // a key command (activating the active key: done, answered)
      evade_key_cmd_t kc{};
      kc.utime = t;
      kc.seq = k;
      kc.op = evade_key_cmd_t::OP_ACTIVATE;
      kc.key_id = 1;
      rig.pub.send(kChanKeyCmd, kc);
    }
    if (k % 100 == 9) {  // a replay of signed bytes: refused at receipt, answered
      if (replay_size == 0) {
        const SigningKey ck = test_command_key();
        evade_burn_plan_t p = plan;
        replay_size = encode_signed(&p, kChanPlan, ck, 1, replay, static_cast<int>(sizeof(replay)));
      }
      rig.pub.send_bytes(kChanPlan, replay, static_cast<unsigned>(replay_size));
    }
    rig.good_cycle(t, seq++);
    EXPECT_EQ(rig.node.persist_auth_state(), 0);
  }
  g_counting = false;
  EXPECT_EQ(g_news.load(), 0) << "operator new called in the authenticated node cycle";
  EXPECT_EQ(rig.node.counts().accounted(), rig.pub.published());
  EXPECT_GT(rig.node.counts().auth_failed, 0);
  EXPECT_GT(rig.node.counts().consumed, 2 * kCycles) << "signed sensor messages were used";
  EXPECT_GT(rig.node.plan_executor().status().accepted, 0);
  EXPECT_GE(rig.node.acks_published(), 3 * (kCycles / 100)) << "plans, key commands, replays answered";
  EXPECT_EQ(rig.node.acks_unsent(), 0);
  EXPECT_GT(rig.node.counts().replayed, 0);
  (void)std::remove(state.c_str());
  (void)rmdir(dir_tmpl);
}

// NODE-RT-1 with the onboard conjunction response (docs/AUTONOMY.md AUT-8): a signed
// conjunction received, its assessment run by the worker (this thread, in its place) and
// collected, the proposal signed and published every cycle it changes and once a second, a
// newer version superseding it and re-planned, the burn loaded at the veto deadline and flown:
// no allocation in the cycle nor in the worker's assessment.
TEST(NodeAllocation, PlanningAConjunctionAndFlyingItsBurnAllocateNothing) {
  NodeConfig cfg;
  Rig rig(cfg, 1000);
  OrbitNav nav(node_event());
  std::int64_t seq = 0;
  auto step = [&](std::int64_t t) {
    rig.pub.send(kChanNav, nav.at(t, ++seq));
    return rig.cycle(t).accel_mps2 > 0.0 ? 1 : 0;
  };
  for (int k = 0; k < 20; ++k) step(kT0 - (20 - k) * kPeriodUs);  // warm-up
  g_news = 0;
  g_counting = true;
  rig.pub.send(kChanConjunction, conjunction_msg(node_event(7, 1), 1));
  step(kT0);
  const bool ran1 = rig.node.plan_once();
  rig.pub.send(kChanConjunction, conjunction_msg(node_event(7, 2), 2));
  step(kT0 + kPeriodUs);  // the first result collected stale, the new version handed out
  const bool ran2 = rig.node.plan_once();
  int thrust = 0;
  for (int k = 2; k < 100; ++k) thrust += step(kT0 + k * kPeriodUs);
  const autonomy::ResponseRecord& r = rig.node.responder().record(0);
  const std::int64_t burn_us = r.assessment.burn_us;
  const std::int64_t deadline = r.veto_deadline_us;
  for (int k = -2; k < 3; ++k) thrust += step(deadline + k * kPeriodUs);
  for (std::int64_t t = burn_us - 2'000'000; t < burn_us + 2'000'000; t += kPeriodUs) thrust += step(t);
  g_counting = false;
  EXPECT_EQ(g_news.load(), 0) << "operator new called while planning or flying the burn";
  EXPECT_TRUE(ran1 && ran2);
  EXPECT_EQ(rig.node.responder().counters().stale_results, 1);
  EXPECT_EQ(rig.node.responder().counters().schedules, 1);
  EXPECT_GT(thrust, 0);
  EXPECT_EQ(r.state, autonomy::ResponseState::kExecuted);
  EXPECT_GT(rig.node.proposals_published(), 100 / 50);
  EXPECT_EQ(rig.node.counts().accounted(), rig.pub.published());
}

}  // namespace
}  // namespace evade::guidance_lcm::test
