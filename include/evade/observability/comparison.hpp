// The planned burn of paper 004 (Yu, Wang, Zhou; eq. 23, §3) beside the alternatives the
// paper discusses: no burn, the paper's own optimum [ε, θ] and its directions A and B. Every
// direction is summarized the same way: the chosen objective's value, the eq. 23 value f,
// the change of the measured angles (eq. 3; objectives.hpp) and the chaser's angles-only
// estimate after the burn (estimation.hpp). The summaries are plain structs; the CLI prints
// them.
#pragma once

#include <string>
#include <vector>

#include "evade/observability/estimation.hpp"
#include "evade/observability/objectives.hpp"
#include "evade/observability/planner.hpp"

namespace evade::observability {

/// A burn direction to summarize: (ε, θ) in the paper frame P, or no burn at all.
struct BurnDirection {
  std::string name;
  bool burn = true;        ///< false: no burn (ε, θ ignored, Δv = 0)
  double eps_rad = 0.0;    ///< elevation ε
  double theta_rad = 0.0;  ///< azimuth θ
};

/// Everything the planner's objectives say about one direction.
struct DirectionSummary {
  BurnDirection direction;
  ObjectiveKind objective = ObjectiveKind::kPaper;
  double value = 0.0;                  ///< the chosen objective's value (its own sense)
  Vec3 dv_lvlh_mps = Vec3::Zero();     ///< Δv in RSW/LVLH [m/s]
  Vec3 dv_paper_mps = Vec3::Zero();    ///< Δv in the paper frame P [m/s]
  double paper_f = 0.0;                ///< eq. 23 (0 without a burn: every OA'_k = 0)
  LosChange los_change;                ///< change of the measured angles
  EstimationResult estimation;         ///< the chaser's estimate after the burn
};

/// Summary of one direction for objective k (the estimate is always computed with ec).
DirectionSummary describe_direction(const SampledProblem& s, ObjectiveKind k,
                                    const EstimationConfig& ec, const BurnDirection& d);

/// The paper's directions that the plan is compared with (scenario keys paper.*,
/// compare.a_eps_theta_rad, compare.b_eps_theta_rad).
struct PaperDirections {
  double optimum_eps_rad = 0.0;    ///< the paper's optimum ε
  double optimum_theta_rad = 0.0;  ///< the paper's optimum θ
  double a_eps_rad = 0.0;          ///< direction A
  double a_theta_rad = 0.0;
  double b_eps_rad = 0.0;          ///< direction B
  double b_theta_rad = 0.0;
};

/// Best value after a number of evaluations (the planner's convergence history, thinned).
struct ConvergencePoint {
  std::size_t evaluations = 0;
  double best = 0.0;
};

/// Every `every`-th entry of history (best value after each evaluation) and the last one.
/// every >= 1, else std::invalid_argument.
std::vector<ConvergencePoint> thin_history(const std::vector<double>& history,
                                           std::size_t every);

struct PlanComparison {
  DirectionSummary optimum;  ///< the plan (value = the planner's own value)
  std::vector<DirectionSummary> compare;  ///< no-burn, paper-optimum, A, B (in this order)
  std::vector<ConvergencePoint> history;  ///< thin_history(res.history, 100)
};

/// The plan res (objective k) and the paper's directions, each summarized.
PlanComparison compare_with_paper(const SampledProblem& s, ObjectiveKind k,
                                  const EstimationConfig& ec, const PlanResult& res,
                                  const PaperDirections& paper);

}  // namespace evade::observability
