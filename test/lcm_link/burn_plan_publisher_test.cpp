// publish_burn_plan (lcm_link/burn_plan_publisher.hpp) over memq://: the seed4 plan of
// `evade plan observability` is published, received on the same LCM instance (memq://
// delivers only within one instance), decoded and checked against the planner's result;
// plans the message cannot carry and LCM failures are clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "evade/evade_burn_plan_t.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/lcm_link/burn_plan_publisher.hpp"
#include "evade/observability/burn_plan.hpp"
#include "evade/observability/planner.hpp"
#include "seed4_problem.hpp"
#include "support/memq_capture.hpp"

namespace {

using evade::BurnPlan;
using evade::lcm_link::publish_burn_plan;

constexpr const char* kChannel = "EVADE_BURN_PLAN_TEST";

// memq:// delivers only within one instance: publisher and subscriber share it.
class Memq : public evade::test::MemqCapture {
 public:
  Memq() : MemqCapture(kChannel) {}
};

// `evade plan observability --seed 3` on scenarios/seed4.yaml (paper objective, ISRES with
// population 80 and 2400 evaluations, BOBYQA polish).
evade::observability::PlanResult plan_seed4() {
  using namespace evade::observability;
  IsresOptions io;
  io.seed = 3;
  return plan_isres(sample(test::seed4()), ObjectiveKind::kPaper, EstimationConfig{}, io);
}

BurnPlan simple_plan() {
  BurnPlan p;
  p.plan_id = 1;
  p.n_impulses = 1;
  p.impulses[0].dv_rsw_mps = evade::Vec3(0.0, 1.0, 0.0);
  p.source = static_cast<int>(evade::PlanSource::kThreatArea);
  return p;
}

TEST(BurnPlanPublisher, Seed4PlanSurvivesPublicationOverMemq) {
  Memq lcm;
  ASSERT_TRUE(lcm.good());
  const evade::observability::PlanResult res = plan_seed4();
  const BurnPlan plan = evade::observability::make_burn_plan(res, 17);
  const std::int64_t utime = publish_burn_plan(lcm.get(), kChannel, plan, 17);
  const auto& frames = lcm.drain();
  ASSERT_EQ(frames.size(), 1u);
  evade::evade_burn_plan_t m{};
  ASSERT_EQ(m.decode(frames[0].data(), 0, static_cast<int>(frames[0].size())),
            static_cast<int>(frames[0].size()));
  EXPECT_EQ(m.seq, 17);
  EXPECT_EQ(m.utime, utime);
  EXPECT_GT(m.utime, 1600000000LL * 1000000LL);  // a real wall-clock time in us
  EXPECT_EQ(m.source, evade::evade_burn_plan_t::SOURCE_OBSERVABILITY_ISRES);
  EXPECT_EQ(m.objective, evade::evade_burn_plan_t::OBJECTIVE_PAPER);
  EXPECT_EQ(m.n_impulses, 1);
  EXPECT_EQ(m.impulse_dv_eci_valid[0], 0);
  EXPECT_DOUBLE_EQ(m.impulse_dv_mps[0], 3.0);
  EXPECT_DOUBLE_EQ(m.impulse_t_s[0], 0.0);
  const double* dvm = m.impulse_dv_rsw_mps[0];
  // Δv in LVLH/RSW has magnitude |Δv| and follows from (ε, θ) through C_P_RSW = diag(-1,-1,1).
  const double mag = std::sqrt(dvm[0] * dvm[0] + dvm[1] * dvm[1] + dvm[2] * dvm[2]);
  EXPECT_NEAR(mag, 3.0, 1e-12);
  const evade::Vec3 dv = evade::observability::dv_rsw_from_angles(m.eps_rad, m.theta_rad, 3.0);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(dvm[i], dv(i), 1e-12);
  EXPECT_NEAR(m.theta_rad, -3.2453, 1e-3);  // the paper objective's optimum (objectives_test)
  EXPECT_GT(m.objective_value, 96.0);
  EXPECT_GT(m.evaluations, 2400);
  // And the message carries exactly the planner's numbers.
  EXPECT_EQ(m.eps_rad, res.eps_rad);
  EXPECT_EQ(m.theta_rad, res.theta_rad);
  EXPECT_EQ(m.objective_value, res.value);
  EXPECT_EQ(m.evaluations, res.evaluations);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(dvm[i], res.dv_rsw_mps(i));
  BurnPlan back;
  ASSERT_TRUE(evade::guidance_lcm::from_lcm(m, &back));
  EXPECT_EQ(back.plan_id, 17);
  EXPECT_EQ(back.n_impulses, 1);
  EXPECT_EQ(back.impulses[0].dv_rsw_mps, plan.impulses[0].dv_rsw_mps);
  EXPECT_EQ(back.observability.theta_rad, plan.observability.theta_rad);
}

TEST(BurnPlanPublisher, PlanPublishedOverMemqDecodesToTheSamePlan) {
  Memq lcm;
  ASSERT_TRUE(lcm.good());
  BurnPlan plan = simple_plan();
  plan.plan_id = 9;
  plan.impulses[0].t_s = 1234.5;
  plan.impulses[0].dv_eci_valid = true;
  plan.impulses[0].dv_eci_mps = evade::Vec3(0.1, -0.2, 0.3);
  const std::int64_t utime = publish_burn_plan(lcm.get(), kChannel, plan, 9);
  EXPECT_GT(utime, 1600000000LL * 1000000LL);  // a real wall-clock time in us
  const auto& frames = lcm.drain();
  ASSERT_EQ(frames.size(), 1u);
  evade::evade_burn_plan_t m{};
  ASSERT_EQ(m.decode(frames[0].data(), 0, static_cast<int>(frames[0].size())),
            static_cast<int>(frames[0].size()));
  EXPECT_EQ(m.utime, utime);
  EXPECT_EQ(m.seq, 9);
  BurnPlan back;
  ASSERT_TRUE(evade::guidance_lcm::from_lcm(m, &back));
  EXPECT_EQ(back.plan_id, plan.plan_id);
  EXPECT_EQ(back.n_impulses, 1);
  EXPECT_EQ(back.impulses[0].t_s, plan.impulses[0].t_s);
  EXPECT_EQ(back.impulses[0].dv_rsw_mps, plan.impulses[0].dv_rsw_mps);
  EXPECT_TRUE(back.impulses[0].dv_eci_valid);
  EXPECT_EQ(back.impulses[0].dv_eci_mps, plan.impulses[0].dv_eci_mps);
  EXPECT_EQ(back.source, static_cast<int>(evade::PlanSource::kThreatArea));
  EXPECT_FALSE(back.observability.valid);
}

TEST(BurnPlanPublisher, TooManyImpulsesAreRefusedAndNothingIsSent) {
  Memq lcm;
  ASSERT_TRUE(lcm.good());
  BurnPlan p = simple_plan();
  p.n_impulses = BurnPlan::kMaxImpulses + 1;
  try {
    publish_burn_plan(lcm.get(), kChannel, p, 1);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("BurnPlan.n_impulses = 9"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(lcm.drain().empty());
}

TEST(BurnPlanPublisher, TwoImpulsePlanWithGivenTimesIsPublishedWhole) {
  Memq lcm;
  ASSERT_TRUE(lcm.good());
  BurnPlan p = simple_plan();
  p.n_impulses = 2;
  p.impulses[1].t_s = p.impulses[0].t_s + 108000.0;
  p.impulses[1].dv_rsw_mps = evade::Vec3(0.0, -0.004, 0.0);
  evade::lcm_link::PlanStamp stamp;
  stamp.utime = 1000000000;
  stamp.epoch_utime = 1000500000;
  const std::int64_t utime = publish_burn_plan(lcm.get(), kChannel, p, 3, stamp);
  EXPECT_EQ(utime, 1000000000);
  const auto& frames = lcm.drain();
  ASSERT_EQ(frames.size(), 1u);
  evade::evade_burn_plan_t m{};
  ASSERT_EQ(m.decode(frames[0].data(), 0, static_cast<int>(frames[0].size())),
            static_cast<int>(frames[0].size()));
  evade::guidance::UplinkedPlan back;
  ASSERT_TRUE(evade::guidance_lcm::from_lcm(m, &back));
  EXPECT_EQ(m.utime, 1000000000);
  EXPECT_EQ(back.epoch_utime_us, 1000500000);
  EXPECT_EQ(back.plan.n_impulses, 2);
  EXPECT_EQ(back.plan.impulses[1].t_s, p.impulses[1].t_s);
  EXPECT_EQ(back.plan.impulses[1].dv_rsw_mps, p.impulses[1].dv_rsw_mps);
}

TEST(BurnPlanPublisher, NullLcmOrEmptyChannelIsInvalidArgument) {
  Memq lcm;
  ASSERT_TRUE(lcm.good());
  EXPECT_THROW(publish_burn_plan(static_cast<lcm_t*>(nullptr), kChannel, simple_plan(), 1),
               std::invalid_argument);
  EXPECT_THROW(publish_burn_plan(lcm.get(), "", simple_plan(), 1), std::invalid_argument);
  EXPECT_TRUE(lcm.drain().empty());
}

TEST(BurnPlanPublisher, UrlThatCannotBeOpenedIsARuntimeErrorNamingIt) {
  try {
    publish_burn_plan(std::string("nosuchprovider://x"), kChannel, simple_plan(), 1);
    FAIL() << "no throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'nosuchprovider://x'"), std::string::npos) << e.what();
  }
}

TEST(BurnPlanPublisher, UrlOverloadPublishesOnItsOwnInstance) {
  const std::int64_t utime = publish_burn_plan(std::string("memq://"), kChannel, simple_plan(), 4);
  EXPECT_GT(utime, 1600000000LL * 1000000LL);
}

}  // namespace
