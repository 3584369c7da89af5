// `evade sim --plan FILE` and the LCM path fly a plan the same way (PLAN-FILE-1): the seed3
// formation plan (two burns 30 h apart) written by the planner's path to a plan file, read
// back and flown in process (sim::plan_run_config on the seed0 scenario at 0.1 Hz, the law +
// plan executor: what `evade sim --plan` does), and the same planner plan published as
// evade_burn_plan_t on memq:// and flown by the guidance node (GuidanceNode, the same
// executor behind LCM) on the same run: every burn is delivered with the same Δv vector, at
// the same cycles. (0.1 Hz: each burn is one 10 s cycle at |Δv|/T; 15 000 cycles per run keep
// the two runs at about 2 s under ASan.)
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "evade/formation/burn_plan.hpp"
#include "evade/formation/formation_scenario.hpp"
#include "evade/formation/limits.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/lcm_link/burn_plan_publisher.hpp"
#include "evade/sim/plan_file.hpp"
#include "evade/sim/plan_run.hpp"
#include "evade/sim/sim_overrides.hpp"
#include "plan_e2e_support.hpp"

namespace {

using namespace evade;

BurnPlan seed3_plan() {
  const config::Scenario sc = config::Scenario::load("seed3");
  const formation::PlanInputs in = formation::read_plan_inputs(sc);
  const formation::LimitsResult lim = formation::compute_limits(in.spec, in.threatened);
  const formation::Decision dec = formation::decide(in.spec, in.threatened, lim, in.conjunction,
                                                    in.timing, in.propagation);
  return formation::make_burn_plan(in.spec, in.threatened, dec, in.propagation, 3);
}

TEST(PlanFileRun, PlanFileFlownInProcessDeliversTheSameDvAsThePlanFlownByTheNodeOverLcm) {
  const BurnPlan plan = seed3_plan();
  const std::string path = ::testing::TempDir() + "seed3_plan_file_lcm_test.json";
  sim::write_plan_file(path, sim::PlanFile{plan, guidance::PlanFrame::kRsw});
  const sim::PlanFile file = sim::read_plan_file(path);
  std::remove(path.c_str());

  config::Scenario seed0 = config::Scenario::load("seed0");
  sim::SimConfig scfg = sim::read_sim_config(seed0);
  scfg.guidance.rate_hz = 0.1;  // `evade sim --plan FILE --guidance-hz 0.1`
  const double epoch_s = 0.0;
  const sim::PlanRunConfig cfg = sim::plan_run_config(scfg, file.plan, epoch_s, 0.0);

  // `evade sim --plan`: the file's plan, in process.
  const auto in_process = sim::make_in_process_plan_endpoint(
      scfg.guidance, file.plan, sim::kPlanRunUtime0, file.frame);
  const sim::PlanRunResult a = sim::run_plan_simulation(cfg, *in_process);

  // The LCM path: the planner's plan published to the node on memq://.
  guidance_lcm::NodeConfig ncfg;
  ncfg.guidance = scfg.guidance;
  test::NodeEndpoint node(ncfg);
  const auto uplink = [&](long k, std::int64_t utime) {
    if (k != 0) return;
    lcm_link::PlanStamp stamp = test::signed_stamp();
    stamp.utime = utime;
    stamp.epoch_utime = sim::kPlanRunUtime0;
    lcm_link::publish_burn_plan(node.lcm(), guidance_lcm::kChanPlan, plan, plan.plan_id, stamp);
  };
  const sim::PlanRunResult b = sim::run_plan_simulation(cfg, node, uplink);

  EXPECT_EQ(node.node().last_status().plan_end, evade_guidance_status_t::PLAN_END_COMPLETED);
  ASSERT_EQ(a.burns.size(), 2u);
  ASSERT_EQ(b.burns.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    std::printf("burn %zu: file in process |dv| %.17g m/s [%.1f, %.1f] s; node over LCM %.17g "
                "m/s [%.1f, %.1f] s\n",
                i + 1, a.burns[i].dv_eci_mps.norm(), a.burns[i].t_start_s, a.burns[i].t_end_s,
                b.burns[i].dv_eci_mps.norm(), b.burns[i].t_start_s, b.burns[i].t_end_s);
    // One executor, bit-exact inputs (the file keeps every double; LCM carries them exactly):
    // the same Δv vector to the last bit, at the same cycles.
    EXPECT_EQ(a.burns[i].dv_eci_mps, b.burns[i].dv_eci_mps);
    EXPECT_EQ(a.burns[i].t_start_s, b.burns[i].t_start_s);
    EXPECT_EQ(a.burns[i].t_end_s, b.burns[i].t_end_s);
    EXPECT_NEAR(a.burns[i].dv_eci_mps.norm(), plan.impulses[i].dv_rsw_mps.norm(), 1e-15);
  }
  EXPECT_EQ(a.satellite_end.r_eci_m, b.satellite_end.r_eci_m);
}

}  // namespace
