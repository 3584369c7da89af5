// The onboard assessment of one event (docs/AUTONOMY.md AUT-6; response.hpp's steps), with the
// real planning: nav_mismatch and no_nav, no action below the red threshold, needs_ground when
// CARA's checks say the 2D Pc does not hold, a burn after the veto deadline that reaches the
// target, a burn refused when it leaves another tracked event above its red threshold, and no
// allocation in any of it.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "autonomy/cam_example_event.hpp"
#include "evade/autonomy/orbit_stm.hpp"
#include "evade/autonomy/response.hpp"
#include "support/counting_new.hpp"

namespace evade::autonomy {
namespace {

using test_example::kNow;

// The shared example with a post-burn target of 1e-5 (a tenth of the red threshold) and the
// veto deadline 1.3 lead times before TCA, before the window opens.
ConjunctionEvent example_event(std::int64_t id = 7) {
  ConjunctionEvent e = test_example::example_event(id);
  e.pc_target = 1e-5;
  e.veto_deadline_us = e.tca_us - static_cast<std::int64_t>(1.3 * test_example::kLeadS * 1e6);
  return e;
}

// A job for e whose navigation at now is e's own state at TCA, offset_m further along its
// radial, carried back to now by the node's model: the nav check sees about offset_m.
PlanningJob job_for(const ConjunctionEvent& e, double offset_m = 0.0) {
  PlanningJob j;
  j.slot = 0;
  j.event = e;
  j.now_us = kNow;
  j.nav_valid = true;
  j.x_nav_eci = e.x1_eci;
  j.x_nav_eci.head<3>() += offset_m * e.x1_eci.head<3>().normalized();
  EXPECT_TRUE(propagate(&j.x_nav_eci, -1e-6 * static_cast<double>(e.tca_us - kNow), 5.0, kEarthDefault));
  return j;
}

ResponderConfig config() {
  ResponderConfig c;
  c.encounter = assessment::encounter_2d_config(assessment::AssessConfig{});
  EXPECT_EQ(validate_responder_config(c), "");
  return c;
}

CamWorkspace g_ws;

TEST(Response, AnOwnStateFarFromTheNavIsRefusedAndNoNavNeedsTheGround) {
  const ResponderConfig cfg = config();
  Assessment a;
  // Radial sigma 30 m: 5 sigma is 150 m; 1 km away is refused. The back-and-forth
  // propagation returns to the state within millimetres (the same RK4 steps reversed).
  assess_event(job_for(example_event(), 1000.0), cfg, kEarthDefault, &g_ws, &a);
  EXPECT_EQ(a.state, ResponseState::kRefused);
  EXPECT_EQ(a.reason, ResponseReason::kNavMismatch);
  EXPECT_NEAR(a.nav_mismatch_sigma, 1000.0 / 30.0, 0.5);
  PlanningJob no_nav = job_for(example_event());
  no_nav.nav_valid = false;
  assess_event(no_nav, cfg, kEarthDefault, &g_ws, &a);
  EXPECT_EQ(a.state, ResponseState::kNeedsGround);
  EXPECT_EQ(a.reason, ResponseReason::kNoNav);
}

TEST(Response, ABurnAfterTheVetoDeadlineReachesTheTarget) {
  const ResponderConfig cfg = config();
  const ConjunctionEvent e = example_event();
  Assessment a;
  assess_event(job_for(e, 10.0), cfg, kEarthDefault, &g_ws, &a);
  ASSERT_EQ(a.state, ResponseState::kProposed) << response_reason_name(a.reason);
  EXPECT_GT(a.pc, e.pc_red);
  EXPECT_LT(a.nav_mismatch_sigma, 1.0);
  EXPECT_GE(a.burn_us, e.veto_deadline_us + static_cast<std::int64_t>(1e6 * cfg.decision_lead_s));
  EXPECT_LE(a.burn_us, e.burn_end_us);
  EXPECT_LE(a.post_pc, e.pc_target) << "verified by the exact outcome (AUT-5)";
  EXPECT_GT(a.dv_eci_mps.norm(), 0.0);
  EXPECT_LE(a.dv_eci_mps.norm(), cfg.cam.max_dv_mps);
  EXPECT_NEAR(a.dv_rsw_mps.norm(), a.dv_eci_mps.norm(), 1e-12 * a.dv_eci_mps.norm() + 1e-15);
  // A deadline at the window's end leaves no burn time after it.
  ConjunctionEvent late = e;
  late.veto_deadline_us = e.burn_end_us;
  assess_event(job_for(late), cfg, kEarthDefault, &g_ws, &a);
  EXPECT_EQ(a.state, ResponseState::kNeedsGround);
  EXPECT_EQ(a.reason, ResponseReason::kNoFeasibleBurn);
}

TEST(Response, BelowTheRedThresholdNothingIsDone) {
  ConjunctionEvent e = example_event();
  e.x2_eci[2] += 5000.0;  // 5 km more miss along the normal: Pc far below 1e-4
  Assessment a;
  assess_event(job_for(e), config(), kEarthDefault, &g_ws, &a);
  EXPECT_EQ(a.state, ResponseState::kNoAction);
  EXPECT_LE(a.pc, e.pc_red);
  EXPECT_EQ(a.burn_us, 0);
}

TEST(Response, WhereThe2dPcDoesNotHoldTheGroundDecides) {
  // The secondary 40 m from the primary moving 0.5 m/s relative to it: the encounter lasts
  // far longer than 2 % of the orbit (CARA's extended check) and the 2D Pc does not hold.
  ConjunctionEvent e = example_event();
  e.x2_eci = e.x1_eci;
  e.x2_eci[0] += 40.0;
  e.x2_eci[4] += 0.5;
  Assessment a;
  assess_event(job_for(e), config(), kEarthDefault, &g_ws, &a);
  EXPECT_EQ(a.state, ResponseState::kNeedsGround);
  EXPECT_EQ(a.reason, ResponseReason::k2dNotValid);
  EXPECT_NE(a.usage_failed & assessment::kUsageExtended, 0);
}

TEST(Response, ABurnThatLeavesAnotherEventAboveItsRedIsNotProposed) {
  const ResponderConfig cfg = config();
  const ConjunctionEvent e = example_event(7);
  // Another event of the same geometry: the burn for e brings it to about e's target, 1e-5.
  PlanningJob job = job_for(e);
  job.others[0] = example_event(8);
  job.others[0].pc_red = 1.0;  // no limit that a burn could break
  job.n_others = 1;
  Assessment a;
  assess_event(job, cfg, kEarthDefault, &g_ws, &a);
  ASSERT_EQ(a.state, ResponseState::kProposed);
  EXPECT_GT(a.other_events_max_post_pc, 0.0);
  EXPECT_LT(a.other_events_max_post_pc, 1e-4);
  job.others[0].pc_red = 1e-7;  // below what any burn for e gives it
  assess_event(job, cfg, kEarthDefault, &g_ws, &a);
  EXPECT_EQ(a.state, ResponseState::kNeedsGround);
  EXPECT_EQ(a.reason, ResponseReason::kRaisesOther);
}

TEST(Response, TheWholeAssessmentAllocatesNothing) {
  const ResponderConfig cfg = config();
  PlanningJob job = job_for(example_event(7));
  job.others[0] = example_event(8);
  job.others[0].x2_eci[2] += 300.0;
  job.others[0].pc_red = 1.0;
  job.n_others = 1;
  Assessment a;
  const long before = g_news.load();
  assess_event(job, cfg, kEarthDefault, &g_ws, &a);
  const long news = g_news.load() - before;
  EXPECT_EQ(a.state, ResponseState::kProposed) << response_reason_name(a.reason);
  EXPECT_EQ(news, 0);
}

TEST(Response, PolicyNamesReadBackAndOthersAreRefused) {
  for (const Policy p : {Policy::kOff, Policy::kVeto, Policy::kApprove}) {
    Policy q = Policy::kOff;
    ASSERT_TRUE(parse_policy(policy_name(p), &q));
    EXPECT_EQ(q, p);
  }
  Policy q = Policy::kVeto;
  EXPECT_FALSE(parse_policy("Veto", &q));
  EXPECT_FALSE(parse_policy("", &q));
  EXPECT_FALSE(parse_policy(nullptr, &q));
  EXPECT_EQ(q, Policy::kVeto);
  ResponderConfig c = config();
  c.nav_mismatch_sigma = 0.0;
  EXPECT_NE(validate_responder_config(c).find("node.autonomy.nav_mismatch_sigma"), std::string::npos);
  c = config();
  c.cam.burn_times = 65;
  EXPECT_NE(validate_responder_config(c).find("node.autonomy.cam.burn_times"), std::string::npos);
}

}  // namespace
}  // namespace evade::autonomy
