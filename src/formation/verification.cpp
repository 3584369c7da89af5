// Verification by propagation and numerical Table 1 (see verification.hpp).
#include "evade/formation/verification.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
    if (!row.involves_threatened) {
      out.push_back(nr);
      continue;
    }
    auto margin_at = [&](double delta_a) {
      ++nr.propagations;
      const std::vector<DeviationSeries> s = fp.series({{burn_time_s, delta_a}});
      return margin(row.def, value_at(s[r], t_eval));
    };
    for (double d : {1.0, -1.0}) {
      const double guess = d > 0 ? row.raise_max_m : row.lower_max_m;
      double result = kNoLimit;
      if (guess == 0.0) {
        result = 0.0;
      } else if (std::isfinite(guess)) {
        double lo = 0.0, f_lo = margin(row.def, row.deviation);
        double hi = 1.2 * guess, f_hi = margin_at(d * hi);
        while (f_hi > 0.0 && hi < 100.0 * guess) {
          lo = hi;
          f_lo = f_hi;
          hi *= 2.0;
          f_hi = margin_at(d * hi);
        }
        if (f_hi > 0.0) {
          result = kNoLimit;  // not reached within 100x the analytic value
        } else {
          int side = 0;  // Illinois regula falsi
          for (int it = 0; it < 60 && (hi - lo) > rel_tol * hi; ++it) {
            const double xm = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
            const double fm = margin_at(d * xm);
            if (fm > 0.0) {
              lo = xm;
              f_lo = fm;
              if (side == -1) f_hi *= 0.5;
              side = -1;
            } else {
              hi = xm;
              f_hi = fm;
              if (side == 1) f_lo *= 0.5;
              side = 1;
            }
            if (std::abs(fm) < 1e-9 * (std::abs(row.def.upper) + std::abs(row.def.lower))) {
              lo = hi = xm;
            }
          }
          result = 0.5 * (lo + hi);
        }
      }
      (d > 0 ? nr.raise_max_m : nr.lower_max_m) = result;
    }
    out.push_back(nr);
  }
  return out;
}

}  // namespace evade::formation
