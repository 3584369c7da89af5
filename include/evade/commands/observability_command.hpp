// `evade plan observability` as a library call: the observability-minimizing evasive burn of
// paper 004 (Yu, Wang, Zhou, "Anti-rendezvous evasive maneuver considering spatial
// geometry"; eq. 23 and §3). read_observability_request reads the scenario (every key and
// its range: observability/observability_params.hpp, Earth through the Earth table), run_observability
// samples the problem, plans with NLopt ISRES (+ local polish) over the chosen objective
// (observability/planner.hpp) and compares the plan with no burn and the paper's directions
// (compare_with_paper); to_json and to_text are the command's two outputs. Publishing the
// plan (observability::make_burn_plan, observability/burn_plan.hpp) stays with the caller: this library is LCM-free.
//
// Frames: dv_lvlh_mps in RSW (x radial out, y along track, z orbit normal); θ, ε and
// dv_paper_mps in the paper frame P (x to the Earth's centre, y = −along track, z normal);
// the burn is at t0, the epoch of the chaser's relative state (the paper gives no date).
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "evade/config/scenario.hpp"
#include "evade/observability/comparison.hpp"
#include "evade/observability/estimation.hpp"
#include "evade/observability/planner.hpp"
#include "evade/observability/problem.hpp"

namespace evade::commands {

/// Command-line values that replace a scenario key (empty / negative: the scenario's).
struct ObservabilityOverrides {
  std::string objective;  ///< replaces objective.name: paper | los-change | estimation
  long seed = -1;         ///< replaces isres.seed when >= 0 (at most 2147483647)
};

/// Everything the command needs, in SI units (frames as in the file comment).
struct ObservabilityRequest {
  observability::ObservabilityProblem problem;  ///< geometry, burn bounds, window (paper §3)
  observability::ObjectiveKind objective = observability::ObjectiveKind::kPaper;
  observability::EstimationConfig estimation;  ///< the chaser's angles-only estimator
  observability::IsresOptions isres;     ///< seed, budgets, polish; progress: the caller's hook
  observability::PaperDirections paper;  ///< the paper's optimum and its directions A and B
  double paper_f = 0.0;          ///< the paper's value of eq. 23 at its optimum (echoed)
  std::string scenario;          ///< the scenario's source (echoed)
  nlohmann::json used;           ///< every scenario key read, with its value (echoed)
};

/// All scenario reads of the command: earth.mu_m3ps2 and earth.re_m (J2 is not part of the
/// HCW model and is not read), the table observability_params(), chaser.r_paper_m,
/// chaser.v_paper_mps, objective.name, objective.k0_term, estimation.prior_sigma_m,
/// estimation.prior_sigma_mps, isres.polish, compare.a_eps_theta_rad,
/// compare.b_eps_theta_rad; then Scenario::check_all_used. Throws config::ConfigError naming
/// the key (bad value, missing required key, unknown key).
ObservabilityRequest read_observability_request(const config::Scenario& sc,
                                                const ObservabilityOverrides& overrides = {});

struct ObservabilityResult {
  observability::ObjectiveKind objective = observability::ObjectiveKind::kPaper;
  observability::PlanResult plan;  ///< the planner's optimum, raw ISRES point, evaluations
  observability::PlanComparison comparison;  ///< optimum, no burn, paper, A, B; thinned history
  observability::IsresOptions isres;     ///< the options the plan ran with (echoed)
  observability::PaperDirections paper;  ///< echoed
  double paper_f = 0.0;        ///< echoed
  double runtime_s = 0.0;      ///< wall time of the plan (ISRES + polish) [s]
  std::size_t samples = 0;     ///< measurement samples t_k = k dt, k = 0..N
  std::string scenario;        ///< echoed
  nlohmann::json used;         ///< echoed
};

/// Samples and validates the problem and the estimator (std::invalid_argument naming the
/// field), plans (progress through req.isres.progress every 1000 evaluations, every 100 for
/// the estimation objective) and compares with the paper's directions.
ObservabilityResult run_observability(const ObservabilityRequest& req);

/// The JSON of `evade plan observability --json` (without the "published", "plan_file" and
/// "uplink" entries the caller adds when it publishes or writes the plan).
nlohmann::json to_json(const ObservabilityResult& r);

/// The human-readable output: the optimum (θ, ε in frame P, Δv in RSW) and each compared
/// direction's value, largest azimuth change and estimate major axis.
std::string to_text(const ObservabilityResult& r);

}  // namespace evade::commands
