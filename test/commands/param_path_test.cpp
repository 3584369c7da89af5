// One parameter's way from argv to the guidance law (docs/ARCHITECTURE.md "A parameter's
// way"): guidance.max_accel_mps2 set by its flag (the CLI's registration, apps/common), by
// --set, by the scenario file, and by nothing (the declared default) reaches
// GuidanceLaw::config() as the very double given. 0.1 + 0.2 = 0.30000000000000004 has no
// short decimal form, so a value that went through text with too few digits would differ in
// its last bit; a flag's value travels as that double (ParamValue), never as text.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include "evade/commands/sim_overrides.hpp"
#include "evade/config/read_params.hpp"
#include "evade/config/scenario.hpp"
#include "evade/guidance/guidance_law.hpp"
#include "evade/guidance/guidance_params.hpp"
#include "param_flag_option.hpp"

namespace {

using namespace evade;

const double kValue = 0.1 + 0.2;

// The law's max_accel_mps2 after `evade sim --scenario seed0 ARGS...` has parsed ARGS.
double law_accel_from_flags(const std::vector<std::string>& args, const std::vector<std::string>& sets) {
  CLI::App app;
  std::vector<ParamValue> values;
  (void)cli::add_param_flag(app, guidance::guidance_params(), "guidance.", "guidance.max_accel_mps2",
                            &values);
  std::vector<std::string> argv(args.rbegin(), args.rend());  // CLI11 takes them reversed
  app.parse(argv);
  config::Scenario sc = config::Scenario::load("seed0");
  for (const std::string& s : sets) sc.apply_override(s);
  commands::apply_sim_overrides({values, false}, &sc);
  const guidance::GuidanceLaw law(commands::read_sim_config(sc).guidance);
  return law.config().max_accel_mps2;
}

TEST(ParamPath, AFlagsValueReachesTheLawAsTheDoubleGiven) {
  EXPECT_EQ(law_accel_from_flags({"--max-accel-mps2", "0.30000000000000004"}, {}), kValue);
  EXPECT_EQ(law_accel_from_flags({"--accel", "0.30000000000000004"}, {}), kValue);  // alias
}

TEST(ParamPath, SetAndTheScenarioFileGiveTheSameDouble) {
  EXPECT_EQ(law_accel_from_flags({}, {"guidance.max_accel_mps2=0.30000000000000004"}), kValue);
  config::Scenario sc = config::Scenario::from_yaml_string(
      "guidance:\n  max_accel_mps2: 0.30000000000000004\n", "inline");
  guidance::GuidanceConfig c;
  config::read_params(sc, "guidance.", guidance::guidance_params(), &c);
  EXPECT_EQ(guidance::GuidanceLaw(c).config().max_accel_mps2, kValue);
}

TEST(ParamPath, AFlagWinsOverSetAndTheFile) {
  EXPECT_EQ(law_accel_from_flags({"--max-accel-mps2", "0.30000000000000004"},
                                 {"guidance.max_accel_mps2=7"}),
            kValue);
  // Without the flag the file's value (seed0: 1 m/s^2, paper 000 Table 2's first column).
  EXPECT_EQ(law_accel_from_flags({}, {}), 1.0);
}

TEST(ParamPath, ABadFlagValueIsRefusedAtParseNamingTheFlagAndTheKey) {
  try {
    (void)law_accel_from_flags({"--max-accel-mps2", "-1"}, {});
    FAIL() << "accepted -1";
  } catch (const CLI::ValidationError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--max-accel-mps2"), std::string::npos) << m;
    EXPECT_NE(m.find("guidance.max_accel_mps2"), std::string::npos) << m;
  }
}

}  // namespace
