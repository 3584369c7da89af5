// The conjunction HIL case (src/hil/conjunction_hil_case.cpp; docs/AUTONOMY.md AUT-11): the
// secondary carried back to t = 0 meets the primary at TCA with the miss asked for, the
// relative position there perpendicular to the relative velocity (TCA is the closest
// approach), and the ground's CDMs read back as `evade conjunction` reads them.
#include <cmath>

#include <gtest/gtest.h>

#include "evade/config/scenario.hpp"
#include "evade/hil/conjunction_hil.hpp"

namespace {

using namespace evade;

// Forward from t = 0 to TCA: the back-propagation's round trip. DOP853 at the simulator's
// tight tolerance (rel 1e-13) over 2.4 h of a 7 km/s orbit: millimetres; 1 cm asked.
TEST(ConjunctionHilCase, TheSecondaryMeetsThePrimaryAtTcaWithTheMissAskedFor) {
  const hil::ConjunctionHilCase c = hil::conjunction_hil_case(hil::HilRun::kBurn, {});
  StateEci own, other;
  sim::propagate_unforced(c.sim, c.tca_s, &own, &other);
  const Vec3 d = other.r_eci_m - own.r_eci_m;
  const Vec3 w = other.v_eci_mps - own.v_eci_mps;
  EXPECT_NEAR(d.norm(), c.config.miss_m, 0.01);
  EXPECT_LT((other.r_eci_m - c.other_tca.r_eci_m).norm(), 0.01);
  EXPECT_LT(std::abs(d.normalized().dot(w.normalized())), 1e-6);  // closest approach at TCA
  // 60 degrees crossing of two 7.6 km/s orbits: |w| = 2 v sin(30 deg) = v.
  EXPECT_NEAR(w.norm(), own.v_eci_mps.norm(), 1e-6 * own.v_eci_mps.norm());
  // 1.5 periods of the 550 km orbit: 2 pi sqrt(a^3/mu) * 1.5, rounded to a second.
  const double a = kEarthDefault.re_m + 550e3;
  EXPECT_NEAR(c.tca_s, 1.5 * 2.0 * M_PI * std::sqrt(a * a * a / kEarthDefault.mu_m3ps2), 0.5);
}

TEST(ConjunctionHilCase, BurnAndVetoSendOneCdmOfTheTruth) {
  for (const hil::HilRun r : {hil::HilRun::kBurn, hil::HilRun::kVeto}) {
    const hil::ConjunctionHilCase c = hil::conjunction_hil_case(r, {});
    ASSERT_EQ(c.cdms.size(), 1u);
    EXPECT_EQ(c.veto, r == hil::HilRun::kVeto);
    const autonomy::ConjunctionEvent& e = c.cdms[0].uplink.event;
    EXPECT_NEAR(c.cdms[0].miss_m, 50.0, 1e-6);
    EXPECT_GT(c.cdms[0].pc, e.pc_red);  // it needs a burn
    EXPECT_EQ(e.tca_us, c.sim.utime0_us + static_cast<std::int64_t>(c.tca_s * 1e6));
    EXPECT_LT((e.x1_eci.head<3>() - c.own_tca.r_eci_m).norm(), 1e-3);  // the CDM's 1 mm digits
    EXPECT_EQ(e.tca_us - e.veto_deadline_us, 7200LL * 1000000);      // uplink defaults
  }
}

TEST(ConjunctionHilCase, UpdateSendsAStaleVersionThenTheTruthWithAShorterDeadline) {
  const hil::ConjunctionHilCase c = hil::conjunction_hil_case(hil::HilRun::kUpdate, {});
  ASSERT_EQ(c.cdms.size(), 2u);
  const autonomy::ConjunctionEvent& v1 = c.cdms[0].uplink.event;
  const autonomy::ConjunctionEvent& v2 = c.cdms[1].uplink.event;
  EXPECT_EQ(v1.event_id, v2.event_id);
  EXPECT_GT(v2.version, v1.version);
  EXPECT_NEAR(c.cdms[0].miss_m, std::hypot(50.0, 9000.0), 1e-3);  // offset across the relative velocity
  EXPECT_LT(c.cdms[0].pc, v1.pc_red);
  EXPECT_NEAR(c.cdms[1].miss_m, 50.0, 1e-6);
  EXPECT_DOUBLE_EQ(c.cdms[1].t_send_s, c.tca_s - 3600.0);
  EXPECT_EQ(v2.tca_us - v2.veto_deadline_us, 2400LL * 1000000);
  EXPECT_EQ(v1.tca_us - v1.veto_deadline_us, 7200LL * 1000000);
}

TEST(ConjunctionHilCase, BadSettingsNameTheirKey) {
  try {
    (void)hil::conjunction_hil_case(hil::HilRun::kUpdate, {{"hil.first_cdm_s", 6000.0}});
    FAIL() << "a first CDM after the update was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("hil.first_cdm_s"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)hil::conjunction_hil_case(hil::HilRun::kBurn, {{"hil.miss_m", -1.0}}),
               config::ConfigError);
  EXPECT_THROW((void)hil::conjunction_hil_case(hil::HilRun::kBurn, {{"hil.no_such_key", 1.0}}),
               config::ConfigError);
  // uplink.* reach the CDM reader: a target above red is refused there, naming the flag.
  try {
    (void)hil::conjunction_hil_case(hil::HilRun::kBurn, {{"uplink.pc_target", 1e-3}});
    FAIL() << "pc_target above pc_red accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--pc-target"), std::string::npos) << e.what();
  }
}

TEST(ConjunctionHilCase, RunNamesRoundTrip) {
  for (const hil::HilRun r : {hil::HilRun::kBurn, hil::HilRun::kVeto, hil::HilRun::kUpdate}) {
    hil::HilRun back{};
    ASSERT_TRUE(hil::parse_hil_run(hil::hil_run_name(r), &back));
    EXPECT_EQ(back, r);
  }
  hil::HilRun x{};
  EXPECT_FALSE(hil::parse_hil_run("fly", &x));
}

}  // namespace
