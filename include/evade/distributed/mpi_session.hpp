// The MPI process group of a distributed `evade` command (issue 13): a thin wrapper over
// MPI_Init / MPI_Finalize (Open MPI; MPI standard 3.1, sec. 8.7). MPI is initialized only
// when the process was started by an MPI launcher (mpirun sets OMPI_COMM_WORLD_SIZE, PMIx
// launchers PMIX_RANK, others PMI_RANK); otherwise, and when evade was built without MPI
// (EVADE_WITH_MPI=OFF), the session is one process of rank 0 and nothing is initialized.
// A session destroyed by an exception's unwinding aborts the whole job (MPI_Abort), so that
// one failing rank does not leave the others waiting in a collective call.
#pragma once

namespace evade::distributed {

class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool active() const { return active_; }  ///< MPI initialized by this session
  /// True if this build can distribute (EVADE_WITH_MPI was found and on).
  static bool built_with_mpi();

 private:
  int rank_ = 0;
  int size_ = 1;
  bool active_ = false;
};

}  // namespace evade::distributed
