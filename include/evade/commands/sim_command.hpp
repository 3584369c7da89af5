// `evade sim` as a library call: the closed-loop close-range evasion simulation of paper 000
// (Yao & Wang, "Active collision avoidance maneuver strategy for on-orbit spacecraft", 2012,
// sec. 4 and Table 2) on a scenario's objects: one run with the guidance behind a
// GuidanceEndpoint (the in-process law by default; evade_guidance_node over LCM through
// lcm_link::sim_lcm_guidance), optionally a Monte Carlo over noise seeds (threads in this
// process by default; MPI ranks through distributed::run_monte_carlo_campaign). The result's
// JSON and text forms are the command's output. The burn-plan mode (`--plan`) is
// sim_plan_command.hpp; the caller's guidance link and Monte Carlo runner are
// sim/run_hooks.hpp.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/config/scenario.hpp"
#include "evade/sim/monte_carlo.hpp"
#include "evade/sim/realtime_simulator.hpp"
#include "evade/sim/run_hooks.hpp"
#include "evade/sim/sim_config.hpp"
#include "evade/sim/simulator.hpp"

namespace evade::commands {

struct SimCommandRequest {
  sim::SimConfig config;              ///< the scenario's simulation (read_sim_command_request)
  std::string scenario_source;        ///< the scenario's name or file
  nlohmann::json scenario_used;       ///< every scenario key read, with its value
  int runs = 0;                       ///< Monte Carlo runs after the single run (0: none) [-]
  std::uint64_t seed = 1;             ///< Monte Carlo seed [-]
  int threads = 2;                    ///< Monte Carlo threads [-]
  sim::SimGuidanceLink guidance;      ///< the single run's guidance
  sim::MonteCarloRunner monte_carlo;  ///< empty: run_monte_carlo in this process
  sim::SampleCallback on_sample;      ///< each sample of the single run (the time history)
  std::function<void(int, int)> on_progress;  ///< Monte Carlo (done, total), serialized
};

/// The SimConfig of sc (read_sim_config: every key checked, none unread) and its echo.
/// Throws config::ConfigError or std::invalid_argument naming the key.
SimCommandRequest read_sim_command_request(const config::Scenario& sc);

/// The simulation parameters a run used (echoed as "parameters", each under its own key:
/// {"guidance": {"max_accel_mps2", "rate_hz"}, "encounter": {"detect_before_tca_s"},
/// "sensor": {"noise_rad", "rate_hz", "has_rates", "rate_noise_radps"}, "gravity", "scenario"}).
struct SimParametersUsed {
  double max_accel_mps2 = 0.0;       ///< guidance.max_accel_mps2
  double detect_before_tca_s = 0.0;  ///< encounter.detect_before_tca_s
  double noise_rad = 0.0;            ///< sensor angle noise 1-sigma
  double sensor_rate_hz = 0.0;
  bool sensor_has_rates = true;      ///< the sensor measures the LOS rates
  double rate_noise_radps = 0.0;     ///< sensor angle-rate noise 1-sigma
  double guidance_rate_hz = 0.0;
  GravityModel gravity = GravityModel::kTwoBodyJ2;
  std::string scenario;              ///< the scenario's name or file
};

struct SimMonteCarloSummary {
  int runs = 0;
  std::uint64_t seed = 0;
  int ranks = 1;
  sim::MonteCarloResult result;  ///< miss percentiles, extremes and mean [m]
};

struct SimCommandResult {
  sim::SimResult run;                   ///< the single run (times in s from the epoch)
  std::string guidance = "in_process";  ///< where its guidance ran
  std::optional<bool> sensors_signed;   ///< over LCM: nav, angles and clock signed
  std::optional<sim::RealtimeResult> realtime;  ///< a real-time run's link and timing figures
  std::optional<SimMonteCarloSummary> monte_carlo;
  bool reporting = true;  ///< false on MPI ranks other than 0: nothing to print
  SimParametersUsed parameters;
  nlohmann::json scenario_used;
  std::vector<std::string> warnings;  ///< for stderr (fell behind the wall clock, no TCA)
};

/// Runs req: the single run, then (when it found a closest approach and runs > 0) the Monte
/// Carlo. No closest approach: run.closest_approach_found false and a warning, no Monte
/// Carlo. Throws std::invalid_argument for a bad request, std::runtime_error when the
/// integration or the link fails.
SimCommandResult run_sim_command(const SimCommandRequest& req);

/// The command's JSON (the keys of `evade sim --json`).
nlohmann::json to_json(const SimCommandResult& r);

/// The command's text: miss, TCA, Δv, burn, cycles; the Monte Carlo percentiles.
std::string to_text(const SimCommandResult& r);

}  // namespace evade::commands
