// Objectives of the observability-minimizing burn (paper 004), on HCW relative motion in the
// paper frame P (x to the Earth's centre, y = −along-track, z = orbit normal; problem.hpp).
//
//  * paper_objective: eq. 23 literally, f(u_E) = Σ_{k=0..N} unit(A_kO) · unit(OA'_k), with
//    A_kO = −Φ_P(t_k) X_P0 the vector from the chaser A_k to the nominal evader O (our reading:
//    chaser→evader; the opposite sign makes f odd in u_E and moves the optimum to the bound),
//    OA'_k = B_r(t_k, t0) u_E the maneuvered evader's displacement from O. The k = 0 term has
//    OA'_0 = 0; ObservabilityProblem::k0 says how it is handled (default: contributes 0, so
//    the ideal f is N = 100 for the paper's 101 samples). Maximized.
//  * los_change: the change of the chaser's measured angles (eq. 3) caused by the burn,
//    Δε_k = ε_m(burn) − ε_m(no burn), Δθ_k likewise, for k = 0..N. The objective is
//    Σ_k sqrt(Δε_k² + Δθ_k²) [rad] (the summed angular change), minimized; the maxima of
//    |Δε_k| and |Δθ_k| are reported beside it.
#pragma once

#include "evade/observability/problem.hpp"

namespace evade::observability {

/// Eq. 23 for direction (ε, θ) [-]; in [−(N+1), N+1].
double paper_objective(const SampledProblem& s, double eps_rad, double theta_rad);

struct LosChange {
  double sum_rad = 0.0;                  ///< Σ_k sqrt(Δε_k² + Δθ_k²) [rad] (the objective)
  double sum_abs_azimuth_rad = 0.0;      ///< Σ_k |Δθ_k| [rad]
  double sum_abs_elevation_rad = 0.0;    ///< Σ_k |Δε_k| [rad]
  double max_azimuth_change_rad = 0.0;   ///< max_k |Δθ_k| [rad]
  double max_elevation_change_rad = 0.0; ///< max_k |Δε_k| [rad]
};

/// Change of the measured LOS angles over the window for direction (ε, θ). A zero burn
/// (dv = 0 passed through dv_p_mps) gives all zeros.
LosChange los_change(const SampledProblem& s, double eps_rad, double theta_rad);
/// Same for an explicit Δv in P (any magnitude, including 0 for the no-burn case).
LosChange los_change_dv(const SampledProblem& s, const Vec3& dv_p_mps);

}  // namespace evade::observability
