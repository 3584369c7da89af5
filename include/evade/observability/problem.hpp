// The observability-minimizing evasion problem of paper 004 (Yu, Wang, Zhou, "Anti-rendezvous
// evasive maneuver considering spatial geometry"): the geometry, the burn parametrization and
// the chaser's angles-only measurement (eq. 3).
//
// Frames.
//  * RSW (evade/dynamics/hcw.hpp): x radial outward, y along track, z orbit normal. All the
//    dynamics are computed in RSW with the foundation's HCW STM.
//  * Paper frame "P" (paper Fig. 1, our reading, see docs/REFERENCES.md, paper 004): x toward
//    the Earth's centre (-R), y opposite the velocity (-S), z = x × y = +W (orbit normal).
//    It is RSW rotated by π about the normal: v_P = C_P_RSW v_RSW with the constant
//    C_P_RSW = diag(-1, -1, +1) (a proper rotation, its own inverse). The HCW equations are
//    invariant under this rotation, so Φ is the same matrix in both frames.
//  Both frames are centred on the evader's nominal (no-burn) circular orbit; the chaser's
//  measurement frame is taken parallel to it (HCW approximation: the chaser's own orbital
//  frame is rotated by ≈ |along-track separation| / r ≈ 8 mrad, a constant offset that is
//  common to the burn and no-burn angles and so cancels in their difference to first order).
//
// State. X_P0 (paper §3) is the chaser's relative state w.r.t. the evader's nominal orbit at
// t0, in P: [x y z xdot ydot zdot] in m, m/s.
//
// Burn. One impulse of fixed magnitude |Δv| at t0, direction (ε, θ) in P (paper §2.1):
//     Δv_P = |Δv| [cos ε cos θ, cos ε sin θ, sin ε],
// θ the azimuth in the P x–y (orbit) plane from +x (toward the Earth), ε the elevation out of
// the orbit plane. Bounds (paper §2.1): −3π/2 ≤ θ ≤ −π/2, |ε| ≤ ξ = 0.05. So θ = −π is a
// purely radial-outward burn.
//
// Measurement (eq. 3). The chaser measures the LOS to the evader, r_PE = r_evader − r_chaser,
// in P: ε_m = arctan(z/x) (pitch), θ_m = arctan(y / sqrt(x² + z²)) (azimuth), principal
// values, exactly as printed. Differences of ε_m are reduced modulo π into (−π/2, π/2]
// (arctan(z/x) has period π in the LOS direction).
#pragma once

#include <utility>
#include <vector>

#include "evade/core/state.hpp"

namespace evade::observability {

/// Constant rotation RSW -> paper frame P: diag(-1, -1, +1). Also P -> RSW.
Mat3 rotation_rsw_to_paper();

/// How the k = 0 term of eq. 23 is handled. At t0 the burn has not displaced the evader yet
/// (OA'_0 = B_r(t0, t0) u_E = 0), so its unit vector is undefined.
enum class K0Term {
  kZero,   ///< unit(0) := 0: the term contributes 0 (our default; ideal f is then N, not N+1)
  kLimit,  ///< the t -> t0 limit of unit(OA'(t)) = unit(Δv): the term is unit(A_0O)·unit(Δv)
};

struct ObservabilityProblem {
  double n_radps = 0.0;            ///< evader's mean motion (circular nominal orbit) [rad/s]
  Vec6 x_chaser_p0 = Vec6::Zero(); ///< X_P0: chaser rel. evader nominal at t0, frame P [m, m/s]
  double dv_mps = 3.0;             ///< burn magnitude |Δv| [m/s], > 0
  double dt_obs_s = 10.0;          ///< measurement interval (0.1 Hz) [s]
  double t_obs_s = 1000.0;         ///< observation window after t0 [s]; samples t_k = k dt_obs_s
  K0Term k0 = K0Term::kZero;       ///< k = 0 term of eq. 23
  double theta_min_rad = -1.5 * 3.14159265358979323846;  ///< azimuth bounds (paper §2.1)
  double theta_max_rad = -0.5 * 3.14159265358979323846;
  double eps_max_rad = 0.05;       ///< |ε| <= eps_max_rad (paper §2.1, ξ = 0.05)
};

/// Throws std::invalid_argument naming the field, value and allowed range: n <= 0 or
/// non-finite, NaN/Inf state, zero chaser position, |Δv| <= 0 or non-finite, dt <= 0,
/// window < dt, more than 1e6 samples, inverted or non-finite bounds.
void validate(const ObservabilityProblem& p);

/// Sample times t_k = k dt, k = 0..N with N = floor(t_obs / dt + 1e-9).
std::vector<double> sample_times(const ObservabilityProblem& p);

/// Δv in P for direction (ε, θ) and magnitude dv_mps.
Vec3 dv_paper_from_angles(double eps_rad, double theta_rad, double dv_mps);
/// Δv in RSW (= LVLH as used by HCW) for direction (ε, θ).
Vec3 dv_rsw_from_angles(double eps_rad, double theta_rad, double dv_mps);

/// Eq. 3: (ε_m, θ_m) of the LOS r_pe_p (evader rel. chaser, frame P) [rad].
std::pair<double, double> los_angles(const Vec3& r_pe_p);
/// Difference of two pitch angles ε_m reduced modulo π into (−π/2, π/2] [rad].
double pitch_difference(double a_rad, double b_rad);

/// Chaser position rel. evader nominal at t, frame P (Φ_P X_P0) [m].
Vec3 chaser_position_p(const ObservabilityProblem& p, double t_s);
/// Evader displacement from its nominal orbit at t caused by the burn, frame P (B_r Δv) [m].
Vec3 burn_displacement_p(const ObservabilityProblem& p, double t_s, const Vec3& dv_p_mps);

/// The problem sampled once (validated): per sample t_k the chaser position Φ_P X_P0 and the
/// impulse-response block B_r(t_k, t0) = Φ_rv(t_k - t0), both in P. Objectives read only this.
struct SampledProblem {
  ObservabilityProblem problem;
  std::vector<double> t_s;        ///< t_k [s]
  std::vector<Vec3> r_chaser_p;   ///< chaser rel. evader nominal at t_k, P [m]
  std::vector<Mat3> b_r_p;        ///< Φ_rv(t_k) in P [s]
};

/// Validates p and samples it.
SampledProblem sample(const ObservabilityProblem& p);

}  // namespace evade::observability
