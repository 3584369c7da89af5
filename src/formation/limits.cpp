// Table 1 of paper 003: per-constraint and overall Δa limits (see limits.hpp).
#include "evade/formation/limits.hpp"

#include <algorithm>
#include <cmath>

#include "evade/core/elements.hpp"

namespace evade::formation {
namespace {

double sign_of(double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); }

// Largest x >= 0 with q0 + rho*d*x*(1 + kappa*d*x) inside [lo, hi]; rho already includes T.
double largest_step(double q0, double rho, double kappa, double d, double lo, double hi,
                    bool* violated) {
  if (q0 < lo || q0 > hi) {
    *violated = true;
    return 0.0;
  }
  const double slope = rho * d;
  if (slope == 0.0) return kNoLimit;
  const double g = (slope > 0.0 ? hi - q0 : lo - q0) / slope;  // >= 0: x (1 + κ d x) = g
  if (kappa == 0.0) return g;
  const double disc = 1.0 + 4.0 * kappa * d * g;
  if (disc <= 0.0) return 1.0 / (2.0 * kappa);  // never reaches the edge: vertex of the parabola
  return 2.0 * g / (1.0 + std::sqrt(disc));
}

}  // namespace

LimitsResult compute_limits(const FormationSpec& spec, const SatelliteId& threatened) {
  const std::vector<ConstraintDef> defs = constraints_for(spec, threatened);  // validates spec
  const MeanElements& mx = spec.sat(threatened);
  LimitsResult res;
  res.threatened = threatened;
  res.k = drift_coefficients(mx.a_m, mx.e, mx.i_rad, spec.earth);
  const double t = spec.horizon_days;
  for (const ConstraintDef& c : defs) {
    ConstraintLimit row;
    row.def = c;
    const MeanElements& f = spec.sat(c.first);
    const MeanElements& s = spec.sat(c.second);
    row.deviation = deviation(c, f, s);
    // ∂q/∂(angle of X): +1 when X is `first`, -1 when X is `second`, 0 otherwise.
    const double role = (threatened == c.first ? 1.0 : 0.0) - (threatened == c.second ? 1.0 : 0.0);
    row.involves_threatened = role != 0.0;
    switch (c.kind) {
      case ConstraintKind::kInterGroupRaan:  // paper eq. 3: Δa ≤ ΔΩ / (K_Ω T)
        row.rate_per_m_day = role * res.k.k_omega_rad_per_m_day;
        break;
      case ConstraintKind::kInterGroupPhase:  // paper eq. 5: Δa ≤ Δφ / (K_φ T)
        row.rate_per_m_day = role * res.k.k_phi_rad_per_m_day;
        break;
      case ConstraintKind::kOutOfPlane: {  // Δa K_Ω T (a + Δa) sin i ≤ Δh
        const double d_raan = wrap_pi(f.raan_rad - s.raan_rad);
        row.rate_per_m_day =
            role * sign_of(d_raan) * res.k.k_omega_rad_per_m_day * mx.a_m * std::sin(mx.i_rad);
        row.quadratic_per_m = 1.0 / mx.a_m;
        break;
      }
      case ConstraintKind::kInPlane: {  // Δa K_am T ≤ ΔS
        const double sep = wrap_pi(f.arg_lat_rad - s.arg_lat_rad +
                                         wrap_pi(f.raan_rad - s.raan_rad) * std::cos(s.i_rad));
        row.rate_per_m_day = role * sign_of(sep) * res.k.k_am_m_per_m_day;
        break;
      }
    }
    bool violated = false;
    row.raise_max_m = largest_step(row.deviation, row.rate_per_m_day * t, row.quadratic_per_m, 1.0,
                                   c.lower, c.upper, &violated);
    row.lower_max_m = largest_step(row.deviation, row.rate_per_m_day * t, row.quadratic_per_m,
                                   -1.0, c.lower, c.upper, &violated);
    row.already_violated = violated;
    if (row.raise_max_m < res.raise_max_m) {
      res.raise_max_m = row.raise_max_m;
      res.raise_binding = c.name;
    }
    if (row.lower_max_m < res.lower_max_m) {
      res.lower_max_m = row.lower_max_m;
      res.lower_binding = c.name;
    }
    res.rows.push_back(row);
  }
  return res;
}

double predicted_deviation(const ConstraintLimit& r, double delta_a_m, double days) {
  return r.deviation + r.rate_per_m_day * days * delta_a_m * (1.0 + r.quadratic_per_m * delta_a_m);
}

}  // namespace evade::formation
