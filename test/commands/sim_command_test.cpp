// `evade sim` as a library call (sim_command.hpp, sim_plan_command.hpp): the run on the
// shipped seed0 scenario against paper 000 (Yao & Wang 2012) Table 2, the JSON keys the CLI
// prints, the guidance and Monte Carlo hooks (how lcm_link and distributed plug in), and the
// plan mode's planned against delivered Δv.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "evade/config/scenario.hpp"
#include "evade/commands/plan_file.hpp"
#include "evade/commands/sim_command.hpp"
#include "evade/commands/sim_plan_command.hpp"

namespace {

using namespace evade;

// seed0 with the acceleration and detection time of one Table 2 entry.
config::Scenario seed0(double accel_mps2, double detect_s) {
  config::Scenario sc = config::Scenario::load("seed0");
  sc.apply_override("guidance.max_accel_mps2=" + std::to_string(accel_mps2));
  sc.apply_override("encounter.detect_before_tca_s=" + std::to_string(detect_s));
  return sc;
}

TEST(SimCommand, Seed0MissIsPaper000Table2) {
  const commands::SimCommandRequest req = commands::read_sim_command_request(seed0(1.0, 10.0));
  const commands::SimCommandResult r = commands::run_sim_command(req);
  ASSERT_TRUE(r.run.closest_approach_found);
  // Paper 000 Table 2: a = 1 m/s², detected 10 s before TCA: miss 50.0021 m (2 cm at 50 Hz).
  EXPECT_NEAR(r.run.miss_m, 50.0021, 0.02);
  EXPECT_EQ(r.guidance, "in_process");
  EXPECT_FALSE(r.monte_carlo.has_value());
  EXPECT_TRUE(r.reporting);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.parameters.max_accel_mps2, 1.0);
  EXPECT_EQ(r.parameters.scenario, "seed0");
  EXPECT_NE(commands::to_text(r).find("miss 50.00"), std::string::npos);
}

