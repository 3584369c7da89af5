// Avoidance decision of paper 003 sec. 3: raise or lower the threatened satellite's
// semi-major axis by the smallest Δa that gives the required miss distance within the
// Table-1 limits, burn `burn_before_tca_s` before the TCA (paper: 18 h) and restore
// `restore_after_tca_s` after it (paper: 12 h).
//
// Conjunction. The debris is given at the TCA relative to the threatened satellite's
// unmaneuvered (numerically propagated) state: miss vector and relative velocity (debris
// minus satellite, inertial velocity) on the satellite's RSW axes (R radial, S along track,
// W orbit normal). The miss of a maneuvered trajectory is the linear closest approach
// around the TCA: δr = r_d − r_x, δv = v_d − v_x at the TCA, t* = −δr·δv/|δv|²,
// miss = |δr + δv t*| (the relative motion is straight to < 1 mm over the few seconds of
// t* at km/s closing speeds).
//
// Decision. The satellite's position at the TCA moves by g Δa (g from a propagated probe
// burn, mostly −(3/2) n τ along track, τ = burn_before_tca_s). With P the projector normal
// to δv, miss²(Δa) = |P(δr0 − g Δa)|², a quadratic in Δa; for each direction the smallest
// |Δa| reaching the required miss solves it, then a secant iteration on the propagated
// miss makes it exact. The feasible direction (|Δa| ≤ its overall limit) with the smaller
// |Δa| (smaller Δv, smaller formation disturbance) is chosen. If neither is feasible, the
// decision says so and gives the best trade-off: the direction whose limit gives the larger
// miss, at that limit, and lists which rows the required Δa would break — never a silent
// violation.
#pragma once

#include <string>
#include <vector>

#include "evade/core/param.hpp"
#include "evade/core/state.hpp"
#include "evade/formation/burn_propagation.hpp"
#include "evade/formation/limits.hpp"
#include "evade/formation/numerical_constraints.hpp"

namespace evade::formation {

struct ConjunctionSpec {
  double tca_s = 0.0;                   ///< TCA from the scenario epoch [s]
  Vec3 miss_rsw_m = Vec3::Zero();       ///< debris − satellite at the TCA, RSW axes [m]
  Vec3 v_rel_rsw_mps = Vec3::Zero();    ///< debris − satellite velocity, RSW axes [m/s]
  double required_miss_m = 0.0;         ///< miss distance to reach [m]
  /// Throws std::invalid_argument naming the key ("conjunction.<key>"), value and range.
  void validate() const;
};

/// The scalar rows of ConjunctionSpec (scenario prefix "conjunction."): tca_s and
/// required_miss_m, both without default (0 is outside their ranges: required keys).
ParamTable<ConjunctionSpec> conjunction_spec_params() noexcept;

struct ManeuverTiming {
  double burn_before_tca_s = 18.0 * 3600.0;    ///< paper: 18 h
  double restore_after_tca_s = 12.0 * 3600.0;  ///< paper: 12 h
  bool restore = true;                         ///< apply the restore burn (−Δa)
  /// Throws std::invalid_argument naming the key ("maneuver.<key>"), value and range; the
  /// burn cannot precede the epoch (burn_before_tca_s <= tca_s).
  void validate(double tca_s) const;
};

/// ManeuverTiming's rows (scenario prefix "maneuver."), defaults those of paper 003.
ParamTable<ManeuverTiming> maneuver_timing_params() noexcept;

struct Encounter {
  double miss_m = 0.0;          ///< closest-approach distance [m]
  double t_offset_s = 0.0;      ///< closest approach − TCA [s]
  Vec3 miss_rsw_m = Vec3::Zero();  ///< debris − satellite at closest approach, RSW of the satellite [m]
};

/// Debris ECI state at the TCA from the satellite's state there and the conjunction.
StateEci debris_state_at_tca(const StateEci& sat_at_tca, const ConjunctionSpec& c);
/// Linear closest approach (see the file comment).
Encounter closest_approach(const StateEci& sat_at_tca, const StateEci& debris_at_tca);

struct DirectionOption {
  std::string direction;              ///< "raise" or "lower"
  double required_delta_a_m = 0.0;    ///< |Δa| reaching the required miss (inf: none)
  double limit_m = 0.0;               ///< overall Table-1 limit in this direction [m]
  bool feasible = false;
  double miss_at_required_m = 0.0;    ///< propagated miss at the required Δa [m]
  double miss_at_limit_m = 0.0;       ///< propagated miss at the limit [m]
  std::vector<std::string> violated;  ///< rows whose limit is below required_delta_a_m
};

struct Decision {
  bool maneuver_needed = true;
  bool feasible = false;
  std::string direction;          ///< "raise", "lower" or "none"
  double delta_a_m = 0.0;         ///< signed Δa of the first burn [m]
  double burn_time_s = 0.0;       ///< from the epoch [s]
  double restore_time_s = 0.0;    ///< from the epoch [s] (restore burn −Δa)
  bool restore = true;
  std::vector<AppliedBurn> burns; ///< Δv of each burn (vis-viva), from the propagation
  double nominal_miss_m = 0.0;    ///< without maneuver [m]
  double predicted_miss_m = 0.0;  ///< propagated miss with the chosen Δa [m]
  DirectionOption raise, lower;
  std::string summary;            ///< one sentence: what was chosen and why
  std::vector<TangentialBurn> burn_plan() const;
};

/// Decides the avoidance maneuver for `threatened`. Propagates its orbit (two-body + J2).
Decision decide(const FormationSpec& spec, const SatelliteId& threatened,
                const LimitsResult& limits, const ConjunctionSpec& conj,
                const ManeuverTiming& timing, const PropagationSettings& settings);

/// Propagated miss for a first burn of signed Δa at timing's burn time.
double propagated_miss(const FormationSpec& spec, const SatelliteId& threatened,
                       const ConjunctionSpec& conj, const ManeuverTiming& timing,
                       const PropagationSettings& settings, double delta_a_m);

}  // namespace evade::formation
