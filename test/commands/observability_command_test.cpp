// `evade plan observability` as a library call (observability_command.hpp) on the shipped
// scenario seed4 (paper 004, Yu, Wang, Zhou, "Anti-rendezvous evasive maneuver considering
// spatial geometry", §3): the request has the paper's numbers, the plan lands within the
// issue's 0.02 rad of the published optimum θ = −3.231 over the paper's 101 samples, the JSON
// has every key the CLI prints, and the reader keeps its rules (required keys, the --seed
// and --objective overrides, no earth.j2 in the HCW model, the parameter table's ranges).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "evade/config/read_params.hpp"
#include "evade/config/scenario.hpp"
#include "evade/commands/observability_command.hpp"
#include "evade/observability/observability_params.hpp"
#include "seed4_problem.hpp"

namespace evade::observability {
namespace {

using namespace evade::commands;

// seed4 with `--set` style overrides.
config::Scenario seed4_with(const std::vector<std::string>& sets) {
  config::Scenario sc = config::Scenario::load("seed4");
  for (const std::string& s : sets) sc.apply_override(s);
  return sc;
}

std::string config_error(const std::vector<std::string>& sets,
                         const ObservabilityOverrides& ov = {}) {
  try {
    const config::Scenario sc = seed4_with(sets);
    (void)read_observability_request(sc, ov);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ObservabilityCommand, RequestHasTheSeed4Numbers) {
  const config::Scenario sc = config::Scenario::load("seed4");
  const ObservabilityRequest req = read_observability_request(sc);
  const ObservabilityProblem ref = test::seed4();
  EXPECT_EQ(req.problem.n_radps, ref.n_radps);
  EXPECT_EQ(req.problem.x_chaser_p0, ref.x_chaser_p0);
  EXPECT_EQ(req.problem.dv_mps, 3.0);
  EXPECT_EQ(req.problem.dt_obs_s, 10.0);
  EXPECT_EQ(req.problem.t_obs_s, 1000.0);
  EXPECT_EQ(req.problem.eps_max_rad, 0.05);
  EXPECT_EQ(req.objective, ObjectiveKind::kPaper);
  EXPECT_EQ(req.isres.seed, 1u);
  EXPECT_EQ(req.isres.population, 80);
  EXPECT_EQ(req.isres.max_evaluations, 2400);
  EXPECT_EQ(req.isres.polish, LocalPolish::kBobyqa);
  EXPECT_EQ(req.paper.optimum_theta_rad, test::kPaperThetaRad);
  EXPECT_EQ(req.paper.a_theta_rad, test::kThetaA);
  EXPECT_EQ(req.paper.b_theta_rad, test::kThetaB);
  EXPECT_EQ(req.paper_f, 100.9991);
  EXPECT_EQ(req.estimation.prior_sigma(3), 5.0);
  EXPECT_EQ(req.used["earth"]["re_m"], 6378137.0);
  EXPECT_FALSE(req.used["earth"].contains("j2"));  // HCW: J2 is not part of the model
}

TEST(ObservabilityCommand, Seed4PlanNearThePublishedOptimumAndJsonKeys) {
  const config::Scenario sc = config::Scenario::load("seed4");
  const ObservabilityResult r = run_observability(read_observability_request(sc));
  // Paper §3: 0.1 Hz over 1000 s, k = 0..100; optimum θ = −3.231 (ours ≈ −3.2456, within
  // the 0.02 rad; the peak is flat, docs/VALIDATION.md), ε = 0, |Δv| = 3 m/s.
  EXPECT_EQ(r.samples, 101u);
  EXPECT_NEAR(r.plan.theta_rad, test::kPaperThetaRad, 0.02);
  EXPECT_NEAR(r.plan.eps_rad, 0.0, 1e-3);
  EXPECT_NEAR(r.plan.dv_rsw_mps.norm(), 3.0, 1e-12);
  EXPECT_GT(r.plan.value, 96.0);
  EXPECT_LT(r.plan.value, 97.0);  // eq. 23 cannot reach the paper's 100.9991 (its early terms ≈ cos 30°)
  ASSERT_EQ(r.comparison.compare.size(), 4u);
  EXPECT_EQ(r.comparison.compare[0].direction.name, "no-burn");

  const nlohmann::json j = to_json(r);
  for (const char* key :
       {"compare", "dv_lvlh_mps", "dv_paper_mps", "eps_rad", "estimation", "evaluations", "frame",
        "history", "isres", "los_change_sum_rad", "max_azimuth_change_rad",
        "max_elevation_change_rad", "name", "objective", "paper", "paper_f", "samples",
        "scenario", "theta_rad", "used", "value"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j.size(), 21u);
  for (const char* key : {"seed", "population", "max_evaluations", "evaluations", "raw_value",
                          "raw_theta_rad", "raw_eps_rad", "polish", "nlopt_result", "runtime_s"}) {
    EXPECT_TRUE(j["isres"].contains(key)) << key;
  }
  EXPECT_EQ(j["objective"], "paper");
  EXPECT_EQ(j["compare"].size(), 4u);
  EXPECT_EQ(j["compare"][0]["theta_rad"], nullptr);  // no burn: no direction
  EXPECT_EQ(j["paper"]["f"], 100.9991);
  EXPECT_EQ(j["samples"], 101);

  const std::string text = to_text(r);
  EXPECT_NE(text.find("objective paper = "), std::string::npos) << text;
  EXPECT_NE(text.find("rad (paper frame P"), std::string::npos) << text;
  EXPECT_NE(text.find("dv_lvlh_mps = ["), std::string::npos) << text;
  EXPECT_NE(text.find("major axis"), std::string::npos) << text;
}

TEST(ObservabilityCommand, OverridesReplaceTheScenarioAndAreNotEchoed) {
  const config::Scenario sc = config::Scenario::load("seed4");
  const ObservabilityRequest req = read_observability_request(sc, {"los-change", 7});
  EXPECT_EQ(req.objective, ObjectiveKind::kLosChange);
  EXPECT_EQ(req.isres.seed, 7u);
  EXPECT_FALSE(req.used["isres"].contains("seed"));
  EXPECT_FALSE(req.used["objective"].contains("name"));
  EXPECT_EQ(req.isres.population, 80);  // the rest of the table is still read
  const config::Scenario sc2 = config::Scenario::load("seed4");
  EXPECT_THROW((void)read_observability_request(sc2, {"", 2147483648L}), std::invalid_argument);
}

TEST(ObservabilityCommand, ReaderErrorsNameTheKey) {
  const std::string missing = config_error({"evader=~"});
  EXPECT_NE(missing.find("evader.altitude_m"), std::string::npos) << missing;
  EXPECT_NE(missing.find("required key"), std::string::npos) << missing;
  const std::string bad = config_error({"burn.eps_max_rad=2"});
  EXPECT_NE(bad.find("burn.eps_max_rad"), std::string::npos) << bad;
  const std::string seed = config_error({"isres.seed=-1"});
  EXPECT_NE(seed.find("isres.seed"), std::string::npos) << seed;
  const std::string earth = config_error({"earth.mu_m3ps2=1"});
  EXPECT_NE(earth.find("earth.mu_m3ps2"), std::string::npos) << earth;
  const std::string j2 = config_error({"earth.j2=0.001"});  // unknown to the HCW model
  EXPECT_NE(j2.find("earth.j2"), std::string::npos) << j2;
  const std::string lists = config_error({"compare.a_eps_theta_rad=[0,1,2]"});
  EXPECT_NE(lists.find("expected [eps, theta]"), std::string::npos) << lists;
}

TEST(ObservabilityCommand, ParamsTableDefaultsAndRequiredKeys) {
  const ObservabilityParams p;
  EXPECT_TRUE(std::isnan(p.burn.dv_mps));  // required: NaN is outside every range
  EXPECT_THROW(p.validate(), std::invalid_argument);
  const std::string md = config::params_markdown("", observability_params());
  EXPECT_NE(md.find("| `burn.dv_mps` | m/s | (required) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| `isres.max_evaluations` | - | 2400 |"), std::string::npos) << md;
}

TEST(ObservabilityInput, ValidateKeepsItsMessages) {
  ObservabilityProblem p = test::seed4();
  p.theta_min_rad = -1.0;
  try {
    validate(p);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "observability problem: theta_min_rad = -1 is invalid; allowed: < theta_max_rad = "
              "-1.570796 (inverted or empty bounds)");
  }
  p = test::seed4();
  p.t_obs_s = 5.0;
  try {
    validate(p);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "observability problem: t_obs_s = 5 is invalid; allowed: finite, >= dt_obs_s (at "
              "least one sample after t0)");
  }
  p = test::seed4();
  p.theta_max_rad = std::nan("");
  EXPECT_THROW(validate(p), std::invalid_argument);
  p = test::seed4();
  p.n_radps = 0.0;
  EXPECT_THROW(validate(p), std::invalid_argument);
}

}  // namespace
}  // namespace evade::observability