TEST(SimCommand, JsonHasTheKeysTheCliPrints) {
  const commands::SimCommandResult r =
      commands::run_sim_command(commands::read_sim_command_request(seed0(1.0, 10.0)));
  const nlohmann::json j = commands::to_json(r);
  for (const char* key :
       {"miss_m", "tca_s", "dv_mps", "burn_s", "cycles", "start_s", "nominal_tca_s",
        "nominal_miss_m", "measurements", "dropouts", "guidance", "final_mode", "final_reason",
        "guidance_dv_used_mps", "meas_accepted", "meas_rejected", "filter_reinits",
        "parameters", "scenario_used"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  // The echo names each parameter by its own key (guidance.max_accel_mps2 under "guidance").
  for (const char* key : {"guidance", "encounter", "sensor", "gravity", "scenario"}) {
    EXPECT_TRUE(j["parameters"].contains(key)) << key;
  }
  EXPECT_EQ(j["parameters"]["guidance"]["max_accel_mps2"], 1.0);
  EXPECT_EQ(j["parameters"]["encounter"]["detect_before_tca_s"], 10.0);
  for (const char* key : {"noise_rad", "rate_hz", "has_rates", "rate_noise_radps"}) {
    EXPECT_TRUE(j["parameters"]["sensor"].contains(key)) << key;
  }
  EXPECT_TRUE(j["parameters"]["guidance"].contains("rate_hz"));
  EXPECT_FALSE(j.contains("sensors_signed"));
  EXPECT_FALSE(j.contains("runs"));
  EXPECT_EQ(j["scenario_used"]["guidance"]["max_accel_mps2"], 1.0);
}

TEST(SimCommand, GuidanceLinkAndMonteCarloRunnerAreTheCallers) {
  commands::SimCommandRequest req = commands::read_sim_command_request(seed0(1.0, 10.0));
  int endpoints = 0;
  req.guidance.name = "lcm";
  req.guidance.sensors_signed = false;
  req.guidance.make_endpoint = [&]() {
    ++endpoints;
    return sim::make_in_process_endpoint(req.config.guidance, req.config.guidance.armed);
  };
  req.runs = 3;
  req.seed = 7;
  req.monte_carlo = [](const sim::SimConfig&, int runs, std::uint64_t, int,
                       const std::function<void(int, int)>&) {
    sim::MonteCarloCampaign c;
    c.result.miss_p50_m = 42.0 + runs;
    c.ranks = 2;
    return c;
  };
  const commands::SimCommandResult r = commands::run_sim_command(req);
  EXPECT_EQ(endpoints, 1);
  const nlohmann::json j = commands::to_json(r);
  EXPECT_EQ(j["guidance"], "lcm");
  EXPECT_EQ(j["sensors_signed"], false);
  EXPECT_EQ(j["runs"], 3);
  EXPECT_EQ(j["ranks"], 2);
  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["miss_m_p50"], 45.0);
  EXPECT_NE(commands::to_text(r).find("monte carlo 3 runs"), std::string::npos);
}

TEST(SimCommand, MonteCarloInThisProcessByDefault) {
  config::Scenario sc = seed0(1.0, 10.0);
  sc.apply_override("sensor.noise_rad=5e-05");
  commands::SimCommandRequest req = commands::read_sim_command_request(sc);
  req.runs = 4;
  req.seed = 3;
  int calls = 0;
  req.on_progress = [&calls](int, int) { ++calls; };
  const commands::SimCommandResult r = commands::run_sim_command(req);
  ASSERT_TRUE(r.monte_carlo.has_value());
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(r.monte_carlo->ranks, 1);
  EXPECT_LE(r.monte_carlo->result.miss_min_m, r.monte_carlo->result.miss_p50_m);
  EXPECT_NEAR(r.monte_carlo->result.miss_p50_m, 50.0, 0.5);
}

// A 2 m/s along-track impulse at the plan's t = 0, 10 s into the run (the CLI test's case).
TEST(SimPlanCommand, ImpulseDeliveredAsPlannedAndJsonKeys) {
  commands::PlanFile f;
  f.plan.plan_id = 1;
  f.plan.n_impulses = 1;
  f.plan.impulses[0].t_s = 0.0;
  f.plan.impulses[0].dv_rsw_mps = Vec3(0.0, 2.0, 0.0);
  const std::string path = ::testing::TempDir() + "sim_plan_command_test.json";
  commands::write_plan_file(path, f);
  commands::SimPlanRequest req = commands::read_sim_plan_request(config::Scenario::load("seed0"));
  req.plan_file = path;
  req.plan_epoch_s = 10.0;
  const commands::SimPlanResult r = commands::run_sim_plan(req);
  ASSERT_EQ(r.impulses.size(), 1u);
  EXPECT_TRUE(r.all_delivered);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_NEAR(r.impulses[0].dv_delivered_mps, 2.0, 1e-5);
  EXPECT_NEAR(r.impulses[0].centre_offset_s, 0.0, 1e-9);
  const nlohmann::json j = commands::to_json(r);
  for (const char* key : {"guidance", "plan", "impulses", "burns_delivered", "cycles",
                          "duration_s", "guidance_rate_hz", "scenario", "scenario_used"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["guidance"], "in_process_plan");
  EXPECT_EQ(j["plan"]["frame"], "rsw");
  EXPECT_EQ(j["impulses"][0]["dv_planned_rsw_mps"].size(), 3u);
  EXPECT_NE(commands::to_text(r).find("impulse at 10.000 s: planned 2.000000000 m/s"),
            std::string::npos);
  (void)std::remove(path.c_str());
}

TEST(SimPlanCommand, BurnBeforeTheRunStartNamesTheEpochFlag) {
  commands::PlanFile f;
  f.plan.n_impulses = 1;
  f.plan.impulses[0].dv_rsw_mps = Vec3(0.0, 2.0, 0.0);
  const std::string path = ::testing::TempDir() + "sim_plan_command_t0.json";
  commands::write_plan_file(path, f);
  commands::SimPlanRequest req = commands::read_sim_plan_request(config::Scenario::load("seed0"));
  req.plan_file = path;
  try {
    (void)commands::run_sim_plan(req);
    ADD_FAILURE() << "a burn at the run's start was flown";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--plan-epoch-s S starts it later"), std::string::npos);
  }
  (void)std::remove(path.c_str());
}

}  // namespace
