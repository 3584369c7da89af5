// The threat-area study of one scenario: everything `evade plan threat-area` reports.
//
// Paper 001 (Yu, Wang, Sun 2017): the chaser's minimum cost at t0 without evasion (sec. 2.1,
// eq. 3), the target's optimal burn direction at fixed V_E minimizing the potential threat
// arc (sec. 3.1 eq. 4–7, sec. 3.2; the paper's timing case V_E = 20 m/s), the smallest
// eliminating V_E (sec. 4.2, Table 3), the arc against V_E (Fig. 8) and the transfer-time
// study (Fig. 4, transfer_study.hpp). Wall times are measured here; nothing is printed:
// the optional progress hooks let a caller report each step as it finishes.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "evade/core/constants.hpp"
#include "evade/threat/evasion.hpp"
#include "evade/threat/threat_area.hpp"
#include "evade/threat/transfer_study.hpp"

namespace evade::threat {

/// The threat-area solvers' inputs, as a threat-area scenario gives them
/// (commands::read_threat_scenario).
struct ThreatScenario {
  EarthModel earth;                     ///< earth.* (only μ and Re enter HCW's n)
  ThreatGeometry geometry;              ///< n from the target's circular orbit; chaser at t0
  ThreatOptions threat;                 ///< chaser., transfer., sweep.
  EvasionOptions evasion;               ///< evasion.* (angles in radians)
  double evasion_dv_mps = 20.0;         ///< evasion.dv_mps: V_E of the single optimization
  double elimination_tol_mps = 0.05;    ///< elimination.tol_mps
  double target_inclination_deg = 0.0;  ///< target.inclination_deg (for the record)
};

struct ThreatStudyRequest {
  bool eliminate = false;                ///< search the eliminating V_E (also per transfer time)
  std::vector<double> sweep_dv_mps;      ///< V_E values of the arc sweep (Fig. 8)
  std::vector<double> sweep_transfer_s;  ///< transfer times of the study (Fig. 4)
};

/// One V_E of the arc sweep.
struct BurnSweepRow {
  EvasionResult evasion;
  double runtime_s = 0.0;
};

/// Optional hooks, each called as its step starts or ends.
struct ThreatStudyProgress {
  std::function<void(double dv_mps, int max_evaluations)> optimizing;  ///< before the main search
  std::function<void(double tol_mps)> eliminating;  ///< before the main elimination
  void (*bisection)(double lo_mps, double hi_mps) = nullptr;  ///< each step of it
  std::function<void(const BurnSweepRow&)> burn_row;
  std::function<void(const TransferStudyRow&)> transfer_row;
};

struct ThreatStudy {
  double period_s = 0.0;                 ///< chaser's (= reference) orbital period
  double chaser_cost_t0_mps = 0.0;       ///< J(t0): full-effort N-impulse cost, no evasion
  double two_impulse_cost_t0_mps = 0.0;  ///< the 2-impulse cost at t0
  double t0_bound_mps = 0.0;             ///< ΔV_max − J(t0)
  EvasionResult evasion;                 ///< optimal direction at V_E = evasion_dv_mps
  double runtime_s = 0.0;                ///< wall time of that search
  std::optional<EliminationResult> elimination;  ///< with ThreatStudyRequest::eliminate
  double elimination_runtime_s = 0.0;
  double eliminating_to_dv_max_ratio = 0.0;  ///< eliminating V_E / ΔV_max
  double eliminating_over_t0_bound = 0.0;    ///< eliminating V_E / (ΔV_max − J(t0))
  std::vector<BurnSweepRow> sweep_dv;
  std::vector<TransferStudyRow> sweep_transfer;
  double total_runtime_s = 0.0;
};

/// Runs the study. Throws std::invalid_argument for bad inputs (naming the field) and
/// std::runtime_error if an elimination search finds no eliminating V_E.
ThreatStudy run_threat_study(const ThreatScenario& in, const ThreatStudyRequest& request,
                             const ThreatStudyProgress& progress = {});

}  // namespace evade::threat
