// A Monte Carlo campaign across the ranks of an MpiSession (issue 13): rank r runs the run
// indices [R r / P, R (r + 1) / P) with the per-run seeds of sim::run_monte_carlo_range
// (from the run index, so any run is reproducible alone); rank 0 gathers the per-run
// results in run order (MPI_Gatherv) and computes the same summary as one process.
#pragma once

#include <cstdint>
#include <functional>

#include "evade/distributed/mpi_session.hpp"
#include "evade/sim/monte_carlo.hpp"
#include "evade/sim/run_hooks.hpp"

namespace evade::distributed {

/// On rank 0: the campaign's result (identical to sim::run_monte_carlo). On the others: an
/// empty result (no runs). on_done(done, total) counts this rank's runs.
sim::MonteCarloResult run_monte_carlo_distributed(const sim::SimConfig& base, int runs,
                                                  std::uint64_t seed, int threads,
                                                  const MpiSession& session,
                                                  const std::function<void(int, int)>& on_done = {});

/// A sim::MonteCarloRunner (`evade sim --runs`, sim_command.hpp): the campaign over the ranks
/// of an MpiSession opened for it (one process unless started by mpirun); ranks = its size,
/// reporting on rank 0 only.
sim::MonteCarloCampaign run_monte_carlo_campaign(const sim::SimConfig& base, int runs,
                                                 std::uint64_t seed, int threads,
                                                 const std::function<void(int, int)>& on_done);

}  // namespace evade::distributed
