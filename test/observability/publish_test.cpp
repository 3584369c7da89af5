// `evade plan observability --publish` over memq://: the real command (compiled into this
// test with a stub registry) publishes evade_burn_plan_t; the test subscribes on the same LCM
// instance, receives, decodes and checks the fields against the planner's result.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "cli_stub.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/observability/planner.hpp"

namespace evade::cli::plan_observability {
lcm::LCM*& lcm_override();
}

namespace {

// Raw C subscription: the callback only copies the bytes (nothing can throw through LCM's C
// dispatch); the test decodes them afterwards. (LCM 1.3.1's typed C++ subscription trips
// UBSan's member-access check inside lcm-cpp-impl.hpp, so the C API is used, as in
// test/guidance_lcm.)
struct Receiver {
  std::vector<std::vector<uint8_t>> frames;
  static void on_raw(const lcm_recv_buf_t* rbuf, const char* /*channel*/, void* user) {
    auto* self = static_cast<Receiver*>(user);
    const auto* p = static_cast<const uint8_t*>(rbuf->data);
    self->frames.emplace_back(p, p + rbuf->data_size);
  }
};

int run_command(const std::vector<std::string>& args) {
  for (auto& e : evade::cli::stub_registry()) {
    if (e.path != std::vector<std::string>{"plan", "observability"}) continue;
    CLI::App app;
    auto runner = e.setup(app);
    std::vector<std::string> rev(args.rbegin(), args.rend());
    app.parse(rev);
    return runner();
  }
  return -1;
}

TEST(ObservabilityPublish, PublishesBurnPlanOverMemq) {
  lcm::LCM lcm("memq://");
  ASSERT_TRUE(lcm.good());
  Receiver rx;
  lcm_subscription_t* sub = lcm_subscribe(lcm.getUnderlyingLCM(), "EVADE_BURN_PLAN_TEST", &Receiver::on_raw, &rx);
  ASSERT_NE(sub, nullptr);
  evade::cli::plan_observability::lcm_override() = &lcm;
  const int rc = run_command({"--scenario", "seed4", "--seed", "3", "--publish", "--lcm-url", "memq://",
                              "--channel", "EVADE_BURN_PLAN_TEST", "--seq", "17"});
  evade::cli::plan_observability::lcm_override() = nullptr;
  ASSERT_EQ(rc, 0);
  while (lcm.handleTimeout(100) > 0) {
  }
  lcm_unsubscribe(lcm.getUnderlyingLCM(), sub);
  ASSERT_EQ(rx.frames.size(), 1u);
  evade::evade_burn_plan_t m{};
  ASSERT_EQ(m.decode(rx.frames[0].data(), 0, static_cast<int>(rx.frames[0].size())),
            static_cast<int>(rx.frames[0].size()));
  EXPECT_EQ(m.seq, 17);
  EXPECT_GT(m.utime, 1600000000LL * 1000000LL);  // a real wall-clock time in us
  EXPECT_EQ(m.source, evade::evade_burn_plan_t::SOURCE_OBSERVABILITY_ISRES);
  EXPECT_EQ(m.objective, evade::evade_burn_plan_t::OBJECTIVE_PAPER);
  EXPECT_EQ(m.dv_eci_valid, 0);
  EXPECT_DOUBLE_EQ(m.dv_mps, 3.0);
  EXPECT_DOUBLE_EQ(m.burn_time_s, 0.0);
  // Δv in LVLH/RSW has magnitude |Δv| and follows from (ε, θ) through C_P_RSW = diag(-1,-1,1).
  const double mag = std::sqrt(m.dv_lvlh_mps[0] * m.dv_lvlh_mps[0] + m.dv_lvlh_mps[1] * m.dv_lvlh_mps[1] +
                               m.dv_lvlh_mps[2] * m.dv_lvlh_mps[2]);
  EXPECT_NEAR(mag, 3.0, 1e-12);
  const evade::Vec3 dv = evade::observability::dv_rsw_from_angles(m.eps_rad, m.theta_rad, 3.0);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.dv_lvlh_mps[i], dv(i), 1e-12);
  EXPECT_NEAR(m.theta_rad, -3.2453, 1e-3);  // the paper objective's optimum (objectives_test)
  EXPECT_GT(m.objective_value, 96.0);
  EXPECT_GT(m.evaluations, 2400);
}

TEST(ObservabilityPublish, CorruptBytesAreRejectedByDecode) {
  evade::evade_burn_plan_t m{};
  std::vector<uint8_t> buf(static_cast<std::size_t>(m.getEncodedSize()));
  ASSERT_EQ(m.encode(buf.data(), 0, static_cast<int>(buf.size())), static_cast<int>(buf.size()));
  buf[0] ^= 0xFF;  // breaks the fingerprint
  evade::evade_burn_plan_t out{};
  EXPECT_LT(out.decode(buf.data(), 0, static_cast<int>(buf.size())), 0);
  EXPECT_LT(out.decode(buf.data(), 0, 4), 0);  // truncated
}

TEST(ObservabilityPublish, BadObjectiveOrSeedIsAParseError) {
  EXPECT_THROW(run_command({"--objective", "nope"}), CLI::ValidationError);
  EXPECT_THROW(run_command({"--seed", "-4"}), CLI::ParseError);
}

TEST(ObservabilityPublish, ScenarioZeroDvIsAConfigErrorNamingTheKey) {
  try {
    run_command({"--set", "burn.dv_mps=0"});
    FAIL() << "no throw";
  } catch (const evade::config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("burn.dv_mps"), std::string::npos) << e.what();
  }
}

TEST(ObservabilityPublish, InvertedBoundsAreInvalidArgument) {
  EXPECT_THROW(run_command({"--set", "burn.theta_min_rad=-1.0"}), std::invalid_argument);
}

}  // namespace
