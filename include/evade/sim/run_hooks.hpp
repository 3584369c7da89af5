// What the caller of a simulation command supplies (commands/sim_command.hpp; paper 000, Yao
// & Wang 2012): where the single run's guidance runs (the in-process law by default;
// evade_guidance_node over LCM through lcm_link::sim_lcm_guidance) and who runs the Monte
// Carlo over noise seeds (threads in this process by default; MPI ranks through
// distributed::run_monte_carlo_campaign).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "evade/sim/guidance_endpoint.hpp"
#include "evade/sim/monte_carlo.hpp"
#include "evade/sim/realtime_link.hpp"
#include "evade/sim/sim_config.hpp"

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

}  // namespace evade::sim
