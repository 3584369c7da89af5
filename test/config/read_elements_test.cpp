// The one reader of Keplerian elements: its limits (a in (0, 1e10] m, e in [0, 1), i in
// [0, 180] deg, angles in [-360, 360] deg, perigee above the surface), its messages (key,
// value, the allowed interval) and its three phase forms.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "evade/config/read_elements.hpp"

namespace evade::config {
namespace {

const char* kOrbit = R"(
orbit:
  a_m: 7000000.0
  e: 0.01
  i_deg: 51.6
  raan_deg: 30.0
  argp_deg: 45.0
  true_anomaly_deg: 10.0
  mean_anomaly_deg: 10.0
  arg_lat_deg: 55.0
)";

Scenario orbit_with(const std::string& assignment) {
  Scenario sc = Scenario::from_yaml_string(kOrbit, "test");
  if (!assignment.empty()) sc.apply_override(assignment);
  return sc;
}

std::string error_of(const std::string& assignment, OrbitPhase phase = OrbitPhase::kTrueAnomaly) {
  try {
    (void)read_elements(orbit_with(assignment), "orbit.", kEarthDefault, phase);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(ReadElements, ReadsEveryFormInRadians) {
  const Scenario sc = orbit_with("");
  const OrbitalElements t = read_elements(sc, "orbit.", kEarthDefault);
  EXPECT_EQ(t.a_m, 7000000.0);
  EXPECT_EQ(t.e, 0.01);
  EXPECT_EQ(t.i_rad, 51.6 * kDegToRad);
  EXPECT_EQ(t.raan_rad, 30.0 * kDegToRad);
  EXPECT_EQ(t.argp_rad, 45.0 * kDegToRad);
  EXPECT_EQ(t.true_anomaly_rad, 10.0 * kDegToRad);
  const OrbitalElements m = read_elements(sc, "orbit.", kEarthDefault, OrbitPhase::kMeanAnomaly);
  EXPECT_EQ(m.true_anomaly_rad, true_from_mean_anomaly(10.0 * kDegToRad, 0.01));
  const OrbitalElements u =
      read_elements(sc, "orbit.", kEarthDefault, OrbitPhase::kArgumentOfLatitude);
  EXPECT_EQ(u.argp_rad, 0.0);
  EXPECT_EQ(u.true_anomaly_rad, 55.0 * kDegToRad);
  EXPECT_EQ(sc.used()["orbit"]["e"], 0.01);  // echoed as a number, as every typed read
}

TEST(ReadElements, EccentricityIsOptionalOnlyInTheArgumentOfLatitudeForm) {
  const Scenario sc = Scenario::from_yaml_string(
      "orbit: {a_m: 7000000, i_deg: 50, raan_deg: 0, arg_lat_deg: 0}\n", "test");
  EXPECT_EQ(read_elements(sc, "orbit.", kEarthDefault, OrbitPhase::kArgumentOfLatitude).e, 0.0);
  EXPECT_EQ(sc.used()["orbit"]["e"], 0.0);
  const Scenario no_e = Scenario::from_yaml_string(
      "orbit: {a_m: 7000000, i_deg: 50, raan_deg: 0, argp_deg: 0, true_anomaly_deg: 0}\n", "test");
  try {
    (void)read_elements(no_e, "orbit.", kEarthDefault);
    ADD_FAILURE() << "accepted a missing e";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "key 'orbit.e' = '<missing>' is invalid: expected a number in [0, 1) (required key)"),
              std::string::npos)
        << e.what();
  }
}

TEST(ReadElements, OneSetOfLimitsWithTheirText) {
  EXPECT_EQ(error_of("orbit.e=1.5"),
            "test: key 'orbit.e' = '1.5' is invalid: expected a number in [0, 1)");
  EXPECT_NE(error_of("orbit.e=1").find("expected a number in [0, 1)"), std::string::npos);
  EXPECT_NE(error_of("orbit.e=-0.1").find("'orbit.e' = '-0.1'"), std::string::npos);
  EXPECT_NE(error_of("orbit.e=0.999").find("perigee"), std::string::npos);  // e itself is allowed
  EXPECT_EQ(error_of("orbit.a_m=nan"),
            "test: key 'orbit.a_m' = 'nan' is invalid: expected a number in (0, 10000000000] m");
  EXPECT_NE(error_of("orbit.a_m=0").find("(0, 10000000000] m"), std::string::npos);
  EXPECT_NE(error_of("orbit.a_m=2e10").find("'orbit.a_m' = '2e10'"), std::string::npos);
  EXPECT_NE(error_of("orbit.i_deg=180.5").find("expected a number in [0, 180] deg"),
            std::string::npos);
  EXPECT_NE(error_of("orbit.raan_deg=400").find("'orbit.raan_deg' = '400' is invalid: expected a "
                                                "number in [-360, 360] deg"),
            std::string::npos);
  EXPECT_NE(error_of("orbit.argp_deg=abc").find("'orbit.argp_deg' = 'abc'"), std::string::npos);
  EXPECT_NE(error_of("orbit.true_anomaly_deg=[1,2]").find("not a list"), std::string::npos);
  EXPECT_NE(error_of("orbit.mean_anomaly_deg=-361", OrbitPhase::kMeanAnomaly)
                .find("orbit.mean_anomaly_deg"),
            std::string::npos);
  EXPECT_NE(error_of("orbit.arg_lat_deg=.inf", OrbitPhase::kArgumentOfLatitude)
                .find("orbit.arg_lat_deg"),
            std::string::npos);
  EXPECT_EQ(error_of(""), "<no error>");
}

TEST(ReadElements, PerigeeMustClearTheEarth) {
  const std::string m = error_of("orbit.e=0.2");  // a (1 - e) = 5600 km
  EXPECT_NE(m.find("'orbit.a_m' = '7000000' and 'orbit.e' = '0.2'"), std::string::npos) << m;
  EXPECT_NE(m.find("perigee radius a (1 - e) = 5600000 m is inside the Earth"), std::string::npos)
      << m;
  EXPECT_NE(error_of("orbit.a_m=6378137").find("inside the Earth"), std::string::npos);
}

TEST(ReadElements, LimitsUsableWithoutAScenario) {
  EXPECT_TRUE(element_value_ok(kEccentricityLimit, 0.0));
  EXPECT_FALSE(element_value_ok(kEccentricityLimit, 1.0));
  EXPECT_FALSE(element_value_ok(kSemiMajorAxisLimit, 0.0));
  EXPECT_TRUE(element_value_ok(kSemiMajorAxisLimit, 1e10));
  EXPECT_FALSE(element_value_ok(kAngleLimit, std::nan("")));
  EXPECT_EQ(element_interval_text(kEccentricityLimit), "[0, 1)");
  EXPECT_EQ(element_interval_text(kInclinationLimit), "[0, 180] deg");
  EXPECT_TRUE(perigee_above_surface(7e6, 0.05, kEarthDefault));
  EXPECT_FALSE(perigee_above_surface(7e6, 0.1, kEarthDefault));
}

}  // namespace
}  // namespace evade::config
