// Constraint margins of paper 003's formation measured by numerical propagation
// (two-body + J2, DOP853) instead of the drift coefficients: the check of Table 1.
//
// Method. Every satellite entering a constraint of the threatened satellite X is propagated
// from its scenario elements (taken as osculating); X is propagated twice, without and with
// the burns. Relative osculating elements of each constrained pair (δΩ, δu, δi, and the
// second member's a, i) are averaged over one nodal period (trapezoid rule on N samples per
// period, which removes the J2 short-period terms to first order), and the constraint
// quantity of formation_model.hpp is evaluated on the averages. The maneuver's effect is
//   Δq(t) = q(averages with X maneuvered)(t) − q(averages with X unmaneuvered)(t),
// and the reported deviation is q0 + Δq(t) with q0 the scenario's current deviation. The
// difference removes the spurious relative drift caused by initializing osculating states
// from mean elements (up to km/day of along-track drift between satellites at different
// arguments of latitude), which is an artefact of the initialization, not of the maneuver.
// Values are given at window centres (every P/N from P/2 on); value_at() interpolates.
#pragma once

#include <map>
#include <vector>

#include "evade/dynamics/dop853.hpp"
#include "evade/formation/burn_propagation.hpp"
#include "evade/formation/formation_model.hpp"

namespace evade::formation {

struct PropagationSettings {
  AdaptiveOptions integrator{};  ///< DOP853 tolerances (defaults: rel 1e-10, abs 1e-6)
  int samples_per_rev = 32;      ///< samples per nodal period for the averaging [8, 512]
  void validate() const;
};

struct DeviationSeries {
  std::vector<double> t_s;        ///< window centres [s]
  std::vector<double> deviation;  ///< q0 + Δq at the centres [rad or m]
};

class FormationPropagator {
 public:
  /// Prepares the time grid up to t_eval_s (+ half a period) and propagates the
  /// unmaneuvered satellites. Throws std::invalid_argument on bad input.
  FormationPropagator(const FormationSpec& spec, const SatelliteId& threatened, double t_eval_s,
                      const PropagationSettings& settings);

  /// Deviation series of every row of constraints_for(spec, threatened), X maneuvered by
  /// `burns`.
  std::vector<DeviationSeries> series(const std::vector<TangentialBurn>& burns,
                                      std::vector<AppliedBurn>* applied = nullptr) const;

  const std::vector<ConstraintDef>& constraints() const { return defs_; }
  /// Current (scenario) deviation of each row.
  const std::vector<double>& initial_deviation() const { return q0_; }

 private:
  struct Angles {
    std::vector<MeanElements> osc;  // per grid sample
  };
  std::vector<double> averaged_deviation(const ConstraintDef& c, const Angles& first,
                                         const Angles& second) const;
  const Angles& angles_of(const SatelliteId& id) const;

  FormationSpec spec_;
  SatelliteId x_;
  PropagationSettings settings_;
  std::vector<ConstraintDef> defs_;
  std::vector<double> q0_;
  double t_eval_s_ = 0.0;
  double period_s_ = 0.0;
  int n_per_rev_ = 32;
  std::vector<double> grid_s_;
  std::vector<double> centres_s_;
  std::map<std::pair<std::size_t, int>, Angles> unmaneuvered_;
  std::vector<std::vector<double>> dev_unmaneuvered_;  // per row, at the centres
};

/// Linear interpolation of a series at t_s (clamped to its ends).
double value_at(const DeviationSeries& s, double t_s);

}  // namespace evade::formation
