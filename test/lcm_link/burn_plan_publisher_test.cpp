// publish_burn_plan (lcm_link/burn_plan_publisher.hpp) over memq://: a plan is published,
// received on the same LCM instance (memq:// delivers only within one instance) and decoded;
// plans the message cannot carry and LCM failures are clear errors.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <lcm/lcm.h>

#include "evade/evade_burn_plan_t.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/lcm_link/burn_plan_publisher.hpp"

namespace {

using evade::BurnPlan;
using evade::lcm_link::publish_burn_plan;

constexpr const char* kChannel = "EVADE_BURN_PLAN_TEST";

// One memq:// instance with a raw C subscription: the callback only copies the bytes
// (nothing can throw through LCM's C dispatch); the test decodes them afterwards. (LCM
// 1.3.1's typed C++ subscription trips UBSan's member-access check inside lcm-cpp-impl.hpp,
// so the C API is used, as in test/guidance_lcm.)
class Memq {
 public:
  Memq() : lcm_(lcm_create("memq://")) {
    if (lcm_ != nullptr) sub_ = lcm_subscribe(lcm_, kChannel, &Memq::on_raw, this);
  }
  ~Memq() {
    if (sub_ != nullptr) lcm_unsubscribe(lcm_, sub_);
    if (lcm_ != nullptr) lcm_destroy(lcm_);
  }
  Memq(const Memq&) = delete;
  Memq& operator=(const Memq&) = delete;
  bool good() const { return lcm_ != nullptr && sub_ != nullptr; }
  lcm_t* get() const { return lcm_; }
  /// Delivers everything queued and returns the frames received so far.
  const std::vector<std::vector<std::uint8_t>>& drain() {
    while (lcm_handle_timeout(lcm_, 100) > 0) {
    }
    return frames_;
  }

 private:
  static void on_raw(const lcm_recv_buf_t* rbuf, const char* /*channel*/, void* user) {
    auto* self = static_cast<Memq*>(user);
    const auto* p = static_cast<const std::uint8_t*>(rbuf->data);
    self->frames_.emplace_back(p, p + rbuf->data_size);
  }
  lcm_t* lcm_;
  lcm_subscription_t* sub_ = nullptr;
  std::vector<std::vector<std::uint8_t>> frames_;
};

BurnPlan simple_plan() {
  BurnPlan p;
  p.plan_id = 1;
  p.n_impulses = 1;
  p.impulses[0].dv_rsw_mps = evade::Vec3(0.0, 1.0, 0.0);
  p.source = static_cast<int>(evade::PlanSource::kThreatArea);
  return p;
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

TEST(BurnPlanPublisher, TwoImpulsePlanIsRefusedAndNothingIsSent) {
  Memq lcm;
  ASSERT_TRUE(lcm.good());
  BurnPlan p = simple_plan();
  p.n_impulses = 2;
  try {
    publish_burn_plan(lcm.get(), kChannel, p, 1);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("BurnPlan.n_impulses = 2"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(lcm.drain().empty());
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
