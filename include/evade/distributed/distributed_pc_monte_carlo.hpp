// The Monte Carlo Pc (assessment/monte_carlo_pc.hpp) across the ranks of an MpiSession: each
// wave of blocks is split into contiguous parts, rank r computes part r on its threads, and
// MPI_Allreduce (MPI standard 3.1, sec. 5.9.6) sums the per-block hit counts, so every rank
// holds every block's hits and applies the same stopping rule. Block b's samples come from
// its own generator seeded with (seed, b): the result is identical to one process.
#pragma once

#include "evade/assessment/monte_carlo_pc.hpp"
#include "evade/distributed/mpi_session.hpp"

namespace evade::distributed {

/// A block runner over session's ranks (the threaded runner when session has one rank).
assessment::McBlockRunner mpi_mc_block_runner(const MpiSession& session);

/// threads per rank, a wave of threads x ranks blocks and the runner above.
assessment::McExecution mpi_mc_execution(int threads, const MpiSession& session);

}  // namespace evade::distributed
