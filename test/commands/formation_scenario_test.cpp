// Paper 003 scenario reading: the shipped seed3 scenarios load and every bad input (NaN,
// negative box, T <= 0, unknown key, inconsistent timing) is rejected naming the key; the
// scalars go through their parameter tables (a missing required key is named, the Earth
// model has the Earth table's one range).
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "evade/core/earth_params.hpp"
#include "evade/commands/formation_scenario.hpp"

namespace evade::formation {
namespace {

using namespace evade::commands;

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

// The elements go through the one element reader (its limits: e in [0, 1)); the
// near-circular model's tighter limit is the formation's own, with its reason.
TEST(FormationScenario, ElementsHaveTheOneReadersLimitsAndTheModelsOwn) {
  const auto error_of = [](const std::string& assignment) -> std::string {
    try {
      (void)read_plan_inputs(seed3_with(assignment));
    } catch (const config::ConfigError& e) {
      return e.what();
    }
    return "<no error>";
  };
  std::string m = error_of("formation.groups.1.deputy1.e=1.5");
  EXPECT_NE(m.find("key 'formation.groups.1.deputy1.e' = '1.5' is invalid: expected a number in [0, 1)"),
            std::string::npos) << m;
  m = error_of("formation.groups.1.deputy1.e=0.05");
  EXPECT_NE(m.find("deputy1.e"), std::string::npos) << m;
  EXPECT_NE(m.find("near-circular"), std::string::npos) << m;
  m = error_of("formation.groups.0.chief.raan_deg=400");
  EXPECT_NE(m.find("expected a number in [-360, 360] deg"), std::string::npos) << m;
}

// seed3.yaml's text without the line holding `key:` (the key then is missing).
std::string seed3_text_without(const std::string& key) {
  for (const std::string& dir : config::scenario_search_dirs()) {
    std::ifstream f(dir + "/seed3.yaml");
    if (!f) continue;
    std::ostringstream out;
    std::string line;
    while (std::getline(f, line)) {
      if (line.find(key + ":") == std::string::npos) out << line << "\n";
    }
    return out.str();
  }
  ADD_FAILURE() << "seed3.yaml not found";
  return "";
}

TEST(FormationScenario, MissingRequiredScalarIsNamed) {
  for (const std::string key : {"side_length_m", "horizon_days", "tca_s", "required_miss_m"}) {
    const config::Scenario sc = config::Scenario::from_yaml_string(seed3_text_without(key), "t");
    try {
      (void)read_plan_inputs(sc);
      ADD_FAILURE() << "accepted a scenario without " << key;
    } catch (const config::ConfigError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("." + key + "'"), std::string::npos) << m;
      EXPECT_NE(m.find("required"), std::string::npos) << m;
    }
  }
}

TEST(FormationScenario, TablesGiveTheRangesAndDefaults) {
  expect_config_error("formation.box_delta_m=20000", "formation.box_delta_m");  // > L/8
  expect_config_error("formation.raan_tolerance_deg=0", "formation.raan_tolerance_deg");
  expect_config_error("conjunction.tca_s=.nan", "conjunction.tca_s");
  expect_config_error("maneuver.restore=maybe", "maneuver.restore");
  expect_config_error("propagation.rel_tol=1e-3", "propagation.rel_tol");
  // One range for the Earth constants: the Earth table's (formation's own [6e6, 7e6] is gone).
  expect_config_error("earth.re_m=2e7", "earth.re_m");
  EXPECT_NO_THROW((void)read_plan_inputs(seed3_with("earth.re_m=5.9e6")));
  // Defaults where the scenario is silent: those of the library structs.
  EXPECT_EQ(PropagationParams{}.rel_tol, PropagationSettings{}.integrator.rel_tol);
  EXPECT_EQ(PropagationParams{}.abs_tol_m, PropagationSettings{}.integrator.abs_tol);
  EXPECT_EQ(PropagationParams{}.samples_per_rev, PropagationSettings{}.samples_per_rev);
  const PlanInputs in = read_plan_inputs(seed3_with(""));
  EXPECT_EQ(in.spec.earth.mu_m3ps2, kEarthDefault.mu_m3ps2);  // seed3 states no Earth model
  EXPECT_EQ(in.propagation.samples_per_rev, 32);
  EXPECT_EQ(in.propagation.integrator.rel_tol, 1e-10);
  EXPECT_EQ(in.spec.raan_tolerance_rad, 0.01 * kDegToRad);
}

TEST(FormationScenario, LibraryStructsValidateWithTheSameTables) {
  ConjunctionSpec c;  // no TCA, no required miss
  try {
    c.validate();
    ADD_FAILURE() << "accepted an empty conjunction";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("conjunction.tca_s"), std::string::npos) << e.what();
  }
  ManeuverTiming t;
  t.restore_after_tca_s = -1.0;
  try {
    t.validate(108000.0);
    ADD_FAILURE() << "accepted restore_after_tca_s = -1";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("maneuver.restore_after_tca_s"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace evade::formation
