// `evade plan formation` as a library call (formation_command.hpp): run_formation on the
// shipped seed3 scenario (paper 003, Duan You et al.: the threatened chief, T = 3 days, burn
// 18 h before the TCA) reproduces the paper's K_Ω and the command's decision, and to_json /
// to_text carry the fields the command prints (margins with their unit).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "evade/config/scenario.hpp"
#include "evade/commands/formation_command.hpp"

namespace evade::formation {
namespace {

using namespace evade::commands;

const FormationResult& seed3_result() {
  static const FormationResult r =
      run_formation(read_formation_request(config::Scenario::load("seed3")));
  return r;
}

TEST(FormationCommand, Seed3GivesThePapersKOmegaAndARaise) {
  const FormationResult& r = seed3_result();
  // Paper 003 eq. 2: K_Ω = 2.0953e-8 rad/(m day).
  EXPECT_NEAR(r.limits.k.k_omega_rad_per_m_day, 2.0953e-8, 5e-13);
  EXPECT_TRUE(r.decision.feasible);
  EXPECT_EQ(r.decision.direction, "raise");
  EXPECT_NEAR(r.decision.delta_a_m, 11.8708, 1e-4);
  EXPECT_NEAR(r.decision.burn_time_s, 108000.0 - 18 * 3600.0, 1e-9);  // 18 h before the TCA
  EXPECT_TRUE(r.verification.clears);
  EXPECT_TRUE(r.verification.all_kept);
  EXPECT_FALSE(r.numerical);
}

TEST(FormationCommand, JsonHasTheKeysTheCliPrints) {
  const nlohmann::json j = to_json(seed3_result());
  for (const char* k :
       {"paper", "threatened", "k_omega_rad_per_m_day", "k_omega_deg_per_m_day",
        "k_omega_paper_rad_per_m_day", "k_phi_rad_per_m_day", "k_phi_kepler_rad_per_m_day",
        "k_am_m_per_m_day", "horizon_days", "limits", "raise_max_m", "lower_max_m",
        "raise_binding", "lower_binding", "decision", "verification", "runtime_s",
        "parameters"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  EXPECT_EQ(j["threatened"], "F1.chief");
  EXPECT_EQ(j["limits"].size(), 6u);
  EXPECT_EQ(j["limits"][0]["unit"], "deg");
  EXPECT_FALSE(j["limits"][0].contains("numerical_raise_max_m"));
  EXPECT_EQ(j["decision"]["burns"].size(), 2u);
  EXPECT_TRUE(j["verification"]["all_constraints_kept"].get<bool>());
  EXPECT_TRUE(j["parameters"]["conjunction"].contains("tca_s"));
}

TEST(FormationCommand, TextGivesEachMarginWithItsUnit) {
  const std::string t = to_text(seed3_result());
  EXPECT_NE(t.find("threatened F1.chief, T = 3.00 days"), std::string::npos) << t;
  EXPECT_NE(t.find("inter_group_raan(F1-Fbase)         min margin  0.000104409 rad"),
            std::string::npos) << t;
  EXPECT_NE(t.find("in_plane_deputy1(F1)               min margin      3999.66 m"),
            std::string::npos) << t;
  EXPECT_NE(t.find("burn t = 43200 s after the epoch: delta_a +11.871 m, dv +0.00581 m/s"),
            std::string::npos) << t;
}

TEST(FormationCommand, UnknownKeyIsRefusedNamingIt) {
  config::Scenario sc = config::Scenario::load("seed3");
  sc.apply_override("formation.typo_m=1");
  EXPECT_THROW((void)read_formation_request(sc), config::ConfigError);
}

}  // namespace
}  // namespace evade::formation
