// The parameter flags (evade/config/param_flags.hpp) against the parameters' declarations:
// every flag sets a declared key, carries the key's unit suffix, and no spelling is used twice.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "evade/assessment/assess_params.hpp"
#include "evade/config/param_flags.hpp"
#include "evade/config/read_params.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/commands/screen_scenario.hpp"
#include "evade/guidance/guidance_params.hpp"
#include "evade/guidance_lcm/node_params.hpp"
#include "evade/sim/sim_params.hpp"
#include "evade/threat/threat_params.hpp"

namespace {

using namespace evade;

const ParamSpec* declaration(const std::string& key) {
  if (const ParamSpec* s = config::find_param_spec(guidance::guidance_params(), "guidance.", key))
    return s;
  if (const ParamSpec* s = config::find_param_spec(guidance_lcm::node_params(), "node.", key))
    return s;
  if (const ParamSpec* s = config::find_param_spec(sim::sim_params(), "", key)) return s;
  if (const ParamSpec* s = config::find_param_spec(threat::threat_option_params(), "", key))
    return s;
  if (const ParamSpec* s = config::find_param_spec(threat::threat_geometry_params(), "", key))
    return s;
  if (const ParamSpec* s = config::find_param_spec(threat::evasion_params(), "", key)) return s;
  if (const ParamSpec* s = config::find_param_spec(commands::screen_scenario_params(), "", key))
    return s;
  if (const ParamSpec* s = config::find_param_spec(assessment::assess_params(), "assessment.", key))
    return s;
  return config::find_param_spec(conjunction::screen_options_params(), "robust.", key);
}

TEST(ParamFlags, EveryFlagSetsADeclaredKeyAndCarriesItsUnit) {
  std::size_t n = 0;
  const config::ParamFlagRow* rows = config::param_flag_rows(&n);
  ASSERT_GT(n, 0u);
  std::set<std::string> spellings;
  for (std::size_t i = 0; i < n; ++i) {
    const ParamSpec* spec = declaration(rows[i].key);
    ASSERT_NE(spec, nullptr) << rows[i].key << " is not declared in any parameter table";
    EXPECT_EQ(config::param_flag_problem(rows[i], *spec), "") << rows[i].flag;
    EXPECT_TRUE(spellings.insert(rows[i].flag).second) << rows[i].flag << " used twice";
    std::string aliases = rows[i].aliases;
    for (std::size_t b = 0; !aliases.empty() && b <= aliases.size();) {
      const std::size_t e = std::min(aliases.find(',', b), aliases.size());
      EXPECT_TRUE(spellings.insert(aliases.substr(b, e - b)).second) << aliases;
      b = e + 1;
    }
  }
}

TEST(ParamFlags, AFlagWithoutItsUnitOrNamingTheWrongUnitIsAProblem) {
  const ParamSpec* rate = declaration("guidance.rate_hz");
  ASSERT_NE(rate, nullptr);
  EXPECT_NE(config::param_flag_problem({"guidance.rate_hz", "--guidance-rate", ""}, *rate), "");
  EXPECT_NE(config::param_flag_problem({"guidance.rate_hz", "--guidance-rate-s", ""}, *rate), "");
  EXPECT_NE(config::param_flag_problem({"guidance.rate_hz", "--x-hz", "--x-hz"}, *rate), "");
  EXPECT_EQ(config::param_flag_problem({"guidance.rate_hz", "--x-hz", "--x"}, *rate), "");
  const ParamSpec* queue = declaration("node.queue_capacity");
  ASSERT_NE(queue, nullptr);
  EXPECT_NE(config::param_flag_problem({"node.queue_capacity", "--queue", ""}, *queue), "");
}

TEST(ParamFlags, ValuesAreCheckedAgainstTheDeclarationNamingFlagAndKey) {
  const config::ParamFlagRow* row = config::find_param_flag("guidance.max_accel_mps2");
  ASSERT_NE(row, nullptr);
  const ParamSpec* spec = declaration(row->key);
  ASSERT_NE(spec, nullptr);
  EXPECT_EQ(config::param_flag_value(*row, *spec, "2.5"), 2.5);
  for (const char* bad : {"nan", "inf", "-1", "0", "1e9", "1x", ""}) {
    try {
      (void)config::param_flag_value(*row, *spec, bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("--max-accel-mps2"), std::string::npos) << m;
      EXPECT_NE(m.find("guidance.max_accel_mps2"), std::string::npos) << m;
      EXPECT_NE(m.find("(0, 100] m/s^2"), std::string::npos) << m;
    }
  }
  // 17 significant digits: the override reads back as the same double.
  EXPECT_EQ(config::param_override_text("k", 0.1), "k=0.10000000000000001");
  EXPECT_EQ(config::param_flag_markdown("guidance.max_accel_mps2"),
            "`--max-accel-mps2` (also `--accel-mps2`, `--accel`)");
  EXPECT_EQ(config::param_flag_markdown("guidance.armed"), "");
}

}  // namespace
