// The Monte Carlo Pc across MPI ranks (include/evade/distributed/distributed_pc_monte_carlo.hpp).
#include "evade/distributed/distributed_pc_monte_carlo.hpp"

#include <algorithm>
#include <vector>

#ifdef EVADE_HAVE_MPI
#include <mpi.h>
#endif

namespace evade::distributed {

assessment::McBlockRunner mpi_mc_block_runner(const MpiSession& session) {
  if (session.size() == 1) return &assessment::run_mc_blocks_threaded;
  const long p = session.size(), r = session.rank();
  return [p, r](const assessment::McEncounter& e, const assessment::MonteCarloOptions& opt,
                long first, long count, long* hits) {
    std::fill(hits, hits + count, 0L);
    const long begin = count * r / p, end = count * (r + 1) / p;
    if (end > begin) assessment::run_mc_blocks_threaded(e, opt, first + begin, end - begin, hits + begin);
#ifdef EVADE_HAVE_MPI
    MPI_Allreduce(MPI_IN_PLACE, hits, static_cast<int>(count), MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
#endif
  };
}

assessment::McExecution mpi_mc_execution(int threads, const MpiSession& session) {
  assessment::McExecution x;
  x.threads = std::max(1, threads);
  x.wave_blocks = x.threads * session.size();
  x.runner = mpi_mc_block_runner(session);
  x.ranks = session.size();
  return x;
}

}  // namespace evade::distributed
