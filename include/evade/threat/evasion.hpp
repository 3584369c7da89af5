// The target's optimal evasive burn against the potential threat area, and the smallest burn
// that eliminates it.
//
// Paper 001 (Yu, Wang, Sun 2017) sec. 3.1: one impulse of fixed magnitude V_E at t0 (eq. 4:
// ΔV_opt = V_E [direction from pitch α and yaw θ in VVLH]), chosen to minimize the threat arc
// (eq. 7); sec. 3.2: a GA (population 60, 20 generations). We use NLopt GN_ISRES (a seeded
// evolutionary strategy; population 60, ≈ 1 200 evaluations by default, like 60 × 20).
//
// Direction (the paper's Fig. 3 was lost in extraction; our definition). VVLH axes
// (evade/core/frames.hpp): x along track, y = −orbit normal, z toward the Earth's centre.
//     Δv_vvlh = V_E [cos α cos θ,  cos α sin θ,  −sin α]
// pitch α ∈ [−π/2, π/2]: elevation above the local horizontal, positive toward the zenith
// (−z); yaw θ ∈ [−π, π]: azimuth in the horizontal plane from the velocity direction (+x)
// toward +y. α = θ = 0 is a prograde burn.
//
// Elimination: bisection on V_E. At each V_E the optimizer runs (stopping as soon as a
// direction with zero arc is found); V_E is "eliminating" when a direction with zero arc was
// found (certified on the sweep grid and its edges), "not eliminating" when the optimizer
// found none (not a proof). Bisection assumes the arc decreases with V_E (the paper's
// finding, checked by our tests). A proven necessary condition: since the sweep includes
// t0, the chaser can add the target's Δv_E to its own
// first impulse at t0 and follow its unperturbed plan, so t0 threatens while
// V_E + J(t0) ≤ ΔV_max, i.e. any eliminating V_E exceeds ΔV_max − J(t0) where J(t0) is the
// chaser's minimum cost at t0 without evasion.
#pragma once

#include <cstdint>

#include "evade/threat/threat_area.hpp"

namespace evade::threat {

/// Δv in VVLH for magnitude V_E, pitch α, yaw θ (definition above).
Vec3 evasion_dv_vvlh(double dv_mps, double alpha_rad, double theta_rad);
/// The same Δv in RSW (the HCW frame).
Vec3 evasion_dv_rsw(double dv_mps, double alpha_rad, double theta_rad);

struct EvasionOptions {
  bool use_isres = false;         ///< NLopt GN_ISRES instead of the sweep search
  int population = 60;            ///< ISRES population (paper's GA: 60)
  int max_evaluations = 1200;     ///< cap of exact arc evaluations (ISRES: ≈ 60 × 20)
  std::uint64_t seed = 1;         ///< ISRES RNG seed / the sweep's sample position in a cell
  int sweep_alpha_cells = 8;      ///< sweep cells in sin α
  int sweep_theta_cells = 16;     ///< sweep cells in θ (≥ 4: cells narrower than 90°)
  double sweep_edge_tol_s = 2.0;  ///< edge tolerance of the sweep's evaluations (ranking only)
  int local_starts = 3;           ///< BOBYQA refinements from the best separated cells
  double local_xtol_rad = 1e-4;   ///< BOBYQA stop: step in sin α and θ [rad]
  int certify_max_cells = 3000;   ///< lower-bound computations of the certificate; 0: none
  double certify_rel_tol = 1e-3;  ///< a cell is closed when its bound ≥ (1 − tol) × best
  double alpha_min_rad = -1.5707963267948966;
  double alpha_max_rad = 1.5707963267948966;
  double theta_min_rad = -3.141592653589793;
  double theta_max_rad = 3.141592653589793;
  /// Stop as soon as the arc is ≤ this [s] (elimination search uses 0); < 0 disables.
  double stop_arc_s = -1.0;
};

/// How the sweep search's result was certified (zeros for ISRES and for V_E = 0).
struct SearchCertificate {
  long grid_evaluations = 0;   ///< exact evaluations of the sweep
  long local_evaluations = 0;  ///< exact evaluations of the BOBYQA refinements
  int local_starts = 0;
  double local_spread_s = 0.0;     ///< largest − smallest arc of the refinements
  double lower_bound_arc_s = 0.0;  ///< no direction of the box has an arc below this
  long bound_cells = 0;            ///< lower bounds computed (sweep cells and their splits)
  long open_cells = 0;             ///< cells still below (1 − tol) × best at the end
  bool certified = false;          ///< lower_bound ≥ (1 − certify_rel_tol) × best arc
  double certify_runtime_s = 0.0;  ///< wall time of the certificate (part of runtime_s)
};

struct EvasionResult {
  double dv_mps = 0.0;
  double alpha_rad = 0.0;
  double theta_rad = 0.0;
  Vec3 dv_vvlh_mps = Vec3::Zero();
  Vec3 dv_rsw_mps = Vec3::Zero();
  ThreatArea area;                ///< threat area for the best direction
  long evaluations = 0;           ///< threat-area evaluations spent
  DecisionCounts counts;          ///< decisions over all evaluations
  SearchCertificate certificate;  ///< sweep search only
  double runtime_s = 0.0;         ///< wall time of the search
};

/// Minimizes the threat arc over the burn direction at fixed V_E. V_E = 0 needs no search
/// (one evaluation). Throws std::invalid_argument on V_E < 0 / NaN or bad options.
EvasionResult optimize_evasion(const ThreatAreaSolver& solver, double dv_mps,
                               const EvasionOptions& opt);

struct EliminationResult {
  double eliminating_dv_mps = 0.0;  ///< smallest V_E found with zero arc (upper bracket)
  double threatened_dv_mps = 0.0;   ///< largest V_E tried that kept an arc (lower bracket)
  EvasionResult best;               ///< the eliminating direction
  double j_t0_mps = 0.0;            ///< chaser's minimum cost at t0 without evasion
  double bound_mps = 0.0;           ///< ΔV_max − J(t0): necessary for elimination
  int bisection_steps = 0;
  long evaluations = 0;
};

/// Bisection on V_E (to tol_mps) with the optimizer as the oracle. `progress` (optional) is
/// called after each step with (lo, hi). Throws std::runtime_error if no V_E up to
/// 10 ΔV_max eliminates the threat.
EliminationResult find_eliminating_dv(const ThreatAreaSolver& solver, const EvasionOptions& opt,
                                       double tol_mps,
                                       void (*progress)(double lo, double hi) = nullptr);

}  // namespace evade::threat
