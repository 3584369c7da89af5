// Avoidance decision of paper 003 sec. 3 (see decision.hpp).
#include "evade/formation/decision.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "evade/core/frames.hpp"

namespace evade::formation {
namespace {

[[noreturn]] void fail_decision(const std::string& field, double v, const std::string& range) {
  throw std::invalid_argument(field + " = " + std::to_string(v) + " outside " + range);
}

StateEci sat_at(const FormationSpec& spec, const SatelliteId& x, double t_s,
                const std::vector<TangentialBurn>& burns, const PropagationSettings& settings) {
  const StateEci s0 = state_from_mean_elements(spec.sat(x), spec.earth);
  return propagate_with_burns(s0, {t_s}, burns, spec.earth, settings.integrator).front();
}

const Param<ConjunctionSpec> kConjunctionRows[] = {
    EVADE_PARAM_REAL(ConjunctionSpec, tca_s, "s", 1.0, 30.0 * kSecondsPerDay, false,
                     "time of closest approach from the scenario epoch"),
    EVADE_PARAM_REAL(ConjunctionSpec, required_miss_m, "m", 1e-3, 1e5, false,
                     "miss distance the maneuver must reach"),
};

const Param<ManeuverTiming> kManeuverRows[] = {
    EVADE_PARAM_REAL(ManeuverTiming, burn_before_tca_s, "s", 1.0, 30.0 * kSecondsPerDay, false,
                     "first burn this long before the TCA (paper: 18 h; at most tca_s)"),
    EVADE_PARAM_REAL(ManeuverTiming, restore_after_tca_s, "s", 1.0, 30.0 * kSecondsPerDay, false,
                     "restore burn this long after the TCA (paper: 12 h)"),
    EVADE_PARAM_BOOL(ManeuverTiming, restore, "apply the restore burn (-delta_a)"),
};

template <class Cfg>
void check_params(const ParamTable<Cfg>& table, const Cfg& c, const std::string& prefix) {
  const std::string bad = validate_params(table, c, prefix);
  if (!bad.empty()) throw std::invalid_argument(bad);
}

}  // namespace

ParamTable<ConjunctionSpec> conjunction_spec_params() noexcept {
  return make_param_table(kConjunctionRows);
}

ParamTable<ManeuverTiming> maneuver_timing_params() noexcept {
  return make_param_table(kManeuverRows);
}

void ConjunctionSpec::validate() const {
  check_params(conjunction_spec_params(), *this, "conjunction.");
  if (!miss_rsw_m.allFinite() || miss_rsw_m.norm() > 1e5) {
    fail_decision("conjunction.miss_rsw_m (norm)", miss_rsw_m.norm(), "finite, [0, 1e5] m");
  }
  if (!v_rel_rsw_mps.allFinite() || v_rel_rsw_mps.norm() < 10.0 || v_rel_rsw_mps.norm() > 2e4) {
    fail_decision("conjunction.v_rel_rsw_mps (norm)", v_rel_rsw_mps.norm(),
         "finite, [10, 2e4] m/s (a fast encounter: the linear closest approach needs it)");
  }
}

void ManeuverTiming::validate(double tca_s) const {
  check_params(maneuver_timing_params(), *this, "maneuver.");
  if (burn_before_tca_s > tca_s) {
    throw std::invalid_argument("key 'maneuver.burn_before_tca_s' = '" +
                                param_value_text(burn_before_tca_s) +
                                "' is invalid: expected at most conjunction.tca_s = " +
                                param_value_text(tca_s) + " s (the burn cannot precede the epoch)");
  }
}

std::vector<TangentialBurn> Decision::burn_plan() const {
  std::vector<TangentialBurn> b;
  if (!maneuver_needed || delta_a_m == 0.0) return b;
  b.push_back({burn_time_s, delta_a_m});
  if (restore) b.push_back({restore_time_s, -delta_a_m});
  return b;
}

StateEci debris_state_at_tca(const StateEci& sat, const ConjunctionSpec& c) {
  const Mat3 c_rsw = rotation_eci_to_rsw(sat);  // rows R, S, W in ECI
  StateEci d;
  d.r_eci_m = sat.r_eci_m + c_rsw.transpose() * c.miss_rsw_m;
  d.v_eci_mps = sat.v_eci_mps + c_rsw.transpose() * c.v_rel_rsw_mps;
  return d;
}

Encounter closest_approach(const StateEci& sat, const StateEci& deb) {
  const Vec3 dr = deb.r_eci_m - sat.r_eci_m;
  const Vec3 dv = deb.v_eci_mps - sat.v_eci_mps;
  Encounter e;
  e.t_offset_s = -dr.dot(dv) / dv.squaredNorm();
  const Vec3 m = dr + dv * e.t_offset_s;
  e.miss_m = m.norm();
  e.miss_rsw_m = rotation_eci_to_rsw(sat) * m;
  return e;
}

double propagated_miss(const FormationSpec& spec, const SatelliteId& threatened,
                       const ConjunctionSpec& conj, const ManeuverTiming& timing,
                       const PropagationSettings& settings, double delta_a_m) {
  const double t_b = conj.tca_s - timing.burn_before_tca_s;
  const StateEci nominal = sat_at(spec, threatened, conj.tca_s, {}, settings);
  const StateEci deb = debris_state_at_tca(nominal, conj);
  if (delta_a_m == 0.0) return closest_approach(nominal, deb).miss_m;
  const StateEci man = sat_at(spec, threatened, conj.tca_s, {{t_b, delta_a_m}}, settings);
  return closest_approach(man, deb).miss_m;
}

namespace {

// What a direction's solution needs besides the miss model.
struct DecisionInputs {
  const FormationSpec& spec;
  const SatelliteId& x;
  const LimitsResult& limits;
  const ConjunctionSpec& conj;
  const ManeuverTiming& timing;
  const PropagationSettings& settings;

