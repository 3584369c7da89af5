// MPI process group (see mpi_session.hpp; MPI standard 3.1, sec. 8.7: MPI_Init_thread,
// MPI_Finalize). Compiled with EVADE_HAVE_MPI when CMake found MPI and EVADE_WITH_MPI is on.
#include "evade/distributed/mpi_session.hpp"

#include <cstdlib>
#include <exception>

#ifdef EVADE_HAVE_MPI
#include <mpi.h>
#endif

namespace evade::distributed {
namespace {

// Environment variables set by MPI launchers (Open MPI's mpirun, PMIx, PMI-1/2).
bool started_by_mpi_launcher() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr ||
         std::getenv("PMI_RANK") != nullptr;
}

}  // namespace

bool MpiSession::built_with_mpi() {
#ifdef EVADE_HAVE_MPI
  return true;
#else
  return false;
#endif
}

MpiSession::MpiSession() {
#ifdef EVADE_HAVE_MPI
  if (!started_by_mpi_launcher()) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    int provided = 0;
    // Worker threads never call MPI: only the main thread does (FUNNELED).
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    active_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#else
  (void)started_by_mpi_launcher;
#endif
}

MpiSession::~MpiSession() {
#ifdef EVADE_HAVE_MPI
  if (!active_) return;
  // Left by an exception (one rank failed): the other ranks may wait in a collective call
  // forever, so end the whole job (MPI_Abort) rather than finalize this rank alone.
  if (std::uncaught_exceptions() > 0) MPI_Abort(MPI_COMM_WORLD, 1);
  MPI_Finalize();
#endif
}

}  // namespace evade::distributed
