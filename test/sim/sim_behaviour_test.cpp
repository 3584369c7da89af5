// Closed-loop behaviours of the paper-000 guidance in the simulator: the sign of the law
// (negative test), COAST after the closest approach, Δv / burn-time limits, the disarmed
// baseline, and scenario input checking.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "evade/config/scenario.hpp"
#include "evade/guidance/los_geometry.hpp"
#include "evade/commands/sim_scenario.hpp"
#include "evade/sim/simulator.hpp"

namespace {

using evade::Vec3;
using namespace evade;

sim::SimConfig seed0() {
  return commands::sim_config_from_scenario(config::Scenario::load("seed0"));
}

// Homing law for the negative test: thrust along +e_θ = u̇/|u̇| (raw, no zenith flip), from
// the ideal sensor's angles and rates.
class PlusEthetaNoFlip final : public sim::GuidanceEndpoint {
 public:
  explicit PlusEthetaNoFlip(double accel) : accel_(accel) {}
  guidance::ThrustCommand exchange(std::int64_t utime_us, const guidance::NavState&,
                                   const guidance::AnglesMeasurement* m) override {
    guidance::ThrustCommand c;
    c.utime_us = utime_us;
    if (m == nullptr) return c;
    const Vec3 ud = guidance::los_unit_rate_from_angle_rates(
        m->elevation_rad, m->azimuth_rad, m->elevation_rate_radps, m->azimuth_rate_radps);
    if (!(ud.norm() > 0.0)) return c;
    c.mode = guidance::GuidanceMode::kEvade;
    c.u_eci = ud.normalized();
    c.accel_mps2 = accel_;
    return c;
  }

