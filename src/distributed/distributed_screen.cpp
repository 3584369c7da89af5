// Screening across MPI ranks (issue 13; see distributed_screen.hpp). Messages: per rank, its
// event count and its events as records of 7 doubles (i, j, tca, miss, speed, collision,
// warning; indices below 2^53 are exact in a double) gathered by MPI_Gatherv; the
// statistics as 7 longs summed by MPI_Reduce (MPI standard 3.1, sec. 5.5 and 5.9).
#include "evade/distributed/distributed_screen.hpp"

#include <array>
#include <climits>
#include <cstddef>
#include <stdexcept>
#include <string>

#ifdef EVADE_HAVE_MPI
#include <mpi.h>
#endif

namespace evade::distributed {
namespace {

using conjunction::Conjunction;
using conjunction::ScreenResult;
using conjunction::ScreenStats;

#ifdef EVADE_HAVE_MPI
constexpr int kRecord = 7;

std::vector<double> pack(const std::vector<Conjunction>& ev) {
  std::vector<double> buf;
  buf.reserve(ev.size() * kRecord);
  for (const auto& c : ev) {
    buf.insert(buf.end(), {static_cast<double>(c.i), static_cast<double>(c.j), c.tca_s, c.miss_m,
                           c.rel_speed_mps, c.collision ? 1.0 : 0.0, c.warning ? 1.0 : 0.0});
  }
  return buf;
}

std::vector<Conjunction> unpack(const std::vector<double>& buf) {
  std::vector<Conjunction> ev(buf.size() / kRecord);
  for (std::size_t k = 0; k < ev.size(); ++k) {
    const double* r = &buf[k * kRecord];
    ev[k] = Conjunction{static_cast<std::size_t>(r[0]), static_cast<std::size_t>(r[1]), r[2], r[3],
                        r[4], r[5] != 0.0, r[6] != 0.0};
  }
  return ev;
}

std::array<long, 8> stats_array(const ScreenStats& s) {
  return {s.steps, s.pairs_checked, s.candidates, s.refined, s.root_solves,
          s.pairs_after_apogee_perigee, s.unproven_leaves, s.repeated_roots_merged};
}

ScreenStats stats_from(const std::array<long, 8>& a) {
  ScreenStats s;
  s.steps = a[0];
  s.pairs_checked = a[1];
  s.candidates = a[2];
  s.refined = a[3];
  s.root_solves = a[4];
  s.pairs_after_apogee_perigee = a[5];
  s.unproven_leaves = a[6];
  s.repeated_roots_merged = a[7];
  return s;
}

ScreenResult gather_on_rank0(const ScreenResult& mine, const MpiSession& session) {
  const std::vector<double> send = pack(mine.events);
  const int count = static_cast<int>(send.size());
  std::vector<int> counts(static_cast<std::size_t>(session.size()), 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> displs(counts.size(), 0);
  int total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    displs[r] = total;
    total += counts[r];
  }
  std::vector<double> recv(session.rank() == 0 ? static_cast<std::size_t>(total) : 0);
  MPI_Gatherv(send.data(), count, MPI_DOUBLE, recv.data(), counts.data(), displs.data(),
              MPI_DOUBLE, 0, MPI_COMM_WORLD);
  const std::array<long, 8> s = stats_array(mine.stats);
  std::array<long, 8> sum{};
  MPI_Reduce(s.data(), sum.data(), 8, MPI_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
  if (session.rank() != 0) return mine;
  ScreenResult all;
  conjunction::ScreenResult merged;
  merged.events = unpack(recv);
  merged.stats = stats_from(sum);
  conjunction::merge_screen_results(all, merged);  // sorts the events
  return all;
}
#endif

}  // namespace

void sum_over_ranks(std::vector<double>& v, const MpiSession& session) {
  if (session.size() == 1) return;
  if (v.size() > static_cast<std::size_t>(INT_MAX))
    throw std::length_error("sum_over_ranks: " + std::to_string(v.size()) + " entries exceed one MPI count");
#ifdef EVADE_HAVE_MPI
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
#endif
}

ScreenResult screen_distributed(const std::vector<conjunction::SpaceObject>& objects,
                                double span_s, const conjunction::ScreenOptions& opt,
                                const MpiSession& session) {
  if (session.size() == 1) return conjunction::screen_robust(objects, span_s, opt);
  const ScreenResult mine =
      conjunction::screen_robust_part(objects, span_s, opt, session.rank(), session.size());
#ifdef EVADE_HAVE_MPI
  return gather_on_rank0(mine, session);
#else
  return mine;
#endif
}

}  // namespace evade::distributed
