// The transfer-time study: how the chaser's cost at t0 and the eliminating burn depend on the
// transfer time ΔT.
//
// Paper 001 (Yu, Wang, Sun 2017) sec. 2.1 and Fig. 4: the chaser's minimum N-impulse cost
// (eq. 3, N = 2, 3, 4, SQP) at departure t0 without evasion, against ΔT; the paper chooses
// ΔT = 2200 s as its worst case and 3 impulses. Beside the costs: the primer-vector lower
// bound of any impulsive plan (hcw_transfer.hpp), the necessary condition for elimination
// V_E > ΔV_max − J(t0) (evasion.hpp), and optionally the eliminating V_E itself (sec. 4.2).
#pragma once

#include <array>
#include <optional>

#include "evade/threat/evasion.hpp"
#include "evade/threat/threat_area.hpp"

namespace evade::threat {

struct TransferStudyOptions {
  int sqp_starts = 8;                 ///< SLSQP starts of each 2/3/4-impulse solve
  bool eliminate = false;             ///< also search the eliminating V_E (costly)
  EvasionOptions evasion{};           ///< the elimination's optimizer
  double elimination_tol_mps = 0.05;  ///< the elimination's bisection tolerance
};

/// One transfer time.
struct TransferStudyRow {
  double dt_transfer_s = 0.0;
  std::array<double, 3> cost_t0_mps{};  ///< minimum cost at t0 with 2, 3 and 4 impulses
  double primer_max_t0 = 1.0;           ///< certified max |p| of the 2-impulse primer at t0
  double primer_lower_bound_t0_mps = 0.0;  ///< J2 / primer_max: no impulsive plan costs less
  double j_t0_mps = 0.0;                ///< J(t0): full-effort cost with the options' N
  double t0_bound_mps = 0.0;            ///< ΔV_max − J(t0): every eliminating V_E exceeds it
  std::optional<EliminationResult> elimination;  ///< with TransferStudyOptions::eliminate
  double elimination_runtime_s = 0.0;   ///< wall time of the elimination search
};

/// The row for transfer time transfer_s, all else as in `options`. Throws
/// std::invalid_argument for a bad geometry, options or transfer time (as ThreatAreaSolver).
TransferStudyRow study_transfer_time(const ThreatGeometry& geometry, const ThreatOptions& options,
                                     double transfer_s, const TransferStudyOptions& study = {});

}  // namespace evade::threat
