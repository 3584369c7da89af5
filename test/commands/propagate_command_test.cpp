// `evade propagate` as a library call on the shipped demo-leo scenario: the J2 secular RAAN
// rate (Vallado, "Fundamentals of Astrodynamics and Applications", 4th ed., 2013, eq. 9-41)
// predicts the one-day node regression, the numerical osculating change agrees with it to
// short-period terms, and the JSON carries the keys the CLI prints.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "evade/config/scenario.hpp"
#include "evade/commands/propagate_command.hpp"

namespace evade::commands {
namespace {

TEST(PropagateCommand, DemoLeoNodeRegressionMatchesTheSecularRate) {
  const config::Scenario sc = config::Scenario::load("demo-leo");
  const PropagateRequest req = read_propagate_request(sc);
  EXPECT_EQ(req.params.duration_s, 86400.0);
  EXPECT_EQ(req.params.rel_tol, 1e-11);
  const PropagateResult r = run_propagate(req);
  // dΩ/dt = -3/2 n J2 (Re / p)^2 cos i for a = 7000 km, e = 0.01, i = 51.6 deg: -4.47 deg/day.
  const double a = 7000000.0, e = 0.01, i = 51.6 * kDegToRad;
  const double n = std::sqrt(req.earth.mu_m3ps2 / (a * a * a));
  const double p = a * (1.0 - e * e);
  const double rate = -1.5 * n * req.earth.j2 * std::pow(req.earth.re_m / p, 2) * std::cos(i);
  EXPECT_NEAR(r.secular_delta_raan_deg, rate * 86400.0 * kRadToDeg, 1e-9);
  EXPECT_NEAR(r.secular_delta_raan_deg, -4.47, 0.005);
  EXPECT_NEAR(r.delta_raan_deg, r.secular_delta_raan_deg, 0.1);  // osculating: short-period terms
  EXPECT_GT(r.j2_displacement_from_kepler_m, 1e5);  // a day of J2 moves the satellite far
  EXPECT_GT(r.stats.steps_accepted, 0);
  EXPECT_EQ(format_calendar_utc(r.end_utc), "2016-02-02 00:00:00.000000000");
  const std::string text = to_text(r);
  EXPECT_NE(text.find("2016-02-01 00:00:00.000000000 UTC"), std::string::npos) << text;
}

TEST(PropagateCommand, TwoBodyHasNoSecularDrift) {
  config::Scenario sc = config::Scenario::load("demo-leo");
  sc.apply_override("propagation.model=two-body");
  const PropagateResult r = run_propagate(read_propagate_request(sc));
  EXPECT_EQ(r.secular_delta_raan_deg, 0.0);
  EXPECT_NEAR(r.delta_raan_deg, 0.0, 1e-9);
  EXPECT_NEAR(r.j2_displacement_from_kepler_m, 0.0, 1e-6);
}

TEST(PropagateCommand, JsonHasTheKeysTheCliPrints) {
  config::Scenario sc = config::Scenario::load("demo-leo");
  sc.apply_override("propagation.duration_s=600");
  const nlohmann::json j = to_json(run_propagate(read_propagate_request(sc)));
  for (const char* key : {"epoch_utc", "end_utc", "model", "r_eci_m", "v_eci_mps", "delta_raan_deg",
                          "secular_delta_raan_deg", "j2_displacement_from_kepler_m", "steps",
                          "rejected_steps", "rhs_evaluations", "runtime_s", "parameters"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j.size(), 13u);
  EXPECT_EQ(j["model"], "two-body-j2");
  EXPECT_EQ(j["r_eci_m"].size(), 3u);
  EXPECT_EQ(j["parameters"]["propagation"]["duration_s"], 600.0);
}

TEST(PropagateCommand, BadInputNamesTheKey) {
  auto error_of = [](const std::string& assignment) -> std::string {
    config::Scenario sc = config::Scenario::load("demo-leo");
    sc.apply_override(assignment);
    try {
      (void)read_propagate_request(sc);
    } catch (const config::ConfigError& e) {
      return e.what();
    }
    return "<no error>";
  };
  EXPECT_NE(error_of("propagation.duration_s=0")
                .find("key 'propagation.duration_s' = '0' is invalid: expected a number in [1, "
                      "31536000] s"),
            std::string::npos);
  EXPECT_NE(error_of("propagation.model=n-body").find("propagation.model"), std::string::npos);
  EXPECT_NE(error_of("orbit.e=1.5").find("expected a number in [0, 1)"), std::string::npos);
  EXPECT_NE(error_of("orbit.extra_deg=1").find("orbit.extra_deg"), std::string::npos);  // unread
}

}  // namespace
}  // namespace evade::commands
