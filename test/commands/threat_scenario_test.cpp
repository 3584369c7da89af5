// Tests of the threat-area parameter tables and scenario reader (paper 001 sec. 4.1 geometry;
// threat_params.hpp, threat_scenario.hpp).
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "evade/config/scenario.hpp"
#include "evade/core/constants.hpp"
#include "evade/threat/threat_params.hpp"
#include "evade/commands/threat_scenario.hpp"
#include "seed1_geometry.hpp"

namespace evade::threat {
namespace {

using testing::seed1_geometry;
using testing::seed1_options;

// The seed1 keys without the optional ones (their defaults are the table's).
const char* const kMinimalDoc = R"(
earth: {mu_m3ps2: 3.986005e14, re_m: 6371110.0}
target: {altitude_m: 370000.0}
chaser: {relative_rsw_m: [0.0, -100000.0, 0.0], relative_rsw_mps: [0.0, 0.0, 0.0],
         dv_max_mps: 324.0}
transfer: {dt_s: 2200.0, impulses: 3}
)";

// The config::ConfigError text of reading `doc` with `assignment` applied ("" if none).
std::string read_error(const std::string& doc, const std::string& assignment) {
  config::Scenario sc = config::Scenario::from_yaml_string(doc, "doc");
  if (!assignment.empty()) sc.apply_override(assignment);
  try {
    commands::read_threat_scenario(sc);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ThreatScenario, Seed1GivesThePaperGeometryAndOptions) {
  const ThreatScenario in = commands::read_threat_scenario(config::Scenario::load("seed1"));
  EXPECT_EQ(in.earth.mu_m3ps2, 3.986005e14);
  EXPECT_EQ(in.earth.re_m, 6371110.0);
  EXPECT_EQ(in.geometry.n_radps, seed1_geometry().n_radps);
  EXPECT_EQ(in.geometry.chaser0_rsw, seed1_geometry().chaser0_rsw);
  EXPECT_EQ(in.geometry.target0_rsw, Vec6::Zero());
  const ThreatOptions o = seed1_options();
  EXPECT_EQ(in.threat.dv_max_mps, o.dv_max_mps);
  EXPECT_EQ(in.threat.transfer_s, o.transfer_s);
  EXPECT_EQ(in.threat.impulses, o.impulses);
  EXPECT_EQ(in.threat.step_s, o.step_s);
  EXPECT_EQ(in.threat.edge_tol_s, 0.05);
  EXPECT_EQ(in.threat.threads, 2);
  EXPECT_EQ(in.evasion.population, 60);
  EXPECT_EQ(in.evasion.max_evaluations, 1200);
  EXPECT_EQ(in.evasion.seed, 1u);
  EXPECT_EQ(in.evasion.alpha_min_rad, -90.0 * kDegToRad);
  EXPECT_EQ(in.evasion.theta_max_rad, 180.0 * kDegToRad);
  EXPECT_EQ(in.evasion_dv_mps, 20.0);
  EXPECT_EQ(in.elimination_tol_mps, 0.05);
  EXPECT_EQ(in.target_inclination_deg, 42.77);
}

TEST(ThreatScenario, OptionalKeysTakeTheLibraryDefaults) {
  const ThreatScenario in =
      commands::read_threat_scenario(config::Scenario::from_yaml_string(kMinimalDoc, "doc"));
  const ThreatOptions lib;
  EXPECT_EQ(in.threat.step_s, lib.step_s);
  EXPECT_EQ(in.threat.edge_tol_s, lib.edge_tol_s);
  EXPECT_EQ(in.threat.threads, lib.threads);
  const EvasionOptions ev;
  EXPECT_EQ(in.evasion.population, ev.population);
  EXPECT_EQ(in.evasion.max_evaluations, ev.max_evaluations);
  EXPECT_EQ(in.evasion.seed, ev.seed);
  EXPECT_DOUBLE_EQ(in.evasion.alpha_min_rad, ev.alpha_min_rad);
  EXPECT_DOUBLE_EQ(in.evasion.alpha_max_rad, ev.alpha_max_rad);
  EXPECT_DOUBLE_EQ(in.evasion.theta_min_rad, ev.theta_min_rad);
  EXPECT_DOUBLE_EQ(in.evasion.theta_max_rad, ev.theta_max_rad);
}

TEST(ThreatScenario, RejectsABadThreatParameterNamingTheKey) {
  const std::string doc = kMinimalDoc;
  for (const char* assignment :
       {"chaser.dv_max_mps=-1", "transfer.dt_s=nan", "transfer.impulses=5", "sweep.step_s=0",
        "sweep.threads=0", "evasion.population=1", "evasion.seed=-1",
        "evasion.alpha_min_deg=100", "elimination.tol_mps=0", "target.altitude_m=1e3",
        "earth.mu_m3ps2=1"}) {
    const std::string key = std::string(assignment).substr(0, std::string(assignment).find('='));
    const std::string error = read_error(doc, assignment);
    EXPECT_NE(error.find("key '" + key + "'"), std::string::npos) << assignment << ": " << error;
    EXPECT_NE(error.find("is invalid"), std::string::npos) << error;
  }
}

TEST(ThreatScenario, MissingRequiredKeysAndUnknownKeysAreNamed) {
  const std::string doc = kMinimalDoc;
  const std::string no_dt = doc.substr(0, doc.find("transfer:")) + "transfer: {impulses: 3}\n";
  const std::string error = read_error(no_dt, "");
  EXPECT_NE(error.find("key 'transfer.dt_s' = '<missing>'"), std::string::npos) << error;
  EXPECT_NE(error.find("required key"), std::string::npos) << error;
  EXPECT_NE(read_error(doc, "sweep.step=5").find("sweep.step"), std::string::npos);
}

TEST(ThreatParams, ValidateNamesTheKeyAndDefaultsAreValid) {
  EXPECT_NO_THROW(ThreatGeometryParams{}.validate());
  EXPECT_NO_THROW(ThreatOptionParams{}.validate());
  EXPECT_NO_THROW(EvasionParams{}.validate());
  ThreatOptionParams p;
  p.sweep.threads = 0;
  try {
    p.validate();
    ADD_FAILURE() << "accepted sweep.threads = 0";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("key 'sweep.threads' = '0'"), std::string::npos)
        << e.what();
  }
  EvasionParams e;
  e.evasion.theta_max_deg = 181.0;
  EXPECT_THROW(e.validate(), std::invalid_argument);
  // Each table names its keys once: the field path is the scenario key.
  EXPECT_EQ(std::string(threat_option_params().begin()->spec.key), "chaser.dv_max_mps");
  EXPECT_EQ(threat_geometry_params().size(), 2u);
  EXPECT_EQ(threat_option_params().size(), 6u);
  EXPECT_EQ(evasion_params().size(), 17u);
  // The table's defaults are the optimizer's defaults.
  const EvasionOptions from_table = EvasionParams{}.options();
  const EvasionOptions defaults;
  EXPECT_EQ(from_table.use_isres, defaults.use_isres);
  EXPECT_EQ(from_table.max_evaluations, defaults.max_evaluations);
  EXPECT_EQ(from_table.sweep_alpha_cells, defaults.sweep_alpha_cells);
  EXPECT_EQ(from_table.sweep_theta_cells, defaults.sweep_theta_cells);
  EXPECT_EQ(from_table.sweep_edge_tol_s, defaults.sweep_edge_tol_s);
  EXPECT_EQ(from_table.local_starts, defaults.local_starts);
  EXPECT_EQ(from_table.local_xtol_rad, defaults.local_xtol_rad);
  EXPECT_EQ(from_table.certify_max_cells, defaults.certify_max_cells);
  EXPECT_EQ(from_table.certify_rel_tol, defaults.certify_rel_tol);
}

}  // namespace
}  // namespace evade::threat
