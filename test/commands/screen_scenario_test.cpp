// The screening scenario reader (screen_scenario.hpp): paper 002's seed2 reads completely
// with the paper's constants, and every bad or missing number is rejected naming its key,
// through the same parameter tables the option structs validate with.
#include <gtest/gtest.h>

#include <string>

#include "evade/config/scenario.hpp"
#include "evade/commands/screen_objects.hpp"
#include "evade/commands/screen_scenario.hpp"
#include "evade/core/epoch.hpp"

namespace evade::conjunction {
namespace {

using namespace evade::commands;

std::string error_of(const config::Scenario& sc) {
  try {
    (void)read_screen_scenario(sc);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

std::string error_with(const std::string& assignment) {
  config::Scenario sc = config::Scenario::load("seed2");
  sc.apply_override(assignment);
  return error_of(sc);
}

TEST(ScreenScenario, Seed2ReadsCompletely) {
  const config::Scenario sc = config::Scenario::load("seed2");
  const ScreenScenario in = read_screen_scenario(sc);
  EXPECT_EQ(in.epoch_utc, "1999-10-01 00:00:00");
  EXPECT_EQ(in.epoch_j2000_s,
            seconds_since_j2000_from_calendar(parse_calendar_utc("1999-10-01 00:00:00")));
  EXPECT_EQ(in.span_s, 43200.0);
  EXPECT_EQ(in.gravity, GravityModel::kTwoBody);
  EXPECT_EQ(in.earth.mu_m3ps2, 3.986005e14);  // the paper's constant, stated by seed2
  EXPECT_EQ(in.earth.re_m, 6378137.0);
  EXPECT_EQ(in.paper_step.h_sim_s, 60.0);
  EXPECT_EQ(in.paper_step.n_warning, 5.0);
  EXPECT_EQ(in.paper_step.m_warning_period, 3.0);
  EXPECT_EQ(in.paper_step.l_enlarge, 5.0);
  EXPECT_EQ(in.paper_step.l_reduce, 5.0);
  EXPECT_EQ(in.robust.threshold_m, 1000.0);
  EXPECT_EQ(in.robust.step_s, 60.0);
  EXPECT_EQ(in.robust.leaf_s, 0.5);
  EXPECT_EQ(in.robust.warning_multiple, in.paper_step.n_warning);
  EXPECT_EQ(in.robust.earth.mu_m3ps2, in.earth.mu_m3ps2);
  EXPECT_EQ(in.robust.gravity, in.gravity);
  EXPECT_EQ(objects_from_scenario(sc, in.earth).size(), 2u);
  EXPECT_NO_THROW(sc.check_all_used());
}

TEST(ScreenScenario, DefaultsWhereTheScenarioIsSilent) {
  const config::Scenario sc =
      config::Scenario::from_yaml_string("span_s: 100\ngravity: two_body_j2\n", "test");
  const ScreenScenario in = read_screen_scenario(sc);
  EXPECT_EQ(in.gravity, GravityModel::kTwoBodyJ2);
  EXPECT_EQ(in.earth.mu_m3ps2, kEarthDefault.mu_m3ps2);
  EXPECT_EQ(in.paper_step.h_sim_s, PaperStepParams{}.h_sim_s);
  EXPECT_EQ(in.robust.threshold_m, ScreenOptions{}.threshold_m);
  EXPECT_EQ(in.robust.gravity, GravityModel::kTwoBodyJ2);
}

TEST(ScreenScenario, RejectsBadValuesNamingTheKey) {
  std::string m = error_with("robust.threshold_m=-1");
  EXPECT_NE(m.find("key 'robust.threshold_m' = '-1' is invalid"), std::string::npos) << m;
  m = error_with("robust.leaf_s=0");
  EXPECT_NE(m.find("robust.leaf_s"), std::string::npos) << m;
  m = error_with("paper_step.l_reduce=1");  // L_D > 1
  EXPECT_NE(m.find("paper_step.l_reduce"), std::string::npos) << m;
  m = error_with("paper_step.h_sim_s=.nan");
  EXPECT_NE(m.find("paper_step.h_sim_s"), std::string::npos) << m;
  m = error_with("earth.mu_m3ps2=1");
  EXPECT_NE(m.find("earth.mu_m3ps2"), std::string::npos) << m;
  m = error_with("span_s=0");
  EXPECT_NE(m.find("span_s"), std::string::npos) << m;
  m = error_with("gravity=three_body");
  EXPECT_NE(m.find("gravity"), std::string::npos) << m;
}

TEST(ScreenScenario, MissingSpanIsARequiredKey) {
  const std::string m = error_of(config::Scenario::from_yaml_string("gravity: two_body\n", "test"));
  EXPECT_NE(m.find("key 'span_s'"), std::string::npos) << m;
  EXPECT_NE(m.find("required"), std::string::npos) << m;
}

TEST(ScreenScenario, OptionStructsValidateWithTheSameTables) {
  ScreenOptions o;
  o.threshold_m = -1.0;
  try {
    o.validate();
    ADD_FAILURE() << "accepted threshold_m = -1";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("robust.threshold_m"), std::string::npos) << e.what();
  }
  PaperStepParams p;
  p.n_warning = 1.0;
  try {
    p.validate();
    ADD_FAILURE() << "accepted n_warning = 1";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("paper_step.n_warning"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace evade::conjunction
