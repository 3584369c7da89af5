// Values given typed to a scenario (Scenario::set_value: a parameter flag, a Python keyword):
// read as the double itself by the declared-parameter reader and by get_double / get_int /
// get_bool, checked against the reader's range with the one error text, winning over the
// document and --set, echoed in used(), and reported by check_all_used() when nobody reads them.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "evade/config/scenario.hpp"
#include "evade/core/param.hpp"

namespace {

using namespace evade;

const ParamSpec kAccel{"max_accel_mps2", "m/s^2", ParamType::kReal, 0.0, 100.0, true,
                       "test", nullptr, nullptr};
const ParamSpec kCount{"n", "-", ParamType::kInt, 1, 10, false, "test", nullptr, nullptr};
const ParamSpec kFlag{"on", "-", ParamType::kBool, 0, 1, false, "test", nullptr, nullptr};

TEST(ScenarioTypedValues, TheDoubleGivenIsTheDoubleRead) {
  config::Scenario sc = config::Scenario::empty("flags");
  sc.set_value({"g.max_accel_mps2", 0.1 + 0.2});
  EXPECT_EQ(sc.get_param("g.max_accel_mps2", kAccel, 9.0), 0.1 + 0.2);
  EXPECT_EQ(sc.used()["g"]["max_accel_mps2"].get<double>(), 0.1 + 0.2);
  EXPECT_TRUE(sc.has("g.max_accel_mps2"));
  EXPECT_NO_THROW(sc.check_all_used());
}

TEST(ScenarioTypedValues, ATypedValueWinsOverTheDocumentAndSetAndTheLastOneCounts) {
  config::Scenario sc = config::Scenario::from_yaml_string("g:\n  max_accel_mps2: 2\n", "doc");
  sc.set_value({"g.max_accel_mps2", 3.0});
  sc.apply_override("g.max_accel_mps2=4");
  sc.set_value({"g.max_accel_mps2", 5.0});
  EXPECT_EQ(sc.get_param("g.max_accel_mps2", kAccel, 9.0), 5.0);
  EXPECT_EQ(sc.get_double("g.max_accel_mps2", 0.0, 10.0), 5.0);
}

TEST(ScenarioTypedValues, OutOfRangeIsRefusedWithTheOneTextNamingTheKey) {
  config::Scenario sc = config::Scenario::empty("command-line flags");
  for (const double bad : {0.0, -1.0, 1e9, std::nan(""), std::numeric_limits<double>::infinity()}) {
    sc.set_value({"g.max_accel_mps2", bad});
    try {
      (void)sc.get_param("g.max_accel_mps2", kAccel, 1.0);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const config::ConfigError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind("command-line flags: key 'g.max_accel_mps2' = '", 0), 0u) << m;
      EXPECT_NE(m.find("expected a number in (0, 100] m/s^2"), std::string::npos) << m;
    }
  }
}

TEST(ScenarioTypedValues, IntegersAndBooleansMustBeWholeAndZeroOrOne) {
  config::Scenario sc = config::Scenario::empty("flags");
  sc.set_value({"n", 3.0});
  sc.set_value({"on", 1.0});
  EXPECT_EQ(sc.get_param("n", kCount, 1.0), 3.0);
  EXPECT_EQ(sc.get_param("on", kFlag, 0.0), 1.0);
  EXPECT_EQ(sc.get_int("n", 1, 10), 3);
  EXPECT_TRUE(sc.get_bool("on"));
  sc.set_value({"n", 2.5});
  sc.set_value({"on", 0.5});
  EXPECT_THROW((void)sc.get_param("n", kCount, 1.0), config::ConfigError);
  EXPECT_THROW((void)sc.get_int("n", 1, 10), config::ConfigError);
  EXPECT_THROW((void)sc.get_param("on", kFlag, 0.0), config::ConfigError);
  EXPECT_THROW((void)sc.get_bool("on"), config::ConfigError);
}

TEST(ScenarioTypedValues, ATypedValueNobodyReadsIsAnUnknownKey) {
  config::Scenario sc = config::Scenario::empty("flags");
  sc.set_value({"g.max_accel_msp2", 1.0});  // a misspelt key
  try {
    sc.check_all_used();
    FAIL() << "an unread typed value passed";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("g.max_accel_msp2"), std::string::npos) << e.what();
  }
}

}  // namespace
