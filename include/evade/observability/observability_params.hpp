// The observability command's parameters (paper 004, Yu, Wang, Zhou, "Anti-rendezvous
// evasive maneuver considering spatial geometry"): the one declaration of each numeric
// scenario key's unit, range and meaning (evade/core/param.hpp).
//
// The struct is laid out like the scenario (evader., burn., observation., estimation.,
// isres., paper.), so that a field's path is its key (`burn.dv_mps`) and the table is read
// with prefix "". The keys without a usable default (the geometry, the burn and the
// observation window of paper §2.1 and §3) default to NaN, outside every range: they are
// required (config::require_params), and `evade params` prints them as "(required)". The
// lists (chaser state, prior sigmas, the comparison directions A and B) and the names
// (objective, k0 term, polish) are read beside the table (observability_command.hpp), Earth
// through the one Earth table (core/earth_params.hpp).
#pragma once

#include <limits>

#include "evade/core/constants.hpp"
#include "evade/core/param.hpp"
#include "evade/core/state.hpp"
#include "evade/observability/estimation.hpp"
#include "evade/observability/planner.hpp"
#include "evade/observability/problem.hpp"

namespace evade::observability {

/// Every number of `evade plan observability`. Defaults: NaN (required), else the command's.
struct ObservabilityParams {
  static constexpr double kRequired = std::numeric_limits<double>::quiet_NaN();

  struct Evader {
    double altitude_m = kRequired;  ///< circular orbit altitude above earth.re_m
  } evader;
  struct Burn {
    double dv_mps = kRequired;         ///< fixed |Δv| (paper §2.1)
    double theta_min_rad = kRequired;  ///< azimuth bounds in frame P (paper §2.1)
    double theta_max_rad = kRequired;
    double eps_max_rad = kRequired;    ///< |ε| <= ξ
  } burn;
  struct Observation {
    double dt_s = kRequired;      ///< measurement interval
    double window_s = kRequired;  ///< observation window after t0
  } observation;
  struct Estimation {
    double sigma_rad = EstimationConfig{}.sigma_rad;
    bool estimator_knows_burn = false;
    int max_iterations = 50;
  } estimation;
  struct Isres {
    int seed = 1;
    int population = 80;
    int max_evaluations = 2400;
    double xtol_rel = 0.0;
    int polish_max_evaluations = 400;
  } isres;
  struct Paper {
    double theta_rad = -3.231;  ///< the paper's published optimum θ
    double eps_rad = 0.0;       ///< ... and ε
    double f = 100.9991;        ///< eq. 23 at the paper's optimum (echoed)
  } paper;

  /// Throws std::invalid_argument naming the first bad key (param_error text).
  void validate() const;
  /// The problem of paper §3: mean motion n = √(μ / (Re + h)³) of the evader's circular
  /// orbit, the chaser's state X_P0 (frame P), the burn and the observation window.
  ObservabilityProblem problem(const EarthModel& earth, const Vec6& x_chaser_p0) const;
  /// The estimation settings (the prior sigmas keep EstimationConfig's defaults).
  EstimationConfig estimation_config() const;
  /// ISRES's options (polish kBobyqa, no progress callback).
  IsresOptions isres_options() const;
};

/// evader.altitude_m, burn.*, observation.*, estimation.sigma_rad,
/// estimation.estimator_knows_burn, estimation.max_iterations, isres.* (but isres.polish),
/// paper.theta_rad, paper.eps_rad, paper.f.
ParamTable<ObservabilityParams> observability_params() noexcept;

}  // namespace evade::observability
