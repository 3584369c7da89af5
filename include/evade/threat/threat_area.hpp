// Potential threat area: the part of the chaser's orbit from which it can still rendezvous
// with the target within ΔT using at most ΔV_max.
//
// Paper 001 (Yu, Wang, Sun 2017) sec. 2.2 (definition, direct search with a fixed step over
// one chaser period, Fig. 2) and sec. 3.1 (new relative states after the target's evasion,
// eq. 4–5; arc length from the number of threatening points N_T and the step, eq. 6–7).
//
// Model (our reading, docs/VALIDATION.md): HCW (RSW) about the target's ORIGINAL
// circular orbit, mean motion n. At t0 = 0 the target is at x_T0 (normally the origin) and
// applies Δv_E; from then on x_T(t) = Φ(t)(x_T0 + [0; Δv_E]) — the evaded target is modelled
// by linear relative motion about the unchanged reference, valid while its displacement stays
// small against the orbit radius (an assumption: at Δv_E ≈ 240 m/s the target drifts hundreds
// of km per orbit and HCW is only indicative). The chaser coasts from x_C0: x_C(t) = Φ(t) x_C0.
// Sweep point t (t ∈ [0, span), span = one chaser period 2π/n by default, step configurable,
// t = 0 INCLUDED): the chaser starts its transfer at t and must reach x_T(t + ΔT), so
//     d(t) = x_T(t + ΔT) − Φ(ΔT) x_C(t) = Φ(t+ΔT)(x_T0 − x_C0) + B(t+ΔT) Δv_E.
// t threatens iff the minimum N-impulse cost of d(t) ≤ ΔV_max. Each point is decided by the
// cheapest sufficient test: 2-impulse cost ≤ ΔV_max ⇒ threatening (a feasible plan); primer
// lower bound > ΔV_max ⇒ safe (certified); the tighter dual lower bound > ΔV_max ⇒ safe
// (certified); the 3-impulse plan of the same IRLS iteration (N ≥ 3) within ΔV_max ⇒
// threatening (a feasible plan); otherwise the N-impulse SQP (threatening iff it
// finds a plan within ΔV_max — the only non-certified "safe" verdict, counted separately).
// Interval edges are refined by bisection between a safe and a threatening sweep point.
#pragma once

#include <cstddef>
#include <vector>

#include "evade/core/state.hpp"
#include "evade/threat/hcw_transfer.hpp"
#include "evade/threat/rendezvous_sqp.hpp"

namespace evade::threat {

struct ThreatGeometry {
  double n_radps = 0.0;                ///< mean motion of the reference (target) orbit
  Vec6 chaser0_rsw = Vec6::Zero();     ///< chaser relative state at t0 [m, m/s]
  Vec6 target0_rsw = Vec6::Zero();     ///< target relative state at t0, before its burn
};

struct ThreatOptions {
  double dv_max_mps = 324.0;     ///< chaser's Δv capacity ΔV_max
  double transfer_s = 2200.0;    ///< fixed transfer time ΔT
  int impulses = 3;              ///< N, 2..4
  double step_s = 5.0;           ///< sweep step
  double span_s = 0.0;           ///< swept window [0, span); 0 ⇒ one chaser period 2π/n
  double edge_tol_s = 0.05;      ///< bisection tolerance of interval edges; 0 ⇒ grid only
  int threads = 2;               ///< sweep threads (1 or 2 sensible on the target machine)
  SqpOptions sqp{};              ///< SQP settings (impulses is overwritten by `impulses`)
};

struct ThreatInterval {
  double start_s = 0.0;  ///< from t0
  double end_s = 0.0;
};

/// How many decisions each test made (grid points and bisection probes).
struct DecisionCounts {
  long two_impulse_accept = 0;  ///< 2-impulse cost ≤ ΔV_max ⇒ threatening
  long bound_reject = 0;        ///< primer lower bound > ΔV_max ⇒ safe
  long sqp_threat = 0;          ///< SQP found a plan within ΔV_max
  long sqp_safe = 0;            ///< SQP did not (not certified)
  long plan_accept = 0;         ///< 3-impulse plan of the dual iteration within ΔV_max ⇒ threat
  long total() const {
    return two_impulse_accept + bound_reject + sqp_threat + sqp_safe + plan_accept;
  }
  DecisionCounts& operator+=(const DecisionCounts& o);
};

struct ThreatArea {
  double arc_s = 0.0;            ///< total length of the threatening intervals [s]
  double arc_deg = 0.0;          ///< same as an arc of the chaser's orbit, 360°·arc/period
  double grid_arc_s = 0.0;       ///< paper eq. 6: N_T × step
  long points = 0;               ///< sweep points
  long threatening_points = 0;   ///< N_T
  std::vector<ThreatInterval> intervals;
  DecisionCounts counts;
};

/// Sweeps and decides threat points for one geometry; thread-safe const queries.
class ThreatAreaSolver {
 public:
  /// Validates (throws std::invalid_argument naming the field, value and allowed range).
  ThreatAreaSolver(const ThreatGeometry& geom, const ThreatOptions& opt);

  const ThreatOptions& options() const { return opt_; }
  const ThreatGeometry& geometry() const { return geom_; }
  const HcwTransfer& transfer() const { return tr_; }
  double period_s() const;

  /// Threat area after the target's burn Δv_E (RSW) at t0.
  ThreatArea evaluate(const Vec3& evasion_dv_rsw_mps) const;
  /// Required change d(t) for a chaser departing at t after the target's burn.
  Vec6 required_change(double t_s, const Vec3& evasion_dv_rsw_mps) const;
  /// Full-effort minimum cost (all SQP starts, no early stop) at departure time t.
  RendezvousPlan min_cost_plan(double t_s, const Vec3& evasion_dv_rsw_mps) const;
  /// Decides one required change; updates `counts`.
  bool threatening(const Vec6& d, DecisionCounts& counts) const;

 private:
  /// An interval edge to bisect between a safe and a threatening departure time.
  struct Edge {
    double safe_t, threat_t;
    std::size_t interval;  ///< index in ThreatArea::intervals
    bool is_start;
  };
  /// Verdict of every grid point (counts.size() threads, one DecisionCounts each).
  std::vector<char> sweep_grid(const Vec3& dv_e, std::vector<DecisionCounts>& counts) const;
  /// Runs of threatening points → intervals; the edges left to bisect (none if edge_tol_s = 0).
  std::vector<Edge> grid_intervals(const std::vector<char>& threat, const Vec3& dv_e,
                                   DecisionCounts& counts,
                                   std::vector<ThreatInterval>& intervals) const;
  /// The edge's time to within edge_tol_s.
  double bisect_edge(const Edge& edge, const Vec3& dv_e, DecisionCounts& counts) const;
  /// Bisects every edge (split over at most counts.size() threads) into `intervals`.
  void refine_edges(const std::vector<Edge>& edges, const Vec3& dv_e,
                    std::vector<DecisionCounts>& counts,
                    std::vector<ThreatInterval>& intervals) const;

  ThreatGeometry geom_;
  ThreatOptions opt_;
  HcwTransfer tr_;
  std::vector<double> t_grid_;
  std::vector<Vec6> w_grid_;                        // Φ(t+ΔT)(x_T0 − x_C0)
  std::vector<Eigen::Matrix<double, 6, 3>> b_grid_;  // B(t+ΔT)
};

}  // namespace evade::threat
