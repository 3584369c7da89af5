// The threat-area (paper 001) and formation (paper 003) plans on the publish path of
// `evade plan ... --publish`, the same as the observability planner's: the planner's library
// makes the BurnPlan (threat::make_burn_plan, formation::make_burn_plan), publish_burn_plan
// (guidance_lcm::to_lcm) sends it on memq://, a subscriber on the same instance decodes the
// bytes, and what it decodes is the planner's plan, bit for bit, with the stamp's epoch and
// frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "evade/evade_burn_plan_t.hpp"
#include "evade/formation/burn_plan.hpp"
#include "evade/formation/formation_scenario.hpp"
#include "evade/formation/limits.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/lcm_link/burn_plan_publisher.hpp"
#include "evade/threat/burn_plan.hpp"
#include "support/memq_capture.hpp"

namespace {

using namespace evade;

constexpr const char* kChannel = "EVADE_BURN_PLAN";

// Publishes plan with the stamp and returns what the subscriber decoded.
evade_burn_plan_t publish_and_receive(const BurnPlan& plan, const lcm_link::PlanStamp& stamp) {
  test::MemqCapture lcm(kChannel);
  EXPECT_TRUE(lcm.good());
  lcm_link::publish_burn_plan(lcm.get(), kChannel, plan, plan.plan_id, stamp);
  const std::vector<std::vector<std::uint8_t>>& frames = lcm.drain();
  evade_burn_plan_t m{};
  EXPECT_EQ(frames.size(), 1u);
  if (frames.size() != 1u) return m;
  EXPECT_EQ(m.decode(frames[0].data(), 0, static_cast<int>(frames[0].size())),
            static_cast<int>(frames[0].size()));
  return m;
}

void expect_same_impulses(const BurnPlan& sent, const BurnPlan& got) {
  ASSERT_EQ(got.n_impulses, sent.n_impulses);
  for (int i = 0; i < sent.n_impulses; ++i) {
    const ImpulsiveBurn& a = sent.impulses[static_cast<std::size_t>(i)];
    const ImpulsiveBurn& b = got.impulses[static_cast<std::size_t>(i)];
    EXPECT_EQ(b.t_s, a.t_s) << "impulse " << i;
    EXPECT_EQ(b.dv_rsw_mps, a.dv_rsw_mps) << "impulse " << i;
    EXPECT_EQ(b.dv_eci_valid, a.dv_eci_valid) << "impulse " << i;
    EXPECT_EQ(b.dv_eci_mps, a.dv_eci_mps) << "impulse " << i;
  }
}

TEST(PlannerPublish, Seed3FormationPlanArrivesWithItsTwoBurnsEpochAndFrame) {
  const config::Scenario sc = config::Scenario::load("seed3");
  const formation::PlanInputs in = formation::read_plan_inputs(sc);
  const formation::LimitsResult lim = formation::compute_limits(in.spec, in.threatened);
  const formation::Decision dec = formation::decide(in.spec, in.threatened, lim, in.conjunction,
                                                    in.timing, in.propagation);
  const BurnPlan plan = formation::make_burn_plan(in.spec, in.threatened, dec, in.propagation, 4);
  lcm_link::PlanStamp stamp;
  stamp.utime = 1'700'000'000'000'000;
  stamp.epoch_utime = 1'700'000'060'000'000;  // scenario t = 0 one minute after the uplink
  stamp.frame = guidance::PlanFrame::kEci;
  const evade_burn_plan_t m = publish_and_receive(plan, stamp);
  EXPECT_EQ(m.seq, 4);
  EXPECT_EQ(m.utime, stamp.utime);
  EXPECT_EQ(m.epoch_utime, stamp.epoch_utime);
  EXPECT_EQ(m.frame, evade_burn_plan_t::FRAME_ECI);
  EXPECT_EQ(m.source, evade_burn_plan_t::SOURCE_FORMATION);
  EXPECT_EQ(m.n_impulses, 2);
  // The message's derived |Δv| is the decision's vis-viva Δv of each burn.
  EXPECT_NEAR(m.impulse_dv_mps[0], std::abs(dec.burns[0].dv_mps), 1e-15);
  EXPECT_NEAR(m.impulse_dv_mps[1], std::abs(dec.burns[1].dv_mps), 1e-15);
  guidance::UplinkedPlan got;
  ASSERT_TRUE(guidance_lcm::from_lcm(m, &got));
  EXPECT_EQ(got.plan.plan_id, 4);
  EXPECT_EQ(got.epoch_utime_us, stamp.epoch_utime);
  EXPECT_EQ(got.frame, guidance::PlanFrame::kEci);
  EXPECT_EQ(got.plan.source, static_cast<int>(PlanSource::kFormation));
  expect_same_impulses(plan, got.plan);
  EXPECT_EQ(got.plan.impulses[1].t_s - got.plan.impulses[0].t_s, 30.0 * 3600.0);
}

TEST(PlannerPublish, ThreatAreaEvasionArrivesAsOneRswImpulseAtTheEpoch) {
  threat::EvasionResult r;  // a 20 m/s burn at α = 0.2 rad, θ = −1.4 rad (the conversion is
  r.dv_mps = 20.0;          // tested with the optimizer in test/threat)
  r.alpha_rad = 0.2;
  r.theta_rad = -1.4;
  r.dv_rsw_mps = threat::evasion_dv_rsw(20.0, 0.2, -1.4);
  const BurnPlan plan = threat::make_burn_plan(r, 11);
  lcm_link::PlanStamp stamp;
  stamp.utime = 1'700'000'000'000'000;
  stamp.epoch_utime = 1'700'000'600'000'000;
  const evade_burn_plan_t m = publish_and_receive(plan, stamp);
  EXPECT_EQ(m.seq, 11);
  EXPECT_EQ(m.frame, evade_burn_plan_t::FRAME_RSW);
  EXPECT_EQ(m.source, evade_burn_plan_t::SOURCE_THREAT_AREA);
  EXPECT_EQ(m.impulse_dv_eci_valid[0], 0);
  EXPECT_EQ(m.impulse_dv_mps[0], plan.impulses[0].dv_rsw_mps.norm());
  guidance::UplinkedPlan got;
  ASSERT_TRUE(guidance_lcm::from_lcm(m, &got));
  EXPECT_EQ(got.epoch_utime_us, stamp.epoch_utime);
  EXPECT_EQ(got.frame, guidance::PlanFrame::kRsw);
  expect_same_impulses(plan, got.plan);
}

}  // namespace
