// Planner of the observability-minimizing burn (paper 004 §2.2). The paper optimizes (ε, θ)
// with a genetic algorithm (population 80, 30 generations); we use NLopt's ISRES (Improved
// Stochastic Ranking Evolution Strategy, Runarsson & Yao 2005, algorithm GN_ISRES) over the
// same box −3π/2 ≤ θ ≤ −π/2, |ε| ≤ 0.05 at fixed |Δv|, optionally followed by a local polish
// (LN_BOBYQA or LN_NELDERMEAD) started at the ISRES best point inside the same box.
//
// Objectives (objectives.hpp, estimation.hpp): `paper` (eq. 23, maximized), `los-change`
// (summed change of the measured angles, minimized), `estimation` (1σ major axis of the
// chaser's posterior position covariance at the end of the window, maximized). Internally the
// planner maximizes a score = value for maximized objectives and −value for minimized ones.
//
// Determinism: nlopt::srand(seed) is called before ISRES, so a given seed gives the same
// result (NLopt's RNG is process-global: do not run two plans concurrently in one process).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "evade/observability/estimation.hpp"
#include "evade/observability/objectives.hpp"

namespace evade::observability {

enum class ObjectiveKind { kPaper, kLosChange, kEstimation };

/// "paper", "los-change", "estimation" <-> the enum; parse throws std::invalid_argument.
ObjectiveKind parse_objective(const std::string& name);
std::string objective_name(ObjectiveKind k);
/// True if the objective is maximized (paper, estimation), false if minimized (los-change).
bool is_maximized(ObjectiveKind k);

/// Value of objective k for direction (ε, θ) (estimation config used only by kEstimation).
double evaluate_objective(ObjectiveKind k, const SampledProblem& s, const EstimationConfig& ec,
                          double eps_rad, double theta_rad);

enum class LocalPolish { kNone, kBobyqa, kNelderMead };
LocalPolish parse_polish(const std::string& name);  ///< "none", "bobyqa", "nelder-mead"
std::string polish_name(LocalPolish p);

struct IsresOptions {
  std::uint64_t seed = 1;          ///< nlopt::srand seed
  int population = 80;             ///< ISRES population (0: NLopt default 20 (n+1))
  int max_evaluations = 2400;      ///< ISRES evaluation budget (80 × 30 like the paper's GA)
  double xtol_rel = 0.0;           ///< ISRES relative x tolerance (0: off; budget-limited)
  LocalPolish polish = LocalPolish::kBobyqa;  ///< local polish after ISRES
  int polish_max_evaluations = 400;  ///< polish budget
  double polish_xtol_abs_rad = 1e-9; ///< polish absolute x tolerance [rad]
  /// Called every `progress_every` evaluations with (evaluations so far, best score so far).
  std::function<void(int, double)> progress;
  int progress_every = 500;
};

/// Throws std::invalid_argument on a bad option (population < 0 or 1..2, budgets < 1,
/// non-finite or negative tolerances).
void validate(const IsresOptions& o);

struct PlanResult {
  ObjectiveKind objective = ObjectiveKind::kPaper;
  double value = 0.0;              ///< objective value at the optimum (its own sense)
  double eps_rad = 0.0;            ///< optimum elevation ε
  double theta_rad = 0.0;          ///< optimum azimuth θ
  Vec3 dv_p_mps = Vec3::Zero();    ///< Δv in the paper frame P [m/s]
  Vec3 dv_rsw_mps = Vec3::Zero();  ///< Δv in RSW/LVLH (x radial, y along track, z normal) [m/s]
  int evaluations = 0;             ///< ISRES + polish objective evaluations
  int isres_evaluations = 0;       ///< of which ISRES
  double isres_value = 0.0;        ///< raw ISRES best value (before the polish)
  double isres_eps_rad = 0.0, isres_theta_rad = 0.0;  ///< raw ISRES best point
  std::vector<double> history;     ///< best value (own sense) after each evaluation
  std::string nlopt_result;        ///< NLopt's termination code of the last stage
};

/// Plans the burn. Validates the problem (via sample()), the estimation config and options.
PlanResult plan_isres(const SampledProblem& s, ObjectiveKind k, const EstimationConfig& ec,
                      const IsresOptions& o);

}  // namespace evade::observability
