// Chaser rendezvous in HCW relative motion with fixed transfer time: the 2-impulse closed
// form and lower bounds (primer vector, dual) on the cost of ANY impulsive rendezvous. The
// N-impulse SQP built on these quantities is in evade/threat/rendezvous_sqp.hpp.
//
// Paper 001 (Yu, Wang, Sun 2017, "Optimal evasive maneuver strategy with potential
// threatening area being considered"), sec. 2.1: the chaser's rendezvous through impulses
// (eq. 1: state after impulses through the C-W transition matrix; eq. 2: total Δv). The
// lower bounds below are ours (weak duality, Neustadt 1964), used to decide threat points.
//
// Notation (RSW frame of the reference orbit, see evade/dynamics/hcw.hpp). Transfer time T,
// chaser state x0 at the transfer start, required final state xf. The REQUIRED CHANGE is
//     d = xf − Φ(T) x0  (6-vector).
// An impulse Δv at time τ ∈ [0, T] contributes B(T − τ) Δv with B(s) = [Φrv(s); Φvv(s)], so a
// plan {(τ_i, Δv_i)} rendezvouses iff Σ_i B(T − τ_i) Δv_i = d; its cost is Σ_i |Δv_i|.
//
// 2 impulses (τ = 0 and T): Δv1 = Φrv(T)⁻¹ d_r, Δv2 = d_v − Φvv(T) Δv1 — the same as
// Δv1 = Φrv⁻¹(r_f − Φrr r0) − v0, Δv2 = v_f − (Φvr r0 + Φvv (v0 + Δv1)).
//
// Lower bound (weak duality). For any λ ∈ R⁶ with |B(s)ᵀ λ| ≤ 1 for all s ∈ [0, T]:
//     λᵀ d = Σ_i λᵀ B(T−τ_i) Δv_i ≤ Σ_i |B(T−τ_i)ᵀ λ| |Δv_i| ≤ Σ_i |Δv_i|,
// so λᵀd bounds the cost of every impulsive plan, whatever the impulse count. The primer of
// the 2-impulse solution, p(τ) = B(T−τ)ᵀ λ with λ_v = u2 and λ_r = Φrv(T)⁻ᵀ(u1 − Φvv(T)ᵀ u2)
// (u_k = Δv_k/|Δv_k|, 0 for a zero impulse), satisfies p(0) = u1, p(T) = u2 and λᵀd = J2 (the
// 2-impulse cost). Scaling λ by 1/max_τ|p(τ)| makes it feasible, hence
//     J_any ≥ J2 / max_τ |p(τ)|.
// If max|p| = 1 the 2-impulse solution is optimal (Lawden's conditions) and the bound is J2.
// max|p| is taken over M+1 samples plus a certified margin: for s between samples h apart,
// |p(s)| ≤ max(|p_j|, |p_j+1|) + h²/8 · max|p''|, and from the closed-form Φvv (hcw.hpp)
// |p''(s)| = |Φvv'(s)ᵀ λ_r + Φvv''(s)ᵀ λ_v| ≤ n√26 |λ_r| + n²√26 |λ_v| (Frobenius bounds of
// the entrywise derivatives of Φvv: (c, 2s, −2s, 4c−3, c)' = n(−s, 2c, −2c, −4s, −s)). The
// bound is therefore a rigorous upper bound of max|p| and J2/that a rigorous lower bound.
//
// Tighter dual bound (Neustadt 1964; the LP/SOCP duality behind Lawden's primer). The best λ
// maximizes λᵀd / max_s|B(s)ᵀλ| and at the optimum equals the cost of the optimal impulsive
// plan. dual_bound() improves λ by iteratively reweighted least squares (IRLS) on the
// restricted primal "min Σ_k |v_k| s.t. Σ_k B_k v_k = d" over a few candidate impulse times
// (τ = 0, T, and the primer samples around the largest |p|): with weights w_k > 0,
//     μ = (Σ_k w_k B_k B_kᵀ)⁻¹ d,  v_k = w_k B_kᵀ μ (feasible: Σ B_k v_k = d),  w_k ← |v_k|,
// a majorize-minimize iteration whose μ converges to the restricted problem's dual (|B_kᵀμ|
// = 1 on the support). Every iterate μ is scored as a certificate μᵀd / max|p|, max|p| with
// the same certified sampling margin as above, so the result is a rigorous lower bound
// whatever the iteration does (it is only more or less tight); the best score is kept and
// is never below the 2-impulse primer bound.
#pragma once