 private:
  double accel_;
};

// seed0 with the debris moved 5 m across the relative velocity: nominal miss ≈ 5 m.
sim::SimConfig seed0_offset() {
  sim::SimConfig c = seed0();
  const Vec3 dv = c.debris0.v_eci_mps - c.satellite0.v_eci_mps;
  const Vec3 across = dv.cross(Vec3::UnitX()).normalized();
  c.debris0.r_eci_m += 5.0 * across;
  return c;
}

double miss_of(const sim::SimConfig& c, sim::GuidanceEndpoint& ep) {
  const sim::SimResult r = sim::run_simulation(c, ep);
  EXPECT_TRUE(r.closest_approach_found);
  return r.miss_m;
}

TEST(SimSign, PlusEthetaWithoutFlipHomesWhileMinusEthetaEvades) {
  const sim::SimConfig c = seed0_offset();
  auto none = sim::make_in_process_endpoint(c.guidance, /*armed=*/false);
  auto evade_ep = sim::make_in_process_endpoint(c.guidance, true);
  PlusEthetaNoFlip homing(c.guidance.max_accel_mps2);
  const double m_none = miss_of(c, *none);
  const double m_evade = miss_of(c, *evade_ep);
  const double m_home = miss_of(c, homing);
  std::printf("miss: no thrust %.4f m, -e_theta (law) %.4f m, +e_theta no flip %.4f m\n",
              m_none, m_evade, m_home);
  EXPECT_NEAR(m_none, 5.0, 0.1);
  // Homing: the +e_θ thrust cancels the transverse velocity — the miss collapses far below
  // the unforced 5 m (the 50 Hz bang-bang leaves ≈ a·dt² ≈ 0.4 mm-level residuals).
  EXPECT_LT(m_home, 0.05);
  // The law adds ≈ ½ a t_go² = 50 m to the 5 m of the unforced miss.
  EXPECT_GT(m_evade, 50.0);
  // Same on the paper's collision course: homing keeps the collision.
  const sim::SimConfig c0 = seed0();
  PlusEthetaNoFlip homing0(c0.guidance.max_accel_mps2);
  EXPECT_LT(miss_of(c0, homing0), 0.01);
}

TEST(SimModes, CoastsWithZeroThrustAfterTheClosestApproach) {
  sim::SimConfig c = seed0();
  c.encounter.post_tca_s = 1.0;
  auto ep = sim::make_in_process_endpoint(c.guidance, true);
  std::vector<sim::SimSample> samples;
  const sim::SimResult r =
      sim::run_simulation(c, *ep, [&](const sim::SimSample& s) { samples.push_back(s); });
  ASSERT_TRUE(r.closest_approach_found);
  ASSERT_TRUE(r.has_final_status);
  EXPECT_EQ(r.final_status.mode, guidance::GuidanceMode::kCoast);
  EXPECT_EQ(r.final_status.reason, guidance::CommandReason::kPassedClosestApproach);
  int after = 0;
  for (const auto& s : samples) {
    if (s.t_s > r.tca_s + 0.05) {  // from the second cycle after the encounter on
      ++after;
      EXPECT_EQ(s.cmd.mode, guidance::GuidanceMode::kCoast) << "t = " << s.t_s;
      EXPECT_EQ(s.cmd.accel_mps2, 0.0) << "t = " << s.t_s;
    }
  }
  EXPECT_GT(after, 40);
  // The guidance's own account stops within one cycle of the encounter.
  EXPECT_LT(r.final_status.dv_used_mps, r.dv_mps + 2.0 * 0.02 * c.guidance.max_accel_mps2);
}

TEST(SimLimits, DvBudgetAndMaxBurnTimeHoldInClosedLoop) {
  sim::SimConfig c = seed0();
  c.guidance.dv_budget_mps = 3.0;
  auto ep = sim::make_in_process_endpoint(c.guidance, true);
  sim::SimResult r = sim::run_simulation(c, *ep);
  std::printf("dv budget 3 m/s: applied dv %.6f m/s, miss %.3f m\n", r.dv_mps, r.miss_m);
  EXPECT_LE(r.dv_mps, 3.0 + 1e-9);
  EXPECT_GE(r.dv_mps, 3.0 - 1e-6);
  EXPECT_EQ(r.final_status.reason, guidance::CommandReason::kDvBudgetExhausted);

  c = seed0();
  c.guidance.max_burn_s = 4.0;
  ep = sim::make_in_process_endpoint(c.guidance, true);
  r = sim::run_simulation(c, *ep);
  std::printf("max burn 4 s: applied burn %.6f s, miss %.3f m\n", r.burn_s, r.miss_m);
  EXPECT_LE(r.burn_s, 4.0 + 1e-9);
  EXPECT_GE(r.burn_s, 4.0 - 0.02 - 1e-9);  // stops within one guidance cycle of the limit
  EXPECT_EQ(r.final_status.reason, guidance::CommandReason::kBurnTimeExhausted);
  // Burning early for 4 s of the 10 s: miss = a t_b (t_go − t_b/2) = 1·4·8 = 32 m.
  EXPECT_NEAR(r.miss_m, 32.0, 0.1);
}

TEST(SimModes, DisarmedRunKeepsTheNominalMissAndUsesNoFuel) {
  const sim::SimConfig c = seed0();
  auto ep = sim::make_in_process_endpoint(c.guidance, false);
  const sim::SimResult r = sim::run_simulation(c, *ep);
  EXPECT_EQ(r.dv_mps, 0.0);
  EXPECT_NEAR(r.miss_m, r.nominal_miss_m, 1e-6);  // Brent bracket 1e-10 s: sub-µm
  EXPECT_NEAR(r.tca_s, r.nominal_tca_s, 1e-9);
}

TEST(SimScenario, NonFiniteOrUnknownKeysAreRejectedWithTheKey) {
  auto load = [](const std::string& extra_key, const std::string& value) {
    config::Scenario sc = config::Scenario::load("seed0");
    sc.apply_override(extra_key + "=" + value);
    sim::SimConfig c = commands::sim_config_from_scenario(sc);
    sc.check_all_used();
    c.validate();
  };
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, std::string>>{{"sensor.noise_rad", ".nan"},
                                                        {"guidance.max_accel_mps2", ".inf"},
                                                        {"satellite.r_eci_m", "[1, .nan, 3]"},
                                                        {"guidance.dv_budget_mps", "-1"}}) {
    try {
      load(key, value);
      ADD_FAILURE() << key << " = " << value << " accepted";
    } catch (const config::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
  try {
    load("sensor.noise", "1e-6");  // unit suffix missing: unknown key
    ADD_FAILURE() << "unknown key accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("sensor.noise"), std::string::npos) << e.what();
  }
}

}  // namespace
