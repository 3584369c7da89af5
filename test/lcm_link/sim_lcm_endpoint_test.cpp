// make_lcm_endpoint (lcm_link/sim_lcm_endpoint.hpp) without a node: argument and
// EVADE_SIM_LCM_REALTIME_FACTOR checks, zero thrust until the node has spoken, and a lockstep
// timeout that names the URL. The two-process link itself is test/guidance_lcm/lcm_link_test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "evade/lcm_link/sim_lcm_endpoint.hpp"

namespace {

using evade::lcm_link::make_lcm_endpoint;

constexpr const char* kFactorVar = "EVADE_SIM_LCM_REALTIME_FACTOR";

// Sets the pacing variable for one scope and restores "unset" afterwards.
struct ScopedFactor {
  explicit ScopedFactor(const char* value) { setenv(kFactorVar, value, 1); }
  ~ScopedFactor() { unsetenv(kFactorVar); }
};

evade::guidance::NavState nav_at(std::int64_t utime_us) {
  evade::guidance::NavState n;
  n.utime_us = utime_us;
  n.r_eci_m = evade::Vec3(6778137.0, 0.0, 0.0);
  n.v_eci_mps = evade::Vec3(0.0, 7668.6, 0.0);
  n.valid = true;
  return n;
}

TEST(SimLcmEndpoint, NonPositiveTimeoutIsInvalidArgument) {
  unsetenv(kFactorVar);
  EXPECT_THROW(make_lcm_endpoint("memq://", true, 0.0), std::invalid_argument);
  EXPECT_THROW(make_lcm_endpoint("memq://", true, -1.0), std::invalid_argument);
  EXPECT_THROW(make_lcm_endpoint("memq://", true, std::nan("")), std::invalid_argument);
}

TEST(SimLcmEndpoint, BadRealtimeFactorIsInvalidArgumentNamingTheVariable) {
  for (const char* bad : {"abc", "0", "-1", "1e7", "2x"}) {
    ScopedFactor f(bad);
    try {
      make_lcm_endpoint("memq://", false, 1.0);
      FAIL() << "no throw for '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(kFactorVar), std::string::npos) << e.what();
    }
  }
  ScopedFactor ok("1000");
  EXPECT_NE(make_lcm_endpoint("memq://", false, 1.0), nullptr);
}

TEST(SimLcmEndpoint, UrlThatCannotBeOpenedIsARuntimeErrorNamingIt) {
  unsetenv(kFactorVar);
  try {
    make_lcm_endpoint("nosuchprovider://x", false, 1.0);
    FAIL() << "no throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'nosuchprovider://x'"), std::string::npos) << e.what();
  }
}

TEST(SimLcmEndpoint, WithoutANodeTheCommandIsZeroThrust) {
  unsetenv(kFactorVar);
  auto ep = make_lcm_endpoint("memq://", false, 1.0);
  for (std::int64_t k = 0; k < 3; ++k) {
    const evade::guidance::ThrustCommand c = ep->exchange(k * 100000, nav_at(k * 100000), nullptr);
    EXPECT_EQ(c.accel_mps2, 0.0);
  }
  evade::guidance::GuidanceStatus st;
  EXPECT_FALSE(ep->status(&st));
}

TEST(SimLcmEndpoint, LockstepWithoutANodeTimesOutNamingTheUrl) {
  unsetenv(kFactorVar);
  auto ep = make_lcm_endpoint("memq://", true, 0.3);
  try {
    ep->exchange(0, nav_at(0), nullptr);
    FAIL() << "no throw";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no command from evade_guidance_node"), std::string::npos) << what;
    EXPECT_NE(what.find("'memq://'"), std::string::npos) << what;
  }
}

}  // namespace
