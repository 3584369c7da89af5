// `evade sim` as a library call: the closed-loop close-range evasion simulation of paper 000
// (Yao & Wang, "Active collision avoidance maneuver strategy for on-orbit spacecraft", 2012,
// sec. 4 and Table 2) on a scenario's objects: one run with the guidance behind a
// GuidanceEndpoint (the in-process law by default; evade_guidance_node over LCM through
// lcm_link::sim_lcm_guidance), optionally a Monte Carlo over noise seeds (threads in this
// process by default; MPI ranks through distributed::run_monte_carlo_campaign). The result's
// JSON and text forms are the command's output. The burn-plan mode (`--plan`) is
// sim_plan_command.hpp.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/config/scenario.hpp"
#include "evade/sim/guidance_endpoint.hpp"
#include "evade/sim/monte_carlo.hpp"
#include "evade/sim/realtime_link.hpp"
#include "evade/sim/realtime_simulator.hpp"
#include "evade/sim/sim_config.hpp"
#include "evade/sim/simulator.hpp"

namespace evade::sim {

/// Where the single run's guidance runs. Default: the in-process law, armed as the scenario
/// says. Another endpoint (lockstep exchanges) or a real-time link (a node at its own fixed
/// rate, truth at wall-clock pace) is supplied by the caller (lcm_link::sim_lcm_guidance).
struct SimGuidanceLink {
  std::string name = "in_process";     ///< "guidance" in the JSON
  std::optional<bool> sensors_signed;  ///< echoed as "sensors_signed" when set
  /// The endpoint of a lockstep run (empty: the in-process law).
  std::function<std::unique_ptr<GuidanceEndpoint>()> make_endpoint;
  /// Set: a real-time run against this link (make_endpoint is not used).
  std::function<std::unique_ptr<RealtimeLink>()> make_realtime_link;
};

/// A Monte Carlo campaign as run: the summary, and over how many processes it was spread.
struct MonteCarloCampaign {
  MonteCarloResult result;  ///< on the reporting process
  int ranks = 1;            ///< processes the runs were spread over [-]
  bool reporting = true;    ///< false on MPI ranks other than 0 (rank 0 reports)
};

/// Runs a campaign of `runs` runs of base (as run_monte_carlo: seeds from the run index);
/// on_done(done, total) after each run of this process.
using MonteCarloRunner = std::function<MonteCarloCampaign(
    const SimConfig& base, int runs, std::uint64_t seed, int threads,
    const std::function<void(int, int)>& on_done)>;

struct SimCommandRequest {
  SimConfig config;               ///< the scenario's simulation (read_sim_command_request)
  std::string scenario_source;    ///< the scenario's name or file
  nlohmann::json scenario_used;   ///< every scenario key read, with its value
  int runs = 0;                   ///< Monte Carlo runs after the single run (0: none) [-]
  std::uint64_t seed = 1;         ///< Monte Carlo seed [-]
  int threads = 2;                ///< Monte Carlo threads [-]
  SimGuidanceLink guidance;       ///< the single run's guidance
  MonteCarloRunner monte_carlo;   ///< empty: run_monte_carlo in this process
  SampleCallback on_sample;       ///< each sample of the single run (the time history)
  std::function<void(int, int)> on_progress;  ///< Monte Carlo (done, total), serialized
};

/// The SimConfig of sc (read_sim_config: every key checked, none unread) and its echo.
/// Throws config::ConfigError or std::invalid_argument naming the key.
SimCommandRequest read_sim_command_request(const config::Scenario& sc);

/// The simulation parameters a run used (echoed as "parameters").
struct SimParametersUsed {
  double accel_mps2 = 0.0;           ///< guidance.max_accel_mps2
  double detect_before_tca_s = 0.0;  ///< encounter.detect_before_tca_s
  double noise_rad = 0.0;            ///< sensor angle noise 1-sigma
  double sensor_rate_hz = 0.0;
  bool sensor_rates = true;          ///< the sensor measures the LOS rates
  double rate_noise_radps = 0.0;     ///< sensor angle-rate noise 1-sigma
  double guidance_rate_hz = 0.0;
  GravityModel gravity = GravityModel::kTwoBodyJ2;
  std::string scenario;              ///< the scenario's name or file
};

struct SimMonteCarloSummary {
  int runs = 0;
  std::uint64_t seed = 0;
  int ranks = 1;
  MonteCarloResult result;  ///< miss percentiles, extremes and mean [m]
};

struct SimCommandResult {
  SimResult run;                         ///< the single run (times in s from the epoch)
  std::string guidance = "in_process";   ///< where its guidance ran
  std::optional<bool> sensors_signed;    ///< over LCM: nav, angles and clock signed
  std::optional<RealtimeResult> realtime;  ///< a real-time run's link and timing figures
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

}  // namespace evade::sim
