// The collision-avoidance plan (`evade plan cam --publish`) on the planners' publish path:
// assessment::make_cam_burn_plan on the shipped example, publish_burn_plan on memq://, a
// subscriber on the same instance decodes the bytes; the plan arrives bit for bit with the
// burn's utime as its epoch, and the guidance node's executor accepts it before the burn.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "evade/assessment/cam_burn_plan.hpp"
#include "evade/assessment/cam_planner.hpp"
#include "evade/assessment/conjunction_input.hpp"
#include "evade/config/scenario.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/lcm_link/burn_plan_publisher.hpp"
#include "support/memq_capture.hpp"

namespace {

using namespace evade;

TEST(CamPublish, ExamplePlanArrivesAsOneBurnAtItsEpochAndTheExecutorAcceptsIt) {
  const config::Scenario sc =
      config::Scenario::load(EVADE_TEST_SCENARIO_DIR "/cam-example.yaml");
  assessment::CamRequest req;
  req.lead_s = 17000.0;
  req.pc_max = 1e-4;
  const assessment::CamPlan p = assessment::plan_cam(
      assessment::read_conjunction_scenario(sc), req, assessment::AssessConfig{},
      assessment::CamConfig{});
  ASSERT_TRUE(p.verified_ok);
  const BurnPlan plan = assessment::make_cam_burn_plan(p, 9);
  lcm_link::PlanStamp stamp;
  stamp.utime = 1'795'000'000'000'000;
  stamp.epoch_utime = stamp.utime + 3'600'000'000;  // the burn one hour after the uplink
  test::MemqCapture lcm("EVADE_BURN_PLAN");
  ASSERT_TRUE(lcm.good());
  lcm_link::publish_burn_plan(lcm.get(), "EVADE_BURN_PLAN", plan, 9, stamp);
  const std::vector<std::vector<std::uint8_t>>& frames = lcm.drain();
  ASSERT_EQ(frames.size(), 1u);
  evade_burn_plan_t m{};
  ASSERT_EQ(m.decode(frames[0].data(), 0, static_cast<int>(frames[0].size())),
            static_cast<int>(frames[0].size()));
  EXPECT_EQ(m.source, evade_burn_plan_t::SOURCE_COLLISION_AVOIDANCE);
  EXPECT_EQ(m.epoch_utime, stamp.epoch_utime);
  EXPECT_EQ(m.n_impulses, 1);
  EXPECT_EQ(m.impulse_t_s[0], 0.0);
  EXPECT_EQ(m.impulse_dv_mps[0], p.dv_rtn_mps.norm());
  guidance::UplinkedPlan got;
  ASSERT_TRUE(guidance_lcm::from_lcm(m, &got));
  EXPECT_EQ(got.plan.plan_id, 9);
  EXPECT_EQ(got.plan.source, static_cast<int>(PlanSource::kCollisionAvoidance));
  EXPECT_EQ(got.plan.impulses[0].dv_rsw_mps, p.dv_rtn_mps);
  EXPECT_TRUE(got.plan.impulses[0].dv_eci_valid);
  EXPECT_EQ(got.plan.impulses[0].dv_eci_mps, p.dv_eci_mps);
  guidance::PlanExecutor exec(guidance::PlanExecutorConfig{});
  EXPECT_EQ(exec.load(got, stamp.utime, true, 0.0), guidance::PlanReject::kNone);
  EXPECT_TRUE(exec.active());
}

}  // namespace
