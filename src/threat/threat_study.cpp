// The threat-area study of one scenario (include/evade/threat/threat_study.hpp). Paper 001
// (Yu, Wang, Sun 2017): sec. 2.1 eq. 3 (J(t0)), sec. 3.1–3.2 eq. 4–7 (optimal direction at
// fixed V_E), sec. 4.2 and Table 3 (eliminating V_E), Fig. 8 (arc against V_E) and Fig. 4
// (transfer-time study).
#include "evade/threat/threat_study.hpp"

#include <chrono>

namespace evade::threat {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// J(t0), the 2-impulse cost at t0 and the elimination bound, without evasion.
void t0_summary(const ThreatAreaSolver& solver, ThreatStudy& out) {
  out.period_s = solver.period_s();
  const RendezvousPlan plan0 = solver.min_cost_plan(0.0, Vec3::Zero());
  out.chaser_cost_t0_mps = plan0.cost_mps;
  out.two_impulse_cost_t0_mps =
      solver.transfer().two_impulse_cost(solver.required_change(0.0, Vec3::Zero()));
  out.t0_bound_mps = solver.options().dv_max_mps - plan0.cost_mps;
}

void eliminate(const ThreatAreaSolver& solver, const ThreatScenario& in,
               const ThreatStudyProgress& progress, ThreatStudy& out) {
  if (progress.eliminating) progress.eliminating(in.elimination_tol_mps);
  const auto t0 = std::chrono::steady_clock::now();
  const EliminationResult e =
      find_eliminating_dv(solver, in.evasion, in.elimination_tol_mps, progress.bisection);
  out.elimination_runtime_s = seconds_since(t0);
  out.eliminating_to_dv_max_ratio = e.eliminating_dv_mps / in.threat.dv_max_mps;
  out.eliminating_over_t0_bound = e.eliminating_dv_mps / e.bound_mps;
  out.elimination = e;
}

void sweep_burns(const ThreatAreaSolver& solver, const ThreatScenario& in,
                 const std::vector<double>& dv_mps, const ThreatStudyProgress& progress,
                 ThreatStudy& out) {
  for (double v : dv_mps) {
    const auto t0 = std::chrono::steady_clock::now();
    BurnSweepRow row;
    row.evasion = optimize_evasion(solver, v, in.evasion);
    row.runtime_s = seconds_since(t0);
    if (progress.burn_row) progress.burn_row(row);
    out.sweep_dv.push_back(row);
  }
}

void sweep_transfers(const ThreatScenario& in, const ThreatStudyRequest& request,
                     const ThreatStudyProgress& progress, ThreatStudy& out) {
  TransferStudyOptions study;
  study.eliminate = request.eliminate;
  study.evasion = in.evasion;
  study.elimination_tol_mps = in.elimination_tol_mps;
  for (double t : request.sweep_transfer_s) {
    out.sweep_transfer.push_back(study_transfer_time(in.geometry, in.threat, t, study));
    if (progress.transfer_row) progress.transfer_row(out.sweep_transfer.back());
  }
}

}  // namespace

ThreatStudy run_threat_study(const ThreatScenario& in, const ThreatStudyRequest& request,
                             const ThreatStudyProgress& progress) {
  const auto t_all = std::chrono::steady_clock::now();
  const ThreatAreaSolver solver(in.geometry, in.threat);
  ThreatStudy out;
  t0_summary(solver, out);
  if (progress.optimizing) progress.optimizing(in.evasion_dv_mps, in.evasion.max_evaluations);
  const auto t_opt = std::chrono::steady_clock::now();
  out.evasion = optimize_evasion(solver, in.evasion_dv_mps, in.evasion);
  out.runtime_s = seconds_since(t_opt);
  if (request.eliminate) eliminate(solver, in, progress, out);
  sweep_burns(solver, in, request.sweep_dv_mps, progress, out);
  sweep_transfers(in, request, progress, out);
  out.total_runtime_s = seconds_since(t_all);
  return out;
}

}  // namespace evade::threat
