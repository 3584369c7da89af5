// Monte Carlo campaign across MPI ranks (issue 13; see distributed_monte_carlo.hpp). Each
// rank sends its per-run miss and delta-v (2 doubles per run, run order) to rank 0 with
// MPI_Gatherv (MPI standard 3.1, sec. 5.5); rank 0 summarizes as sim::run_monte_carlo.
#include "evade/distributed/distributed_monte_carlo.hpp"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#ifdef EVADE_HAVE_MPI
#include <mpi.h>
#endif

namespace evade::distributed {

sim::MonteCarloResult run_monte_carlo_distributed(const sim::SimConfig& base, int runs,
                                                  std::uint64_t seed, int threads,
                                                  const MpiSession& session,
                                                  const std::function<void(int, int)>& on_done) {
  if (session.size() == 1) return sim::run_monte_carlo(base, runs, seed, threads, on_done);
  if (runs < 1) throw std::invalid_argument("monte carlo: runs = " + std::to_string(runs) +
                                            " outside [1, inf)");
  const long p = session.size(), r = session.rank();
  const int begin = static_cast<int>(runs * r / p);
  const int end = static_cast<int>(runs * (r + 1) / p);
  sim::MonteCarloRuns mine = sim::run_monte_carlo_range(base, begin, end, seed, threads, on_done);
#ifdef EVADE_HAVE_MPI
  std::vector<double> send;
  send.reserve(2 * mine.miss_m.size());
  for (std::size_t k = 0; k < mine.miss_m.size(); ++k) {
    send.push_back(mine.miss_m[k]);
    send.push_back(mine.dv_mps[k]);
  }
  std::vector<int> counts(static_cast<std::size_t>(p)), displs(static_cast<std::size_t>(p));
  for (long q = 0; q < p; ++q) {
    const auto b = static_cast<int>(runs * q / p), e = static_cast<int>(runs * (q + 1) / p);
    counts[static_cast<std::size_t>(q)] = 2 * (e - b);
    displs[static_cast<std::size_t>(q)] = 2 * b;
  }
  std::vector<double> recv(r == 0 ? 2 * static_cast<std::size_t>(runs) : 0);
  MPI_Gatherv(send.data(), static_cast<int>(send.size()), MPI_DOUBLE, recv.data(), counts.data(),
              displs.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if (r != 0) return {};
  std::vector<double> miss(static_cast<std::size_t>(runs)), dv(static_cast<std::size_t>(runs));
  for (std::size_t k = 0; k < miss.size(); ++k) {
    miss[k] = recv[2 * k];
    dv[k] = recv[2 * k + 1];
  }
  return sim::summarize_monte_carlo(std::move(miss), std::move(dv));
#else
  return sim::summarize_monte_carlo(std::move(mine.miss_m), std::move(mine.dv_mps));
#endif
}

sim::MonteCarloCampaign run_monte_carlo_campaign(const sim::SimConfig& base, int runs,
                                                 std::uint64_t seed, int threads,
                                                 const std::function<void(int, int)>& on_done) {
  const MpiSession mpi;
  sim::MonteCarloCampaign c;
  c.result = run_monte_carlo_distributed(base, runs, seed, threads, mpi, on_done);
  c.ranks = mpi.size();
  c.reporting = mpi.rank() == 0;
  return c;
}

}  // namespace evade::distributed