  double miss(double delta_a_m) const {
    return propagated_miss(spec, x, conj, timing, settings, delta_a_m);
  }
};

// Linear model of the miss (decision.hpp): δr(Δa) = δr0 − g Δa, g from a propagated 1 m
// probe, both projected normal to δv (P).
struct MissModel {
  Vec3 pr0;            // P δr0
  Vec3 pg;             // P g
  double target = 0.0; // required miss with a 1e-4 relative margin [m]
};

MissModel miss_model(const DecisionInputs& in, const StateEci& nominal, const StateEci& deb,
                     double burn_time_s) {
  const double probe_m = 1.0;
  const StateEci probe =
      sat_at(in.spec, in.x, in.conj.tca_s, {{burn_time_s, probe_m}}, in.settings);
  const Vec3 g = (probe.r_eci_m - nominal.r_eci_m) / probe_m;
  const Vec3 dv = deb.v_eci_mps - nominal.v_eci_mps;
  const Vec3 vhat = dv.normalized();
  auto perp = [&](const Vec3& v) -> Vec3 { return v - vhat * vhat.dot(v); };
  MissModel mm;
  mm.pr0 = perp(deb.r_eci_m - nominal.r_eci_m);
  mm.pg = perp(g);
  mm.target = in.conj.required_miss_m * (1.0 + 1e-4);
  return mm;
}

// Smallest |Δa| in direction d (+1 raise, −1 lower) reaching the target: the quadratic's
// root, then Newton steps on the propagated miss; the miss at the limit; the rows whose
// limit the required Δa breaks.
void solve_direction(DirectionOption& opt, double d, const MissModel& mm,
                     const DecisionInputs& in, double nominal_miss_m) {
  const Vec3& pr0 = mm.pr0;
  const Vec3& pg = mm.pg;
  const double target = mm.target;
  const double qa = pg.squaredNorm();
  const double qb = -2.0 * d * pr0.dot(pg);
  const double qc = pr0.squaredNorm() - target * target;
  const double disc = qb * qb - 4.0 * qa * qc;
  if (!(qa > 0.0) || disc < 0.0) {
    opt.required_delta_a_m = kNoLimit;
  } else {
    double xr = (-qb + std::sqrt(disc)) / (2.0 * qa);
    double m = in.miss(d * xr);
    for (int it = 0; it < 8 && m < target; ++it) {  // Newton on the propagated miss
      const Vec3 rel = pr0 - pg * d * xr;
      const double slope = -d * rel.dot(pg) / std::max(rel.norm(), 1e-9);
      if (!(slope > 0.0)) break;
      xr += (target - m) / slope + 1e-6 * xr;
      m = in.miss(d * xr);
    }
    opt.required_delta_a_m = xr;
    opt.miss_at_required_m = m;
  }
  const double lim = opt.limit_m;
  opt.feasible = opt.required_delta_a_m <= lim;
  if (std::isfinite(lim) && lim > 0.0) {
    opt.miss_at_limit_m = in.miss(d * lim);
  } else if (lim == 0.0) {
    opt.miss_at_limit_m = nominal_miss_m;
  } else {
    opt.miss_at_limit_m = std::numeric_limits<double>::infinity();
  }
  for (const ConstraintLimit& row : in.limits.rows) {
    const double rl = d > 0 ? row.raise_max_m : row.lower_max_m;
    if (rl < opt.required_delta_a_m) opt.violated.push_back(row.def.name);
  }
}

// The feasible direction with the smaller |Δa|, else the best trade-off at a limit; the
// summary says which and why.
void choose_direction(Decision& dec, double required_miss_m) {
  std::ostringstream why;
  const DirectionOption* pick = nullptr;
  if (dec.raise.feasible && dec.lower.feasible) {
    pick = dec.raise.required_delta_a_m <= dec.lower.required_delta_a_m ? &dec.raise : &dec.lower;
    why << pick->direction << " by " << pick->required_delta_a_m
        << " m: both directions are within the limits, this one needs the smaller change";
  } else if (dec.raise.feasible || dec.lower.feasible) {
    pick = dec.raise.feasible ? &dec.raise : &dec.lower;
    const DirectionOption& other = dec.raise.feasible ? dec.lower : dec.raise;
    why << pick->direction << " by " << pick->required_delta_a_m << " m (limit " << pick->limit_m
        << " m); " << other.direction << " would need " << other.required_delta_a_m
        << " m, beyond its limit " << other.limit_m << " m";
  }
  if (pick != nullptr) {
    dec.feasible = true;
    dec.direction = pick->direction;
    dec.delta_a_m = (pick == &dec.raise ? 1.0 : -1.0) * pick->required_delta_a_m;
    dec.predicted_miss_m = pick->miss_at_required_m;
  } else {
    // Infeasible: best trade-off = the direction whose limit gives the larger miss.
    dec.feasible = false;
    pick = dec.raise.miss_at_limit_m >= dec.lower.miss_at_limit_m ? &dec.raise : &dec.lower;
    dec.direction = pick->direction;
    dec.delta_a_m = (pick == &dec.raise ? 1.0 : -1.0) * pick->limit_m;
    dec.predicted_miss_m = pick->miss_at_limit_m;
    why << "INFEASIBLE: required miss " << required_miss_m << " m needs raise "
        << dec.raise.required_delta_a_m << " m (limit " << dec.raise.limit_m << " m) or lower "
        << dec.lower.required_delta_a_m << " m (limit " << dec.lower.limit_m
        << " m); best trade-off within every constraint: " << pick->direction << " by "
        << pick->limit_m << " m giving a miss of " << pick->miss_at_limit_m << " m";
  }
  dec.summary = why.str();
}

}  // namespace

Decision decide(const FormationSpec& spec, const SatelliteId& threatened,
                const LimitsResult& limits, const ConjunctionSpec& conj,
                const ManeuverTiming& timing, const PropagationSettings& settings) {
  spec.validate();
  conj.validate();
  timing.validate(conj.tca_s);
  settings.validate();
  Decision dec;
  dec.burn_time_s = conj.tca_s - timing.burn_before_tca_s;
  dec.restore_time_s = conj.tca_s + timing.restore_after_tca_s;
  dec.restore = timing.restore;

  const StateEci nominal = sat_at(spec, threatened, conj.tca_s, {}, settings);
  const StateEci deb = debris_state_at_tca(nominal, conj);
  const Encounter enc0 = closest_approach(nominal, deb);
  dec.nominal_miss_m = enc0.miss_m;
  dec.raise.direction = "raise";
  dec.lower.direction = "lower";
  dec.raise.limit_m = limits.raise_max_m;
  dec.lower.limit_m = limits.lower_max_m;
  if (enc0.miss_m >= conj.required_miss_m) {
    dec.maneuver_needed = false;
    dec.feasible = true;
    dec.direction = "none";
    dec.predicted_miss_m = enc0.miss_m;
    dec.summary = "nominal miss already meets the requirement: no maneuver";
    return dec;
  }

  const DecisionInputs in{spec, threatened, limits, conj, timing, settings};
  const MissModel mm = miss_model(in, nominal, deb, dec.burn_time_s);
  solve_direction(dec.raise, 1.0, mm, in, enc0.miss_m);
  solve_direction(dec.lower, -1.0, mm, in, enc0.miss_m);
  choose_direction(dec, conj.required_miss_m);
  // Δv of each burn from the propagation (vis-viva at the burn point).
  if (dec.delta_a_m != 0.0) {
    const StateEci s0 = state_from_mean_elements(spec.sat(threatened), spec.earth);
    const double t_last = dec.restore ? dec.restore_time_s : dec.burn_time_s;
    propagate_with_burns(s0, {t_last}, dec.burn_plan(), spec.earth, settings.integrator,
                         &dec.burns);
  }
  return dec;
}

}  // namespace evade::formation