#include <array>
#include <vector>

#include "evade/core/state.hpp"

namespace evade::threat {

/// One impulse of a plan: time from the transfer start [s] and Δv in RSW [m/s].
struct Impulse {
  double t_s = 0.0;
  Vec3 dv_rsw_mps = Vec3::Zero();
};

struct RendezvousPlan {
  std::vector<Impulse> impulses;
  double cost_mps = 0.0;  ///< Σ |Δv| of the impulses (exact, not smoothed)
};

/// Bound from the 2-impulse primer.
struct PrimerBound {
  double two_impulse_cost_mps = 0.0;  ///< J2
  double primer_max = 1.0;            ///< certified upper bound of max_τ |p(τ)| (≥ 1)
  double lower_bound_mps = 0.0;       ///< J2 / primer_max ≤ cost of any impulsive plan
  double primer_argmax_s = 0.0;       ///< sample time of the largest |p| (from transfer start)
};

/// Precomputed HCW quantities for one mean motion n and transfer time T; cheap per-query
/// functions. Throws std::invalid_argument for n ≤ 0, T ≤ 0, non-finite inputs, or a T at
/// which Φrv(T) is singular (n T a multiple of π makes the out-of-plane 2-impulse problem
/// singular; a multiple of 2π also the in-plane one).
class HcwTransfer {
 public:
  static constexpr int kPrimerSamples = 64;

  HcwTransfer(double n_radps, double transfer_s);

  double n_radps() const { return n_; }
  double transfer_s() const { return T_; }

  /// d = xf − Φ(T) x0.
  Vec6 required_change(const Vec6& x0_rsw, const Vec6& xf_rsw) const;
  /// The 2-impulse plan for a required change d (impulses at 0 and T).
  RendezvousPlan two_impulse(const Vec6& d) const;
  /// Cost of the 2-impulse plan only (no allocation).
  double two_impulse_cost(const Vec6& d) const;
  /// Primer-vector lower bound for the cost of any impulsive plan achieving d.
  PrimerBound primer_bound(const Vec6& d) const;
  /// Dual lower bound: max(primer_bound, best IRLS certificate after ≤ max_iterations).
  /// Stops early once the bound exceeds stop_above_mps, or once the IRLS primal (a feasible
  /// plan) costs ≤ stop_above_mps (then no bound can exceed it).
  PrimerBound dual_bound(const Vec6& d, double stop_above_mps = -1.0,
                         int max_iterations = 40) const;
  /// Same, starting from primer_bound(d) already computed by the caller. If three_impulse is
  /// given, it receives a feasible 3-impulse plan (exact end impulses, exact cost) built from
  /// the last IRLS plan, or an empty plan if there is none.
  PrimerBound dual_bound(const Vec6& d, const PrimerBound& primer, double stop_above_mps,
                         int max_iterations = 40,
                         RendezvousPlan* three_impulse = nullptr) const;
  /// Certified upper bound of max_τ |B(T−τ)ᵀλ| (samples + margin); argmax sample index.
  double certified_primer_max(const Vec6& lambda, int* argmax_j = nullptr) const;
  /// True if max_τ |B(T−τ)ᵀλ| < cap is certified: the samples, and within any interval whose
  /// sampled bound reaches cap, 8 sub-samples (closed-form STM) with a 64× smaller margin.
  bool certify_primer_below(const Vec6& lambda, double cap) const;
  /// Primer p(τ) = B(T−τ)ᵀ λ for a given λ (exposed for tests).
  Vec3 primer(const Vec6& lambda, double tau_s) const;
  /// λ of the 2-impulse solution of d (with unit vectors u1, u2; zero impulses give 0).
  Vec6 primer_lambda(const Vec6& d) const;

  /// Residual of a plan: Σ B(T−τ_i)Δv_i − d (zero for a valid rendezvous).
  Vec6 plan_residual(const RendezvousPlan& plan, const Vec6& d) const;

  // Internals shared with the SQP (rendezvous_sqp.hpp).
  const Mat3& phi_vv_T() const { return vv_T_; }
  const Mat3& phi_rv_T_inv() const { return rv_T_inv_; }

 private:
  double n_;
  double T_;
  Mat3 rr_T_, rv_T_, vr_T_, vv_T_, rv_T_inv_;
  std::array<Mat3, kPrimerSamples + 1> rv_s_;  // Φrv(s_j), s_j = T − τ_j, τ_j = j T / M
  std::array<Mat3, kPrimerSamples + 1> vv_s_;
};

}  // namespace evade::threat
