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
  int population = 60;            ///< ISRES population (paper's GA: 60)
  int max_evaluations = 1200;     ///< ≈ 60 × 20 generations
  std::uint64_t seed = 1;         ///< NLopt RNG seed (reproducible runs; up to 2^53)
  double alpha_min_rad = -1.5707963267948966;
  double alpha_max_rad = 1.5707963267948966;
  double theta_min_rad = -3.141592653589793;
  double theta_max_rad = 3.141592653589793;
  /// Stop as soon as the arc is ≤ this [s] (elimination search uses 0); < 0 disables.
  double stop_arc_s = -1.0;
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
