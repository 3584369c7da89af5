// `evade plan threat-area` as a library call (threat_area_command.hpp): run_threat_area on
// the shipped seed1 scenario gives the published timing case's figures (paper 001, Yu Dateng,
// Wang Hua, Sun Fuyu 2017: V_E = 20 m/s; the numbers the command has always printed), and
// to_json / to_text carry the fields the command prints (the burn with its frame and unit).
#include <string>

#include <gtest/gtest.h>

#include "evade/config/scenario.hpp"
#include "evade/commands/threat_area_command.hpp"

namespace evade::threat {
namespace {

using namespace evade::commands;

const ThreatAreaResult& seed1_result() {
  static const ThreatAreaResult r =
      run_threat_area(read_threat_area_request(config::Scenario::load("seed1")));
  return r;
}

TEST(ThreatAreaCommand, Seed1DefaultRunIsTheCliNumbers) {
  const ThreatAreaResult& r = seed1_result();
  EXPECT_EQ(r.scenario_source, "seed1");
  EXPECT_DOUBLE_EQ(r.study.chaser_cost_t0_mps, 83.48078242728009);
  EXPECT_EQ(r.study.evasion.dv_mps, 20.0);
  EXPECT_DOUBLE_EQ(r.study.evasion.area.arc_s, 2543.14453125);
  EXPECT_DOUBLE_EQ(r.study.evasion.alpha_rad, -0.19025266887535233);
  EXPECT_DOUBLE_EQ(r.study.evasion.theta_rad, -3.1398998981576147);
}

TEST(ThreatAreaCommand, JsonHasTheKeysTheCliPrints) {
  const nlohmann::json j = to_json(seed1_result());
  for (const char* k :
       {"scenario", "n_radps", "period_s", "dt_transfer_s", "impulses", "dv_max_mps",
        "target_inclination_deg", "model", "chaser_cost_t0_mps", "two_impulse_cost_t0_mps",
        "t0_bound_mps", "runtime_s", "dv_mps", "threat_arc_s", "threat_arc_deg", "grid_arc_s",
        "intervals", "alpha_rad", "theta_rad", "dv_vvlh_mps", "dv_rsw_mps", "evaluations",
        "decisions", "search", "total_runtime_s", "parameters"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  EXPECT_EQ(j["threat_arc_s"].get<double>(), 2543.14453125);
  EXPECT_EQ(j["dv_rsw_mps"].size(), 3u);
  EXPECT_EQ(j["search"]["method"], "sweep+bobyqa");
  EXPECT_FALSE(j.contains("eliminating_dv_mps"));  // only with --eliminate
  EXPECT_FALSE(j.contains("sweep_dv"));
  EXPECT_TRUE(j["parameters"]["transfer"].contains("dt_s"));
}

TEST(ThreatAreaCommand, TextNamesTheBurnWithItsFrameAndUnit) {
  const std::string t = to_text(seed1_result());
  EXPECT_NE(t.find("arc 2543.14 s"), std::string::npos) << t;
  EXPECT_NE(t.find("alpha (pitch) -0.1903 rad, theta (yaw) -3.1399 rad in VVLH"),
            std::string::npos) << t;
  EXPECT_NE(t.find("dv_vvlh [-19.6391, -0.0332, +3.7821] m/s"), std::string::npos) << t;
  EXPECT_NE(t.find("dv_rsw [-3.7821, -19.6391, +0.0332] m/s"), std::string::npos) << t;
  EXPECT_NE(t.find("threat intervals (s after t0): [0.00, 2543.14]"), std::string::npos) << t;
}

}  // namespace
}  // namespace evade::threat
