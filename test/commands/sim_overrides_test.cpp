// Run-time overrides of the paper-000 simulation scenario (sim_overrides.hpp): each given value
// replaces its scenario key (range-checked by the parameter tables, echoed in used()), the
// angles-only sensor rule, and read_sim_config's checks naming the key.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "evade/config/param_flags.hpp"
#include "evade/config/scenario.hpp"
#include "evade/commands/sim_overrides.hpp"

namespace {

using namespace evade;

TEST(SimOverrides, NothingGivenKeepsTheScenario) {
  config::Scenario plain = config::Scenario::load("seed0");
  config::Scenario sc = config::Scenario::load("seed0");
  commands::apply_sim_overrides(commands::SimOverrides{}, &sc);
  const sim::SimConfig a = commands::read_sim_config(plain);
  const sim::SimConfig b = commands::read_sim_config(sc);
  EXPECT_EQ(a.guidance.max_accel_mps2, b.guidance.max_accel_mps2);
  EXPECT_EQ(a.encounter.detect_before_tca_s, b.encounter.detect_before_tca_s);
  EXPECT_EQ(a.sensor.noise_rad, b.sensor.noise_rad);
  EXPECT_TRUE(b.sensor.has_rates);
  EXPECT_EQ(plain.used(), sc.used());
}

TEST(SimOverrides, EachValueReplacesItsKeyExactly) {
  config::Scenario sc = config::Scenario::load("seed0");
  commands::SimOverrides o;
  // Not a short decimal: the double itself arrives (no text form on the way).
  o.params.push_back({"guidance.max_accel_mps2", 0.1 + 0.2});
  o.params.push_back({"encounter.detect_before_tca_s", 12.5});
  o.params.push_back({"sensor.rate_hz", 25.0});
  o.params.push_back({"guidance.rate_hz", 20.0});
  commands::apply_sim_overrides(o, &sc);
  const sim::SimConfig c = commands::read_sim_config(sc);
  EXPECT_EQ(c.guidance.max_accel_mps2, 0.1 + 0.2);
  EXPECT_EQ(c.encounter.detect_before_tca_s, 12.5);
  EXPECT_EQ(c.sensor.rate_hz, 25.0);
  EXPECT_EQ(c.guidance.rate_hz, 20.0);
  EXPECT_TRUE(c.sensor.has_rates);
  EXPECT_EQ(sc.used()["encounter"]["detect_before_tca_s"].get<double>(), 12.5);
}

TEST(SimOverrides, AngleNoiseAloneSelectsTheAnglesOnlySensor) {
  config::Scenario sc = config::Scenario::load("seed0");
  commands::SimOverrides o;
  o.params.push_back({"sensor.noise_rad", 5e-05});
  commands::apply_sim_overrides(o, &sc);
  const sim::SimConfig c = commands::read_sim_config(sc);
  EXPECT_EQ(c.sensor.noise_rad, 50e-6);
  EXPECT_FALSE(c.sensor.has_rates);
}

TEST(SimOverrides, AngleAndRateNoiseKeepTheMeasuredRates) {
  config::Scenario sc = config::Scenario::load("seed0");
  commands::SimOverrides o;
  o.params.push_back({"sensor.noise_rad", 5e-05});
  o.params.push_back({"sensor.rate_noise_radps", 1e-06});
  commands::apply_sim_overrides(o, &sc);
  const sim::SimConfig c = commands::read_sim_config(sc);
  EXPECT_TRUE(c.sensor.has_rates);
  EXPECT_EQ(c.sensor.rate_noise_radps, 1e-6);
}

TEST(SimOverrides, NoRatesSelectsAnglesOnlyWithoutNoise) {
  config::Scenario sc = config::Scenario::load("seed0");
  commands::SimOverrides o;
  o.no_rates = true;
  commands::apply_sim_overrides(o, &sc);
  const sim::SimConfig c = commands::read_sim_config(sc);
  EXPECT_FALSE(c.sensor.has_rates);
  EXPECT_EQ(c.sensor.noise_rad, 0.0);
}

TEST(SimOverrides, OutOfRangeValueIsNamedByItsKey) {
  config::Scenario sc = config::Scenario::load("seed0");
  commands::SimOverrides o;
  o.params.push_back({"guidance.max_accel_mps2", -1.0});
  commands::apply_sim_overrides(o, &sc);
  try {
    (void)commands::read_sim_config(sc);
    FAIL() << "expected an error naming guidance.max_accel_mps2";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("guidance.max_accel_mps2"), std::string::npos)
        << e.what();
  }
}

TEST(SimOverrides, ReadSimConfigRejectsAnUnusedKey) {
  config::Scenario sc = config::Scenario::load("seed0");
  sc.apply_override("sensor.noise=1e-6");
  try {
    (void)commands::read_sim_config(sc);
    FAIL() << "expected an error naming sensor.noise";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("sensor.noise"), std::string::npos) << e.what();
  }
}

}  // namespace
