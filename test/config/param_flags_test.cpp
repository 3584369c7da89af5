// The parameter flags (evade/config/param_flags.hpp), declared with the parameters' rows:
// every flag carries its key's unit suffix, no spelling is used twice, and the README's flags
// are the ones declared.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "evade/assessment/assess_params.hpp"
#include "evade/config/param_flags.hpp"
#include "evade/config/read_params.hpp"
#include "evade/commands/conjunction_uplink_command.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/commands/screen_scenario.hpp"
#include "evade/guidance/guidance_params.hpp"
#include "evade/guidance_lcm/node_params.hpp"
#include "evade/sim/sim_params.hpp"
#include "evade/threat/threat_params.hpp"

namespace {

using namespace evade;

// Every table a flag can be declared in, with its keys' prefix.
struct Table {
  const char* prefix;
  std::vector<std::pair<std::string, ParamSpec>> rows;  // full key, declaration
};

template <class Cfg>
Table table(const char* prefix, const ParamTable<Cfg>& t) {
  Table out{prefix, {}};
  for (const Param<Cfg>& p : t) out.rows.emplace_back(prefix + std::string(p.spec.key), p.spec);
  return out;
}

std::vector<Table> tables() {
  return {table("guidance.", guidance::guidance_params()),
          table("node.", guidance_lcm::node_params()),
          table("", sim::sim_params()),
          table("", threat::threat_option_params()),
          table("", threat::threat_geometry_params()),
          table("", threat::evasion_params()),
          table("", commands::screen_scenario_params()),
          table("assessment.", assessment::assess_params()),
          table("robust.", conjunction::screen_options_params()),
          table("uplink.", commands::conjunction_uplink_params())};
}

const ParamSpec* declaration(const std::string& key) {
  static const std::vector<Table> all = tables();
  for (const Table& t : all) {
    for (const auto& [k, spec] : t.rows) {
      if (k == key) return &spec;
    }
  }
  return nullptr;
}

ParamSpec with(const ParamSpec& s, const char* flag, const char* aliases) {
  ParamSpec out = s;
  out.flag = flag;
  out.aliases = aliases;
  return out;
}

TEST(ParamFlags, EveryFlagIsDeclaredWithItsKeyCarriesItsUnitAndIsSpelledOnce) {
  std::set<std::string> spellings;
  std::size_t flags = 0;
  for (const Table& t : tables()) {
    for (const auto& [key, spec] : t.rows) {
      if (spec.flag == nullptr) continue;
      ++flags;
      EXPECT_EQ(config::param_flag_problem(key, spec), "") << spec.flag;
      EXPECT_TRUE(spellings.insert(spec.flag).second) << spec.flag << " used twice";
      const std::string aliases = spec.aliases;
      for (std::size_t b = 0; !aliases.empty() && b <= aliases.size();) {
        const std::size_t e = std::min(aliases.find(',', b), aliases.size());
        EXPECT_TRUE(spellings.insert(aliases.substr(b, e - b)).second) << aliases;
        b = e + 1;
      }
    }
  }
  EXPECT_EQ(flags, 24u);  // the flags of README.md "Flags" (7 of them evade conjunction's): each declared with its row
}

TEST(ParamFlags, TheReadmeFlagsSetTheirKeys) {
  const std::pair<const char*, const char*> expected[] = {
      {"guidance.rate_hz", "--guidance-rate-hz"}, {"guidance.stale_limit_s", "--stale-limit-s"},
      {"guidance.max_accel_mps2", "--max-accel-mps2"}, {"node.status_divider", "--status-divider"},
      {"node.queue_capacity", "--queue-capacity"}, {"encounter.detect_before_tca_s", "--detect-s"},
      {"sensor.rate_hz", "--sensor-rate-hz"}, {"sensor.noise_rad", "--noise-rad"},
      {"sensor.rate_noise_radps", "--rate-noise-radps"}, {"evasion.dv_mps", "--dv-mps"},
      {"transfer.dt_s", "--dt-transfer-s"}, {"transfer.impulses", "--impulses"},
      {"span_s", "--span-s"}, {"robust.threshold_m", "--threshold-m"}, {"robust.step_s", "--step-s"},
      {"assessment.window_s", "--window-s"}, {"assessment.mc_max_samples", "--mc-max-samples"}};
  for (const auto& [key, flag] : expected) {
    const ParamSpec* spec = declaration(key);
    ASSERT_NE(spec, nullptr) << key;
    ASSERT_NE(spec->flag, nullptr) << key;
    EXPECT_EQ(std::string(spec->flag), flag) << key;
  }
}

TEST(ParamFlags, AFlagWithoutItsUnitOrNamingTheWrongUnitIsAProblem) {
  const ParamSpec* rate = declaration("guidance.rate_hz");
  ASSERT_NE(rate, nullptr);
  const std::string key = "guidance.rate_hz";
  EXPECT_NE(config::param_flag_problem(key, with(*rate, "--guidance-rate", "")), "");
  EXPECT_NE(config::param_flag_problem(key, with(*rate, "--guidance-rate-s", "")), "");
  EXPECT_NE(config::param_flag_problem(key, with(*rate, "--x-hz", "--x-hz")), "");
  EXPECT_EQ(config::param_flag_problem(key, with(*rate, "--x-hz", "--x")), "");
  EXPECT_NE(config::param_flag_problem(key, with(*rate, nullptr, nullptr)), "");  // none declared
  const ParamSpec* queue = declaration("node.queue_capacity");
  ASSERT_NE(queue, nullptr);
  EXPECT_NE(config::param_flag_problem("node.queue_capacity", with(*queue, "--queue", "")), "");
}

TEST(ParamFlags, ValuesAreCheckedAgainstTheDeclarationNamingFlagAndKey) {
  const std::string key = "guidance.max_accel_mps2";
  const ParamSpec* spec = declaration(key);
  ASSERT_NE(spec, nullptr);
  EXPECT_EQ(config::param_flag_value(key, *spec, "2.5"), 2.5);
  for (const char* bad : {"nan", "inf", "-1", "0", "1e9", "1x", ""}) {
    try {
      (void)config::param_flag_value(key, *spec, bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("--max-accel-mps2"), std::string::npos) << m;
      EXPECT_NE(m.find("guidance.max_accel_mps2"), std::string::npos) << m;
      EXPECT_NE(m.find("(0, 100] m/s^2"), std::string::npos) << m;
    }
  }
  EXPECT_EQ(config::param_flag_markdown(*spec), "`--max-accel-mps2` (also `--accel-mps2`, `--accel`)");
  const ParamSpec* armed = declaration("guidance.armed");
  ASSERT_NE(armed, nullptr);
  EXPECT_EQ(config::param_flag_markdown(*armed), "");
}

}  // namespace
