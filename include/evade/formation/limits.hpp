// Largest raise / lower of the semi-major axis of one satellite that keeps every formation
// constraint for T days: paper 003 sec. 2, Table 1 (eqs. 3, 5, the out-of-plane inequality
// Δa·K_Ω·T·(a+Δa)·sin i ≤ Δh, and the in-plane bound Δa·K_am·T ≤ ΔS).
//
// Model: a change Δa of the threatened satellite X, held for T days, moves its RAAN by
// K_Ω Δa T and its argument of latitude by K_φ Δa T (drift_coefficients.hpp). Each
// constraint deviation q then changes by
//   inter-group RAAN   ±K_Ω Δa T                          (+ if X is the group chief)
//   inter-group phase  ±K_φ Δa T
//   out-of-plane       ∓sgn(δΩ) K_Ω Δa T (a_X + Δa) sin i_X   (paper's inequality, exact in Δa)
//   in-plane           ∓sgn(s)  K_am Δa T                       (paper: K_am = a K_φ)
// (the sign is that of ∂q/∂Ω_X resp. ∂q/∂u_X; δΩ, s of the deputy relative to its chief).
// For a direction d = ±1 the limit is the largest x = |Δa| keeping lower ≤ q ≤ upper: the
// edge met is the one q moves toward, ΔΩ, Δφ, Δh, ΔS of the paper = that edge minus the
// current deviation. Raise and lower limits differ because the current deviation sits
// asymmetrically in the band (and the box itself is asymmetric: −Δ…+4Δ, −6Δ…+3Δ). A
// constraint that X does not enter has no limit (+inf). A constraint already violated gives
// limit 0 and is flagged. The overall limits are the minima over the rows.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "evade/formation/drift_coefficients.hpp"
#include "evade/formation/formation_model.hpp"

namespace evade::formation {

inline constexpr double kNoLimit = std::numeric_limits<double>::infinity();

struct ConstraintLimit {
  ConstraintDef def;
  double deviation = 0.0;          ///< current deviation from nominal [rad or m]
  double rate_per_m_day = 0.0;     ///< dq/dt per metre of Δa (at Δa → 0) [rad or m /(m day)]
  double quadratic_per_m = 0.0;    ///< κ in q = q0 + ρ Δa T (1 + κ Δa) (out-of-plane: 1/a)
  double raise_max_m = kNoLimit;   ///< largest Δa > 0 [m]
  double lower_max_m = kNoLimit;   ///< largest |Δa| for Δa < 0 [m]
  bool already_violated = false;
  bool involves_threatened = true;
};

struct LimitsResult {
  SatelliteId threatened;
  DriftCoefficients k;             ///< at the threatened satellite's a, e, i
  std::vector<ConstraintLimit> rows;
  double raise_max_m = kNoLimit;
  double lower_max_m = kNoLimit;
  std::string raise_binding;       ///< name of the row giving raise_max_m
  std::string lower_binding;
};

/// Table 1 for `threatened` over spec.horizon_days. Validates the spec.
LimitsResult compute_limits(const FormationSpec& spec, const SatelliteId& threatened);

/// Analytic deviation of row `r` after Δa (signed) held for `days` days.
double predicted_deviation(const ConstraintLimit& r, double delta_a_m, double days);

}  // namespace evade::formation
