// Verification by propagation of paper 003's avoidance (sec. 3 "precise orbit determination
// and configuration analysis" after the maneuver): two-body + J2 propagation of the
// threatened group and the reference group with the burns applied; the miss at the TCA and
// each constraint's minimum margin over [0, burn time + T days]
// (numerical_constraints.hpp for how the margins are measured). Also the numerical
// counterpart of Table 1: limits found by bisection on Δa (held for T days, no restore)
// with the propagated constraint margins.
#pragma once

#include <string>
#include <vector>

#include "evade/formation/decision.hpp"
#include "evade/formation/limits.hpp"
#include "evade/formation/numerical_constraints.hpp"

namespace evade::formation {

struct ConstraintCheck {
  std::string name;
  double lower = 0.0, upper = 0.0;       ///< band [rad or m]
  double initial_deviation = 0.0;        ///< [rad or m]
  double final_deviation = 0.0;          ///< at burn + T days, propagated [rad or m]
  double min_margin = 0.0;               ///< smallest distance to an edge over the window
  double t_min_margin_s = 0.0;           ///< when [s from the epoch]
  bool kept = false;
};

struct Verification {
  double miss_at_tca_m = 0.0;            ///< propagated closest approach [m]
  double closest_approach_offset_s = 0.0;
  bool clears = false;                   ///< miss >= required
  std::vector<ConstraintCheck> rows;
  bool all_kept = false;
  double window_end_s = 0.0;             ///< burn + T days [s from the epoch]
  std::vector<AppliedBurn> burns;
};

Verification verify(const FormationSpec& spec, const SatelliteId& threatened,
                    const ConjunctionSpec& conj, const Decision& decision,
                    const PropagationSettings& settings);

struct NumericalLimitRow {
  std::string name;
  double raise_max_m = kNoLimit;
  double lower_max_m = kNoLimit;
  int propagations = 0;
};

/// For each row X enters: the Δa (per direction) at which the propagated deviation at
/// burn_time_s + T days reaches the band edge, to relative tolerance rel_tol (bracketing
/// with the analytic limit, then bisection/regula falsi). Rows X does not enter: +inf.
std::vector<NumericalLimitRow> numerical_limits(const FormationSpec& spec,
                                                const SatelliteId& threatened,
                                                const LimitsResult& analytic, double burn_time_s,
                                                const PropagationSettings& settings,
                                                double rel_tol = 1e-3);

}  // namespace evade::formation
