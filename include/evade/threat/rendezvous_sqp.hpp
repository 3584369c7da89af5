// N-impulse (N = 2..4) minimum-total-Δv HCW rendezvous with fixed transfer time, solved by SQP.
//
// Paper 001 (Yu, Wang, Sun 2017, "Optimal evasive maneuver strategy with potential
// threatening area being considered"), sec. 2.1: the chaser's N-impulse optimal rendezvous
// (eq. 1: state after impulses through the C-W transition matrix; eq. 2: total Δv; eq. 3:
// min Σ|Δv_k| with fixed t0, tf and boundary states), solved by SQP. Notation (required
// change d, B(s), the primer λ): evade/threat/hcw_transfer.hpp.
//
// N impulses (SQP). Variables: the N−2 intermediate times τ_i ∈ [0, T] and impulses Δv_i;
// the first (τ = 0) and last (τ = T) impulses are the 2-impulse solution of the residual
// e = d − Σ B(T−τ_i)Δv_i. With J = φ(Δv1) + Σ φ(Δv_i) + φ(ΔvN), φ(v) = √(|v|²+ε²) − ε (a
// smoothing of |v| at 0; φ ≤ |v| ≤ φ + ε) and g_k = ∇φ(Δv_k):
//     ∂J/∂e = λ (same formula as the primer, with g in place of u),
//     ∂J/∂Δv_i = g_i − B(T−τ_i)ᵀ λ,   ∂J/∂τ_i = λᵀ B'(T−τ_i) Δv_i,
// B'(s) = [Φvv(s); Φvv'(s)]. NLopt LD_SLSQP minimizes J from several starts (the primer's
// maximum and uniform times); the reported cost is the exact Σ|Δv| of the best plan, so any
// result is a feasible plan (an upper bound of the true optimum); local optima are possible,
// which is why the starts are several and the tests compare against brute force.
#pragma once

#include <vector>

#include "evade/core/state.hpp"
#include "evade/threat/hcw_transfer.hpp"

namespace evade::threat {

/// Options of the N-impulse SQP.
struct SqpOptions {
  int impulses = 3;               ///< N, 2..4
  int starts = 4;                 ///< number of SLSQP starts (≥ 1)
  double smoothing_mps = 1e-4;    ///< ε of φ(v) = √(|v|²+ε²) − ε
  double xtol_rel = 1e-10;
  double ftol_abs = 1e-9;         ///< [m/s]
  int max_eval_per_start = 400;
  /// Decision mode: stop as soon as a plan with exact cost ≤ this is found; < 0 disables.
  double stop_at_cost_mps = -1.0;
  /// Decision mode only: after the first start (at the primer's maximum), run the other
  /// starts only if the best cost is within this of stop_at_cost_mps. Over 13 803 undecided
  /// sweep points of the seed1 scenario the first start was never worse than 16 starts by
  /// more than 0.023 m/s, so 1 m/s keeps every close call fully searched.
  double decision_margin_mps = 1.0;
};

/// Minimum-total-Δv N-impulse rendezvous with fixed transfer time: first impulse at 0, last at
/// T, intermediate times free. Throws std::invalid_argument for N outside 2..4 or a non-finite
/// d. The result is never worse than the 2-impulse plan.
RendezvousPlan optimize_rendezvous(const HcwTransfer& tr, const Vec6& d, const SqpOptions& opt);

/// Exact cost Σ|Δv| and the SLSQP objective for the given variables (exposed for tests of
/// the analytic gradient): vars = [τ_2..τ_{N−1}, Δv_2..Δv_{N−1}]; returns the smoothed J.
double sqp_objective(const HcwTransfer& tr, const Vec6& d, int impulses, double smoothing_mps,
                     const std::vector<double>& vars, std::vector<double>* grad);

}  // namespace evade::threat
