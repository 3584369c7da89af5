// Paper 003 scenario reading: the shipped seed3 scenarios load and every bad input (NaN,
// negative box, T <= 0, unknown key, inconsistent timing) is rejected naming the key.
#include <string>

#include <gtest/gtest.h>

#include "evade/formation/formation_scenario.hpp"

namespace evade::formation {
namespace {

config::Scenario seed3_with(const std::string& assignment) {
  config::Scenario sc = config::Scenario::load("seed3");
  if (!assignment.empty()) sc.apply_override(assignment);
  return sc;
}

void expect_config_error(const std::string& assignment, const std::string& key) {
  const config::Scenario sc = seed3_with(assignment);
  try {
    (void)read_plan_inputs(sc);
    sc.check_all_used();
    ADD_FAILURE() << "accepted " << assignment;
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST(FormationScenario, Seed3LoadsCompletely) {
  const config::Scenario sc = seed3_with("");
  const PlanInputs in = read_plan_inputs(sc);
  EXPECT_NO_THROW(sc.check_all_used());
  EXPECT_EQ(in.spec.groups.size(), 2u);
  EXPECT_EQ(in.spec.groups[in.threatened.group].name, "F1");
  EXPECT_EQ(in.threatened.role, Role::kChief);
  EXPECT_DOUBLE_EQ(in.timing.burn_before_tca_s, 18 * 3600.0);   // paper: 18 h before
  EXPECT_DOUBLE_EQ(in.timing.restore_after_tca_s, 12 * 3600.0); // paper: 12 h after
  EXPECT_DOUBLE_EQ(in.spec.horizon_days, 3.0);                  // paper: T = 3 days
  const config::Scenario inf = config::Scenario::load("seed3-infeasible");
  EXPECT_NO_THROW((void)read_plan_inputs(inf));
  EXPECT_NO_THROW(inf.check_all_used());
}

TEST(FormationScenario, RejectsBadInput) {
  expect_config_error("formation.box_delta_m=-5", "formation.box_delta_m");
  expect_config_error("formation.horizon_days=0", "formation.horizon_days");
  expect_config_error("formation.horizon_days=-3", "formation.horizon_days");
  expect_config_error("formation.groups.1.chief.a_m=.nan", "formation.groups.1.chief.a_m");
  expect_config_error("formation.groups.0.deputy1.i_deg=.inf", "formation.groups.0.deputy1.i_deg");
  expect_config_error("conjunction.required_miss_m=-1", "conjunction.required_miss_m");
  expect_config_error("conjunction.group=F9", "conjunction.group");
  expect_config_error("conjunction.satellite=deputy3", "conjunction.satellite");
  expect_config_error("formation.reference_group=Fx", "formation.reference_group");
  expect_config_error("maneuver.burn_before_tca_s=200000", "maneuver.burn_before_tca_s");
  expect_config_error("conjunction.v_rel_rsw_mps=[0,0,0]", "v_rel_rsw_mps");
  expect_config_error("formation.groups.1.name=Fbase", "formation.groups.1.name");
  expect_config_error("formation.box_size_m=5000", "formation.box_size_m");  // unknown key
  expect_config_error("propagation.samples_per_rev=4", "propagation.samples_per_rev");
}

}  // namespace
}  // namespace evade::formation
