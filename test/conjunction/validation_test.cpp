// Bad objects are rejected with their index and field (issue 6): negative size, e >= 1,
// perigee inside the Earth, NaN, in YAML scenarios, CSV text and object lists.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "evade/config/scenario.hpp"
#include "evade/commands/screen_objects.hpp"
#include "evade/conjunction/population.hpp"
#include "evade/conjunction/robust_screen.hpp"

namespace evade::conjunction {
namespace {

using namespace evade::commands;

std::string yaml_with(const std::string& second) {
  return "objects:\n"
         "  - {name: ok, a_m: 7000000, e: 0.001, i_deg: 50, raan_deg: 0, argp_deg: 0, "
         "mean_anomaly_deg: 0, size_m: 1, pos_error_m: 1}\n"
         "  - " + second + "\n";
}

std::string error_of_yaml(const std::string& second) {
  try {
    objects_from_scenario(config::Scenario::from_yaml_string(yaml_with(second), "test"), kEarthDefault);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(RejectsBadObjects, YamlNegativeSizeNamesIndexAndField) {
  const std::string msg = error_of_yaml(
      "{a_m: 7000000, e: 0, i_deg: 50, raan_deg: 0, argp_deg: 0, mean_anomaly_deg: 0, "
      "size_m: -1, pos_error_m: 1}");
  EXPECT_NE(msg.find("objects.1.size_m"), std::string::npos) << msg;
}

TEST(RejectsBadObjects, YamlHyperbolicNamesE) {
  const std::string msg = error_of_yaml(
      "{a_m: 7000000, e: 1.0, i_deg: 50, raan_deg: 0, argp_deg: 0, mean_anomaly_deg: 0, "
      "size_m: 1, pos_error_m: 1}");
  EXPECT_NE(msg.find("objects.1.e"), std::string::npos) << msg;
}

TEST(RejectsBadObjects, YamlElementsHaveTheOneReadersLimits) {
  const std::string msg = error_of_yaml(
      "{a_m: 7000000, e: 1.5, i_deg: 50, raan_deg: 0, argp_deg: 0, mean_anomaly_deg: 0, "
      "size_m: 1, pos_error_m: 1}");
  EXPECT_NE(msg.find("key 'objects.1.e' = '1.5' is invalid: expected a number in [0, 1)"),
            std::string::npos) << msg;
}

TEST(RejectsBadObjects, YamlPerigeeInsideEarth) {
  const std::string msg = error_of_yaml(
      "{a_m: 7000000, e: 0.1, i_deg: 50, raan_deg: 0, argp_deg: 0, mean_anomaly_deg: 0, "
      "size_m: 1, pos_error_m: 1}");
  EXPECT_NE(msg.find("objects.1.a_m"), std::string::npos) << msg;
  EXPECT_NE(msg.find("inside the Earth"), std::string::npos) << msg;
}

TEST(RejectsBadObjects, YamlNaNInCartesianState) {
  const std::string msg =
      error_of_yaml("{r_eci_m: [7000000, .nan, 0], v_eci_mps: [0, 7500, 0], size_m: 1, pos_error_m: 1}");
  EXPECT_NE(msg.find("objects.1.r_eci_m"), std::string::npos) << msg;
}

std::string error_of_csv(const std::string& text) {
  try {
    objects_from_csv(text, kEarthDefault);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(RejectsBadObjects, CsvFieldsNamed) {
  const std::string head = "name,a_m,e,i_deg,raan_deg,argp_deg,mean_anomaly_deg,size_m,pos_error_m\n";
  const std::string good = "a,7000000,0,50,0,0,0,1,1\n";
  EXPECT_EQ(error_of_csv(head + good + good), "");
  std::string m = error_of_csv(head + good + "b,7000000,0,50,0,0,0,-2,1\n");
  EXPECT_NE(m.find("object 1"), std::string::npos) << m;
  EXPECT_NE(m.find("size_m"), std::string::npos) << m;
  m = error_of_csv(head + good + "b,7000000,1.2,50,0,0,0,1,1\n");
  EXPECT_NE(m.find("object 1"), std::string::npos) << m;
  EXPECT_NE(m.find(": e ="), std::string::npos) << m;
  m = error_of_csv(head + good + "b,6000000,0,50,0,0,0,1,1\n");
  EXPECT_NE(m.find("inside the Earth"), std::string::npos) << m;
  m = error_of_csv(head + good + "b,7000000,0,50,0,400,0,1,1\n");  // the one angle limit
  EXPECT_NE(m.find("argp_deg = 400 outside [-360, 360] deg"), std::string::npos) << m;
  m = error_of_csv(head + good + "b,7000000,nan,50,0,0,0,1,1\n");
  EXPECT_NE(m.find("object 1"), std::string::npos) << m;
  EXPECT_NE(m.find(" e "), std::string::npos) << m;
}

TEST(RejectsBadObjects, CsvCartesianParses) {
  const auto objs = objects_from_csv(
      "name,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,size_m,pos_error_m\n"
      "s,7000000,0,0,0,7546,0,2,0.5\n",
      kEarthDefault);
  ASSERT_EQ(objs.size(), 1u);
  EXPECT_EQ(objs[0].name, "s");
  EXPECT_DOUBLE_EQ(objs[0].size_m, 2.0);
}

TEST(RejectsBadObjects, ObjectListsCheckedBeforeScreening) {
  PopulationOptions pop;
  pop.count = 5;
  auto objs = synthetic_population(pop);
  auto expect_field = [&](const std::vector<SpaceObject>& o, const std::string& field) {
    try {
      screen_robust(o, 100.0, ScreenOptions{});
      ADD_FAILURE() << "accepted bad " << field;
    } catch (const std::invalid_argument& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("object 3"), std::string::npos) << m;
      EXPECT_NE(m.find(field), std::string::npos) << m;
    }
  };
  auto bad = objs;
  bad[3].size_m = -1.0;
  expect_field(bad, "size_m");
  bad = objs;
  bad[3].pos_error_m = std::nan("");
  expect_field(bad, "pos_error_m");
  bad = objs;
  bad[3].state.v_eci_mps *= 2.0;  // escape speed: e >= 1
  expect_field(bad, "e =");
  bad = objs;
  bad[3].state.v_eci_mps *= 0.5;  // perigee deep inside the Earth
  expect_field(bad, "perigee_radius_m");
  bad = objs;
  bad[3].state.r_eci_m.x() = std::nan("");
  expect_field(bad, "r_eci_m");
}

TEST(RejectsBadOptions, ScreenOptionsNamed) {
  ScreenOptions o;
  o.step_s = -1.0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = ScreenOptions{};
  o.threshold_m = std::nan("");
  EXPECT_THROW(o.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace evade::conjunction
