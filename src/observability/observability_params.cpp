// The observability command's parameter table (include/evade/observability/
// observability_params.hpp). Paper 004 (Yu, Wang, Zhou, "Anti-rendezvous evasive maneuver
// considering spatial geometry"): §2.1 (the fixed |Δv|, the azimuth bounds −3π/2 ≤ θ ≤ −π/2
// and |ε| ≤ ξ), §3 (the 400 km circular orbit, the 0.1 Hz observation over 1000 s), the GA
// budget of §2.2 (population 80 × 30 generations, our ISRES) and the published optimum. The
// ranges are those the command has always accepted.
#include "evade/observability/observability_params.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace evade::observability {
namespace {

using P = ObservabilityParams;

const Param<P> kRows[] = {
    EVADE_PARAM_REAL(P, evader.altitude_m, "m", 1e5, 1e8, false,
                     "altitude of the evader's circular orbit above earth.re_m"),
    EVADE_PARAM_REAL(P, burn.dv_mps, "m/s", 1e-6, 1e4, false,
                     "fixed burn magnitude (norm of dv)"),
    EVADE_PARAM_REAL(P, burn.theta_min_rad, "rad", -2.0 * kTwoPi, 2.0 * kTwoPi, false,
                     "lower bound of the burn azimuth theta (frame P)"),
    EVADE_PARAM_REAL(P, burn.theta_max_rad, "rad", -2.0 * kTwoPi, 2.0 * kTwoPi, false,
                     "upper bound of the burn azimuth theta (frame P)"),
    EVADE_PARAM_REAL(P, burn.eps_max_rad, "rad", 0.0, 0.5 * kPi, false,
                     "bound xi of the burn elevation: abs(eps) <= xi"),
    EVADE_PARAM_REAL(P, observation.dt_s, "s", 1e-3, 1e5, false,
                     "interval of the chaser's angle measurements"),
    EVADE_PARAM_REAL(P, observation.window_s, "s", 1e-3, 1e7, false,
                     "observation window after the burn (samples k dt_s, k = 0..N)"),
    EVADE_PARAM_REAL(P, estimation.sigma_rad, "rad", 1e-12, 1.0, false,
                     "1-sigma noise of each measured angle (estimation objective, summaries)"),
    EVADE_PARAM_BOOL(P, estimation.estimator_knows_burn,
                     "the chaser's batch fit includes the true burn"),
    EVADE_PARAM_INT(P, estimation.max_iterations, "-", 1, 10000,
                    "Levenberg-Marquardt iterations of the batch fit"),
    EVADE_PARAM_INT(P, isres.seed, "-", 0, 2147483647,
                    "ISRES random seed (--seed overrides it)"),
    EVADE_PARAM_INT(P, isres.population, "-", 0, 100000,
                    "ISRES population (0: NLopt's default)"),
    EVADE_PARAM_INT(P, isres.max_evaluations, "-", 1, 100000000, "ISRES evaluation budget"),
    EVADE_PARAM_REAL(P, isres.xtol_rel, "-", 0.0, 1.0, false,
                     "ISRES relative x tolerance (0: budget-limited)"),
    EVADE_PARAM_INT(P, isres.polish_max_evaluations, "-", 1, 1000000,
                    "evaluation budget of the local polish after ISRES"),
    EVADE_PARAM_REAL(P, paper.theta_rad, "rad", -kTwoPi, kTwoPi, false,
                     "the paper's published optimum theta (compared with the plan)"),
    EVADE_PARAM_REAL(P, paper.eps_rad, "rad", -kPi, kPi, false,
                     "the paper's published optimum eps"),
    EVADE_PARAM_REAL(P, paper.f, "-", -1e9, 1e9, false,
                     "the paper's value of eq. 23 at its optimum (echoed)"),
};

}  // namespace

ParamTable<ObservabilityParams> observability_params() noexcept {
  return make_param_table(kRows);
}

void ObservabilityParams::validate() const {
  const std::string error = validate_params(observability_params(), *this, "");
  if (!error.empty()) throw std::invalid_argument(error);
}

ObservabilityProblem ObservabilityParams::problem(const EarthModel& earth,
                                                  const Vec6& x_chaser_p0) const {
  ObservabilityProblem p;
  p.n_radps = std::sqrt(earth.mu_m3ps2 / std::pow(earth.re_m + evader.altitude_m, 3));
  p.x_chaser_p0 = x_chaser_p0;
  p.dv_mps = burn.dv_mps;
  p.theta_min_rad = burn.theta_min_rad;
  p.theta_max_rad = burn.theta_max_rad;
  p.eps_max_rad = burn.eps_max_rad;
  p.dt_obs_s = observation.dt_s;
  p.t_obs_s = observation.window_s;
  return p;
}

EstimationConfig ObservabilityParams::estimation_config() const {
  EstimationConfig ec;
  ec.sigma_rad = estimation.sigma_rad;
  ec.estimator_knows_burn = estimation.estimator_knows_burn;
  ec.max_iterations = estimation.max_iterations;
  return ec;
}

IsresOptions ObservabilityParams::isres_options() const {
  IsresOptions io;
  io.seed = static_cast<std::uint64_t>(isres.seed);
  io.population = isres.population;
  io.max_evaluations = isres.max_evaluations;
  io.xtol_rel = isres.xtol_rel;
  io.polish_max_evaluations = isres.polish_max_evaluations;
  return io;
}

}  // namespace evade::observability
