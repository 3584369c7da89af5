// Verification by propagation and numerical Table 1 (see verification.hpp).
#include "evade/formation/verification.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace evade::formation {

Verification verify(const FormationSpec& spec, const SatelliteId& threatened,
                    const ConjunctionSpec& conj, const Decision& decision,
                    const PropagationSettings& settings) {
  conj.validate();
  Verification v;
  v.window_end_s = decision.burn_time_s + spec.horizon_days * kSecondsPerDay;
  const double t_eval = std::max(v.window_end_s, decision.restore_time_s);
  FormationPropagator fp(spec, threatened, t_eval, settings);
  const std::vector<TangentialBurn> plan = decision.burn_plan();
  const std::vector<DeviationSeries> ser = fp.series(plan, &v.burns);
  v.all_kept = true;
  for (std::size_t r = 0; r < ser.size(); ++r) {
    const ConstraintDef& c = fp.constraints()[r];
    ConstraintCheck cc;
    cc.name = c.name;
    cc.lower = c.lower;
    cc.upper = c.upper;
    cc.initial_deviation = fp.initial_deviation()[r];
    cc.final_deviation = value_at(ser[r], v.window_end_s);
    cc.min_margin = margin(c, cc.final_deviation);
    cc.t_min_margin_s = v.window_end_s;
    for (std::size_t k = 0; k < ser[r].t_s.size() && ser[r].t_s[k] <= v.window_end_s; ++k) {
      const double m = margin(c, ser[r].deviation[k]);
      if (m < cc.min_margin) {
        cc.min_margin = m;
        cc.t_min_margin_s = ser[r].t_s[k];
      }
    }
    cc.kept = cc.min_margin >= 0.0;
    v.all_kept = v.all_kept && cc.kept;
    v.rows.push_back(cc);
  }
  const StateEci s0 = state_from_mean_elements(spec.sat(threatened), spec.earth);
  const StateEci nominal =
      propagate_with_burns(s0, {conj.tca_s}, {}, spec.earth, settings.integrator).front();
  const StateEci man =
      propagate_with_burns(s0, {conj.tca_s}, plan, spec.earth, settings.integrator).front();
  const Encounter e = closest_approach(man, debris_state_at_tca(nominal, conj));
  v.miss_at_tca_m = e.miss_m;
  v.closest_approach_offset_s = e.t_offset_s;
  v.clears = e.miss_m >= conj.required_miss_m;
  return v;
}

namespace {

/// The margin of one row at the end of the window after a Δa [m] held from the burn.
using MarginFn = std::function<double(double delta_a_m)>;

struct Bracket {
  double lo = 0.0, f_lo = 0.0;  ///< |Δa| keeping the row (margin f_lo > 0)
  double hi = 0.0, f_hi = 0.0;  ///< |Δa| breaking it (f_hi <= 0)
};

// Illinois regula falsi on the bracket, in direction d (+1 raise, −1 lower): stops at the
// relative width rel_tol or when a margin is within zero_tol of 0.
double illinois(const MarginFn& margin_at, double d, Bracket b, double rel_tol, double zero_tol) {
  int side = 0;
  for (int it = 0; it < 60 && (b.hi - b.lo) > rel_tol * b.hi; ++it) {
    const double xm = (b.lo * b.f_hi - b.hi * b.f_lo) / (b.f_hi - b.f_lo);
    const double fm = margin_at(d * xm);
    if (fm > 0.0) {
      b.lo = xm;
      b.f_lo = fm;
      if (side == -1) b.f_hi *= 0.5;
      side = -1;
    } else {
      b.hi = xm;
      b.f_hi = fm;
      if (side == 1) b.f_lo *= 0.5;
      side = 1;
    }
    if (std::abs(fm) < zero_tol) b.lo = b.hi = xm;
  }
  return 0.5 * (b.lo + b.hi);
}

// The numerical limit of one row in direction d: bracketed from the analytic value (1.2×,
// doubling up to 100×), then regula falsi. 0 when the analytic limit is 0; +inf when it is
// infinite or not reached within 100× of it.
double limit_in_direction(const MarginFn& margin_at, const ConstraintLimit& row, double d,
                          double rel_tol) {
  const double guess = d > 0 ? row.raise_max_m : row.lower_max_m;
  if (guess == 0.0) return 0.0;
  if (!std::isfinite(guess)) return kNoLimit;
  Bracket b;
  b.f_lo = margin(row.def, row.deviation);
  b.hi = 1.2 * guess;
  b.f_hi = margin_at(d * b.hi);
  while (b.f_hi > 0.0 && b.hi < 100.0 * guess) {
    b.lo = b.hi;
    b.f_lo = b.f_hi;
    b.hi *= 2.0;
    b.f_hi = margin_at(d * b.hi);
  }
  if (b.f_hi > 0.0) return kNoLimit;  // not reached within 100x the analytic value
  return illinois(margin_at, d, b, rel_tol,
                  1e-9 * (std::abs(row.def.upper) + std::abs(row.def.lower)));
}

}  // namespace

std::vector<NumericalLimitRow> numerical_limits(const FormationSpec& spec,
                                                const SatelliteId& threatened,
                                                const LimitsResult& analytic, double burn_time_s,
                                                const PropagationSettings& settings,
                                                double rel_tol) {
  if (!std::isfinite(burn_time_s) || burn_time_s < 0.0) {
    throw std::invalid_argument("numerical_limits: burn_time_s = " + std::to_string(burn_time_s) +
                                " outside [0, inf)");
  }
  const double t_eval = burn_time_s + spec.horizon_days * kSecondsPerDay;
  FormationPropagator fp(spec, threatened, t_eval, settings);
  std::vector<NumericalLimitRow> out;
  for (std::size_t r = 0; r < analytic.rows.size(); ++r) {
    const ConstraintLimit& row = analytic.rows[r];
    NumericalLimitRow nr;
    nr.name = row.def.name;
    if (row.involves_threatened) {
      const MarginFn margin_at = [&](double delta_a) {
        ++nr.propagations;
        const std::vector<DeviationSeries> s = fp.series({{burn_time_s, delta_a}});
        return margin(row.def, value_at(s[r], t_eval));
      };
      nr.raise_max_m = limit_in_direction(margin_at, row, 1.0, rel_tol);
      nr.lower_max_m = limit_in_direction(margin_at, row, -1.0, rel_tol);
    }
    out.push_back(nr);
  }
  return out;
}

}  // namespace evade::formation
