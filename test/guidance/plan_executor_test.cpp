// PlanExecutor (guidance/plan_executor.hpp), requirements PLAN-* of docs/GUIDANCE_NODE.md:
// one test per rejection reason (PLAN-VAL-1), burns centred on their time with the planned
// Δv (PLAN-EXE-1), the ends (PLAN-END-1: disarm, evasion, SAFE, missed start, superseded)
// and no allocation in step (PLAN-RT-1).
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "evade/guidance/plan_executor.hpp"

#include "support/counting_new.hpp"

namespace {

using evade::BurnPlan;
using evade::Vec3;
using namespace evade::guidance;

constexpr std::int64_t kT0 = 1'000'000'000;  // utime of the first cycle [us]
constexpr std::int64_t kCycleUs = 20'000;    // 50 Hz

PlanExecutorConfig config() {
  PlanExecutorConfig c;
  c.max_accel_mps2 = 1.0;
  c.cycle_s = 0.02;
  c.dv_budget_mps = 10.0;
  c.max_burn_s = 600.0;
  return c;
}

NavState nav() {  // circular-ish LEO, r along x, v along y: RSW = (x, y, z)
  NavState n;
  n.valid = true;
  n.r_eci_m = Vec3(6.778e6, 0.0, 0.0);
  n.v_eci_mps = Vec3(0.0, 7668.6, 0.0);
  return n;
}

// Two impulses 100 s apart starting 10 s after the epoch kT0.
UplinkedPlan two_impulses(std::int64_t id = 1) {
  UplinkedPlan p;
  p.epoch_utime_us = kT0;
  p.plan.plan_id = id;
  p.plan.n_impulses = 2;
  p.plan.impulses[0].t_s = 10.0;
  p.plan.impulses[0].dv_rsw_mps = Vec3(0.3, -0.4, 0.0);  // 0.5 m/s: 25 cycles
  p.plan.impulses[1].t_s = 110.0;
  p.plan.impulses[1].dv_rsw_mps = Vec3(0.0, 0.0, 0.0105);  // 0.0105 m/s: 1 cycle at 0.525
  return p;
}

PlanReject load(PlanExecutor& e, const UplinkedPlan& p, bool armed = true) {
  return e.load(p, kT0, armed, 0.0);
}

// PLAN-VAL-1: each reason, with the reason counted and the plan not started.
TEST(PlanExecutor, EachRejectionReasonIsNamedAndCounted) {
  struct Case {
    PlanReject want;
    void (*edit)(UplinkedPlan*);
    bool armed;
  };
  const Case cases[] = {
      {PlanReject::kImpulseCount, [](UplinkedPlan* p) { p->plan.n_impulses = 0; }, true},
      {PlanReject::kImpulseCount, [](UplinkedPlan* p) { p->plan.n_impulses = 9; }, true},
      {PlanReject::kNotFinite,
       [](UplinkedPlan* p) { p->plan.impulses[1].dv_rsw_mps.x() = std::nan(""); }, true},
      {PlanReject::kNotFinite,
       [](UplinkedPlan* p) { p->plan.impulses[0].t_s = std::numeric_limits<double>::infinity(); },
       true},
      {PlanReject::kUnknownFrame, [](UplinkedPlan* p) { p->frame = static_cast<PlanFrame>(7); },
       true},
      {PlanReject::kUnknownFrame, [](UplinkedPlan* p) { p->frame = PlanFrame::kEci; }, true},
      {PlanReject::kBurnInPast, [](UplinkedPlan* p) { p->plan.impulses[0].t_s = 0.2; }, true},
      {PlanReject::kNotOrdered, [](UplinkedPlan* p) { p->plan.impulses[1].t_s = 9.0; }, true},
      {PlanReject::kOverlapping, [](UplinkedPlan* p) { p->plan.impulses[1].t_s = 10.27; }, true},
      {PlanReject::kOverBudget,
       [](UplinkedPlan* p) { p->plan.impulses[1].dv_rsw_mps = Vec3(0.0, 9.6, 0.0); }, true},
      {PlanReject::kOverThrustLimit,
       [](UplinkedPlan* p) {  // 700 m/s at 1 m/s^2: 700 s > max_burn_s = 600 s
         p->plan.impulses[1].dv_rsw_mps = Vec3(0.0, 0.0, 700.0);
       },
       true},
      // Found by fuzzing (docs/ASSURANCE.md): a finite but huge Δv has no int cycle count
      // (the conversion was undefined behaviour); it is over the burn-time limit.
      {PlanReject::kOverThrustLimit,
       [](UplinkedPlan* p) { p->plan.impulses[0].dv_rsw_mps = Vec3(1e300, 0.0, 0.0); }, true},
      // Found while fixing the finding above: an epoch near the int64 limit overflowed the
      // burn's start cycle (signed overflow).
      {PlanReject::kNotFinite,
       [](UplinkedPlan* p) { p->epoch_utime_us = std::numeric_limits<std::int64_t>::max() - 5; },
       true},
      {PlanReject::kDisarmed, [](UplinkedPlan*) {}, false},
  };
  for (const Case& c : cases) {
    PlanExecutorConfig cfg = config();
    if (c.want == PlanReject::kOverThrustLimit) cfg.dv_budget_mps = 1e4;
    PlanExecutor e(cfg);
    UplinkedPlan p = two_impulses();
    c.edit(&p);
    EXPECT_EQ(load(e, p, c.armed), c.want) << plan_reject_name(c.want);
    EXPECT_EQ(e.status().rejected[static_cast<std::size_t>(c.want)], 1) << plan_reject_name(c.want);
    EXPECT_EQ(e.status().last_reject, c.want);
    EXPECT_FALSE(e.active());
    EXPECT_EQ(e.status().accepted, 0);
  }
}

// The rejection and end names are the node's plan-status vocabulary: one distinct name per
// value, and a value outside the enum is UNKNOWN.
TEST(PlanExecutor, EveryRejectionAndEndHasItsOwnName) {
  std::set<std::string> rejects;
  for (int r = 0; r < static_cast<int>(PlanReject::kCount); ++r) {
    rejects.insert(plan_reject_name(static_cast<PlanReject>(r)));
  }
  EXPECT_EQ(rejects.size(), static_cast<std::size_t>(PlanReject::kCount));
  EXPECT_EQ(rejects.count("UNKNOWN"), 0u);
  EXPECT_STREQ(plan_reject_name(PlanReject::kOverBudget), "OVER_BUDGET");
  EXPECT_STREQ(plan_reject_name(PlanReject::kCount), "UNKNOWN");
  std::set<std::string> ends;
  for (int e = 0; e <= static_cast<int>(PlanEnd::kSuperseded); ++e) {
    ends.insert(plan_end_name(static_cast<PlanEnd>(e)));
  }
  EXPECT_EQ(ends.size(), 7u);
  EXPECT_EQ(ends.count("UNKNOWN"), 0u);
  EXPECT_STREQ(plan_end_name(PlanEnd::kMissedStart), "MISSED_START");
  EXPECT_STREQ(plan_end_name(static_cast<PlanEnd>(99)), "UNKNOWN");
}

TEST(PlanExecutor, PlanIdMustBeNewerThanTheLastAccepted) {
  PlanExecutor e(config());
  ASSERT_EQ(load(e, two_impulses(5)), PlanReject::kNone);
  EXPECT_EQ(load(e, two_impulses(5)), PlanReject::kNotNewer);
  EXPECT_EQ(load(e, two_impulses(4)), PlanReject::kNotNewer);
  EXPECT_EQ(e.status().rejected[static_cast<std::size_t>(PlanReject::kNotNewer)], 2);
  EXPECT_EQ(e.status().plan_id, 5);  // the active plan is unchanged
  EXPECT_EQ(load(e, two_impulses(6)), PlanReject::kNone);
  EXPECT_EQ(e.status().plan_id, 6);
  EXPECT_EQ(e.status().accepted, 2);
}

TEST(PlanExecutor, BudgetCountsWhatTheLawHasSpent) {
  PlanExecutor e(config());  // budget 10 m/s, plan 0.5105 m/s
  EXPECT_EQ(e.load(two_impulses(), kT0, true, 9.6), PlanReject::kOverBudget);
  EXPECT_EQ(e.load(two_impulses(), kT0, true, 9.4), PlanReject::kNone);
}

// Runs cycles from kT0 to end_us with a law in `mode`; returns Σ a T per impulse window.
struct Flight {
  Vec3 dv_eci[2] = {Vec3::Zero(), Vec3::Zero()};
  double t_first_s[2] = {-1, -1};
  double t_last_end_s[2] = {-1, -1};
};
Flight fly(PlanExecutor& e, std::int64_t end_us, GuidanceMode mode = GuidanceMode::kStandby) {
  Flight f;
  for (std::int64_t now = kT0; now < end_us; now += kCycleUs) {
    const PlanThrust t = e.step(nav(), true, mode, now);
    if (t.accel_mps2 <= 0.0) continue;
    const int i = e.status().n_impulses > 0 ? e.status().impulses_done : 0;
    f.dv_eci[i] += t.accel_mps2 * 0.02 * t.u_eci;
    const double t_s = 1e-6 * static_cast<double>(now - kT0);
    if (f.t_first_s[i] < 0) f.t_first_s[i] = t_s;
    f.t_last_end_s[i] = t_s + 0.02;
  }
  return f;
}

// PLAN-EXE-1: each burn delivers its Δv (RSW = ECI axes for this nav) centred within T/2.
TEST(PlanExecutor, BurnsDeliverThePlannedDeltaVCentredOnTheirTimes) {
  PlanExecutor e(config());
  const UplinkedPlan p = two_impulses();
  ASSERT_EQ(load(e, p), PlanReject::kNone);
  const Flight f = fly(e, kT0 + 120'000'000);
  EXPECT_EQ(e.status().state, PlanState::kEnded);
  EXPECT_EQ(e.status().end, PlanEnd::kCompleted);
  EXPECT_EQ(e.status().impulses_done, 2);
  for (int i = 0; i < 2; ++i) {
    const Vec3 want = p.plan.impulses[static_cast<std::size_t>(i)].dv_rsw_mps;
    EXPECT_LT((f.dv_eci[i] - want).norm(), 1e-12 * want.norm()) << i;
    EXPECT_NEAR(e.status().dv_delivered_mps[static_cast<std::size_t>(i)], want.norm(),
                1e-12 * want.norm());
    const double centre = 0.5 * (f.t_first_s[i] + f.t_last_end_s[i]);
    EXPECT_LE(std::abs(centre - p.plan.impulses[static_cast<std::size_t>(i)].t_s), 0.01 + 1e-9);
    const double start_s = 1e-6 * static_cast<double>(e.status().burn_start_us[static_cast<std::size_t>(i)] - kT0);
    const double end_s = 1e-6 * static_cast<double>(e.status().burn_end_us[static_cast<std::size_t>(i)] - kT0);
    EXPECT_NEAR(start_s, f.t_first_s[i], 1e-9);
    EXPECT_NEAR(end_s, f.t_last_end_s[i], 1e-9);
  }
  EXPECT_NEAR(f.t_last_end_s[0] - f.t_first_s[0], 0.5, 1e-9);  // 25 cycles at 1 m/s^2
}

TEST(PlanExecutor, EciFrameFliesTheFixedEciDeltaV) {
  PlanExecutor e(config());
  UplinkedPlan p = two_impulses();
  p.frame = PlanFrame::kEci;
  p.plan.n_impulses = 1;
  p.plan.impulses[0].dv_eci_valid = true;
  p.plan.impulses[0].dv_eci_mps = Vec3(0.0, 0.0, -0.2);
  ASSERT_EQ(load(e, p), PlanReject::kNone);
  const Flight f = fly(e, kT0 + 20'000'000);
  EXPECT_LT((f.dv_eci[0] - Vec3(0.0, 0.0, -0.2)).norm(), 1e-13);
  EXPECT_EQ(e.status().end, PlanEnd::kCompleted);
}

// PLAN-EXE-1 at the bottom of the double range (fuzz findings 6 and 7): a Δv whose squares
// underflow (1e-170 m/s) or whose components are subnormal (a few ULPs of 4.9e-324) is flown
// along a unit direction (to 1e-15, a few roundings of a normalisation) parallel to the
// planned Δv, in either frame.
TEST(PlanExecutor, TinyAndSubnormalImpulsesThrustAlongAUnitDirection) {
  const double ulp = std::numeric_limits<double>::denorm_min();
  const Vec3 cases[] = {Vec3(1e-170, 2e-170, 0.0), Vec3(2 * ulp, 91 * ulp, 0.0),
                        Vec3(4200 * ulp, 1000 * ulp, 0.0), Vec3(0.0, 0.0, -ulp)};
  for (const PlanFrame frame : {PlanFrame::kRsw, PlanFrame::kEci}) {
    for (const Vec3& dv : cases) {
      PlanExecutor e(config());
      UplinkedPlan p = two_impulses();
      p.frame = frame;
      p.plan.n_impulses = 1;
      p.plan.impulses[0].dv_rsw_mps = dv;
      p.plan.impulses[0].dv_eci_valid = true;
      p.plan.impulses[0].dv_eci_mps = dv;
      ASSERT_EQ(load(e, p), PlanReject::kNone);
      int thrusting = 0;
      for (std::int64_t now = kT0; now < kT0 + 20'000'000; now += kCycleUs) {
        const PlanThrust t = e.step(nav(), true, GuidanceMode::kStandby, now);
        if (!(t.accel_mps2 > 0.0)) continue;
        ++thrusting;
        EXPECT_NEAR(t.u_eci.norm(), 1.0, 1e-15) << dv.transpose();
        // RSW = ECI axes for this nav: the direction is dv's, compared on the scaled vector.
        const Vec3 want = (dv / dv.cwiseAbs().maxCoeff()).normalized();
        EXPECT_LT((t.u_eci - want).norm(), 1e-15) << dv.transpose();
      }
      EXPECT_EQ(thrusting, 1) << dv.transpose();  // one cycle: |dv| far below a_max T
      EXPECT_EQ(e.status().end, PlanEnd::kCompleted);
    }
  }
}

// Fuzz finding 8: |Δv| a hair (5e-13 relative) above a whole number of cycles at a_max. The
// burn-cycle count's guard against rounding an exact multiple up made it round down, and
// the burn flew at a_max (1 + 5e-13): above the thrust limit. Now it takes one cycle more,
// never above a_max, and still delivers the planned Δv.
TEST(PlanExecutor, ThrustNeverExceedsTheLimitWhenDvIsAHairAboveWholeCycles) {
  for (const double excess : {5e-13, 1e-13, 1e-15}) {
    PlanExecutor e(config());
    UplinkedPlan p = two_impulses();
    p.plan.n_impulses = 1;
    p.plan.impulses[0].dv_rsw_mps = Vec3(0.5 * (1.0 + excess), 0.0, 0.0);  // 25 cycles + a hair
    ASSERT_EQ(load(e, p), PlanReject::kNone);
    double dv_mps = 0.0;
    for (std::int64_t now = kT0; now < kT0 + 20'000'000; now += kCycleUs) {
      const PlanThrust t = e.step(nav(), true, GuidanceMode::kStandby, now);
      EXPECT_LE(t.accel_mps2, 1.0) << excess;
      dv_mps += t.accel_mps2 * 0.02;
    }
    EXPECT_NEAR(dv_mps, 0.5 * (1.0 + excess), 1e-15) << excess;
    EXPECT_EQ(e.status().end, PlanEnd::kCompleted);
  }
}

// PLAN-END-1
TEST(PlanExecutor, DisarmCancelsThePlan) {
  PlanExecutor e(config());
  ASSERT_EQ(load(e, two_impulses()), PlanReject::kNone);
  e.step(nav(), true, GuidanceMode::kStandby, kT0);
  const PlanThrust t = e.step(nav(), false, GuidanceMode::kStandby, kT0 + kCycleUs);
  EXPECT_EQ(t.accel_mps2, 0.0);
  EXPECT_EQ(e.status().end, PlanEnd::kCancelledDisarm);
  EXPECT_FALSE(e.active());
  const Flight f = fly(e, kT0 + 120'000'000);  // nothing more is flown
  EXPECT_EQ(f.dv_eci[0].norm() + f.dv_eci[1].norm(), 0.0);
}

TEST(PlanExecutor, CloseRangeEvasionPreemptsABurnAndAbandonsThePlan) {
  PlanExecutor e(config());
  ASSERT_EQ(load(e, two_impulses()), PlanReject::kNone);
  fly(e, kT0 + 9'900'000);  // into the first burn (it starts at 9.74 s)
  ASSERT_EQ(e.status().state, PlanState::kBurning);
  const PlanThrust t = e.step(nav(), true, GuidanceMode::kEvade, kT0 + 9'900'000);
  EXPECT_EQ(t.accel_mps2, 0.0);
  EXPECT_EQ(e.status().end, PlanEnd::kPreemptedEvasion);
  EXPECT_EQ(e.status().impulses_done, 0);
  EXPECT_NEAR(e.status().dv_delivered_mps[0], 0.16, 1e-12);  // 8 cycles of 0.02 m/s
  ThrustCommand law;
  law.mode = GuidanceMode::kEvade;
  law.accel_mps2 = 1.0;
  law.u_eci = Vec3::UnitX();
  PlanThrust plan;
  plan.accel_mps2 = 0.5;
  plan.u_eci = Vec3::UnitY();
  EXPECT_EQ(merge_plan_thrust(law, plan).u_eci, Vec3::UnitX());  // the law's thrust wins
}

TEST(PlanExecutor, SafeDuringABurnAbandonsThePlan) {
  PlanExecutor e(config());
  ASSERT_EQ(load(e, two_impulses()), PlanReject::kNone);
  fly(e, kT0 + 9'900'000);
  e.step(nav(), true, GuidanceMode::kSafe, kT0 + 9'900'000);
  EXPECT_EQ(e.status().end, PlanEnd::kAbandonedSafe);
}

TEST(PlanExecutor, SafeWhileWaitingDoesNotEndThePlan) {
  PlanExecutor e(config());
  ASSERT_EQ(load(e, two_impulses()), PlanReject::kNone);
  fly(e, kT0 + 5'000'000, GuidanceMode::kSafe);
  EXPECT_EQ(e.status().state, PlanState::kWaiting);
}

TEST(PlanExecutor, AStartCyclePassedIsAMissedStart) {
  PlanExecutor e(config());
  ASSERT_EQ(load(e, two_impulses()), PlanReject::kNone);
  e.step(nav(), true, GuidanceMode::kStandby, kT0 + 11'000'000);  // node paused past 9.74 s
  EXPECT_EQ(e.status().end, PlanEnd::kMissedStart);
}

TEST(PlanExecutor, ANewerPlanSupersedesTheActiveOne) {
  PlanExecutor e(config());
  ASSERT_EQ(load(e, two_impulses(1)), PlanReject::kNone);
  ASSERT_EQ(load(e, two_impulses(2)), PlanReject::kNone);
  EXPECT_EQ(e.status().plan_id, 2);
  EXPECT_EQ(e.status().state, PlanState::kWaiting);
}

// PLAN-RT-1
TEST(PlanExecutor, StepAndLoadDoNotAllocate) {
  PlanExecutor e(config());
  const UplinkedPlan p = two_impulses();
  const long before = g_news.load();
  ASSERT_EQ(load(e, p), PlanReject::kNone);
  fly(e, kT0 + 120'000'000);
  EXPECT_EQ(g_news.load() - before, 0);
  EXPECT_EQ(e.status().end, PlanEnd::kCompleted);
}

}  // namespace
