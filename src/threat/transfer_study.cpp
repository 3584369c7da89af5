// Transfer-time study (include/evade/threat/transfer_study.hpp). Paper 001 (Yu, Wang, Sun
// 2017) sec. 2.1, eq. 3 (N-impulse minimum cost, N = 2..4) against ΔT as in Fig. 4, the
// primer-vector bound, and the eliminating burn of sec. 4.2.
#include "evade/threat/transfer_study.hpp"

#include <chrono>

namespace evade::threat {

TransferStudyRow study_transfer_time(const ThreatGeometry& geometry, const ThreatOptions& options,
                                     double transfer_s, const TransferStudyOptions& study) {
  ThreatOptions tt = options;
  tt.transfer_s = transfer_s;
  const ThreatAreaSolver solver(geometry, tt);
  TransferStudyRow row;
  row.dt_transfer_s = transfer_s;
  const Vec6 d0 = solver.required_change(0.0, Vec3::Zero());
  for (int n = 2; n <= 4; ++n) {
    SqpOptions so;
    so.impulses = n;
    so.starts = study.sqp_starts;
    row.cost_t0_mps[n - 2] = optimize_rendezvous(solver.transfer(), d0, so).cost_mps;
  }
  const PrimerBound pb = solver.transfer().primer_bound(d0);
  row.primer_max_t0 = pb.primer_max;
  row.primer_lower_bound_t0_mps = pb.lower_bound_mps;
  row.j_t0_mps = solver.min_cost_plan(0.0, Vec3::Zero()).cost_mps;
  row.t0_bound_mps = tt.dv_max_mps - row.j_t0_mps;
  if (study.eliminate) {
    const auto t0 = std::chrono::steady_clock::now();
    row.elimination =
        find_eliminating_dv(solver, study.evasion, study.elimination_tol_mps, nullptr);
    row.elimination_runtime_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return row;
}

}  // namespace evade::threat
