// ISRES planner for paper 004's burn direction (§2.2: the paper uses a GA; we use NLopt
// GN_ISRES, Runarsson & Yao, IEEE TSMC-C 35(2), 2005) with an optional local polish.
#include "evade/observability/planner.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <nlopt.hpp>

namespace evade::observability {
namespace {

struct Context {
  const SampledProblem* s;
  const EstimationConfig* ec;
  ObjectiveKind kind;
  const IsresOptions* o;
  PlanResult* result;
  double best_score = -std::numeric_limits<double>::infinity();
  double best_eps = 0.0, best_theta = 0.0;
  int evaluations = 0;
};

double score_of(ObjectiveKind k, double value) { return is_maximized(k) ? value : -value; }

double nlopt_objective(const std::vector<double>& x, std::vector<double>& /*grad*/, void* data) {
  auto* c = static_cast<Context*>(data);
  const double value = evaluate_objective(c->kind, *c->s, *c->ec, x[0], x[1]);
  const double score = std::isfinite(value) ? score_of(c->kind, value)
                                            : -std::numeric_limits<double>::max();
  ++c->evaluations;
  if (score > c->best_score) {
    c->best_score = score;
    c->best_eps = x[0];
    c->best_theta = x[1];
  }
  c->result->history.push_back(score_of(c->kind, c->best_score));
  if (c->o->progress && c->o->progress_every > 0 && c->evaluations % c->o->progress_every == 0)
    c->o->progress(c->evaluations, score_of(c->kind, c->best_score));
  return score;
}

std::string run_stage(nlopt::opt& opt, std::vector<double>& x) {
  double f = 0.0;
  try {
    return nlopt_result_to_string(static_cast<nlopt_result>(opt.optimize(x, f)));
  } catch (const nlopt::roundoff_limited&) {
    return "NLOPT_ROUNDOFF_LIMITED";  // the best point found so far is kept by the context
  }
}

}  // namespace

ObjectiveKind parse_objective(const std::string& name) {
  if (name == "paper") return ObjectiveKind::kPaper;
  if (name == "los-change") return ObjectiveKind::kLosChange;
  if (name == "estimation") return ObjectiveKind::kEstimation;
  throw std::invalid_argument("objective '" + name + "' is unknown; allowed: paper, los-change, estimation");
}

std::string objective_name(ObjectiveKind k) {
  switch (k) {
    case ObjectiveKind::kPaper: return "paper";
    case ObjectiveKind::kLosChange: return "los-change";
    case ObjectiveKind::kEstimation: return "estimation";
  }
  return "?";
}

bool is_maximized(ObjectiveKind k) { return k != ObjectiveKind::kLosChange; }

double evaluate_objective(ObjectiveKind k, const SampledProblem& s, const EstimationConfig& ec,
                          double eps_rad, double theta_rad) {
  switch (k) {
    case ObjectiveKind::kPaper: return paper_objective(s, eps_rad, theta_rad);
    case ObjectiveKind::kLosChange: return los_change(s, eps_rad, theta_rad).sum_rad;
    case ObjectiveKind::kEstimation:
      return estimate_angles_only(s, ec, dv_paper_from_angles(eps_rad, theta_rad, s.problem.dv_mps))
          .major_axis_m;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

LocalPolish parse_polish(const std::string& name) {
  if (name == "none") return LocalPolish::kNone;
  if (name == "bobyqa") return LocalPolish::kBobyqa;
  if (name == "nelder-mead") return LocalPolish::kNelderMead;
  throw std::invalid_argument("polish '" + name + "' is unknown; allowed: none, bobyqa, nelder-mead");
}

std::string polish_name(LocalPolish p) {
  switch (p) {
    case LocalPolish::kNone: return "none";
    case LocalPolish::kBobyqa: return "bobyqa";
    case LocalPolish::kNelderMead: return "nelder-mead";
  }
  return "?";
}

void validate(const IsresOptions& o) {
  if (o.population < 0 || o.population == 1 || o.population == 2)
    throw std::invalid_argument("isres: population = " + std::to_string(o.population) +
                                " is invalid; allowed: 0 (NLopt default) or >= 3");
  if (o.max_evaluations < 1)
    throw std::invalid_argument("isres: max_evaluations = " + std::to_string(o.max_evaluations) +
                                " is invalid; allowed: >= 1");
  if (o.polish != LocalPolish::kNone && o.polish_max_evaluations < 1)
    throw std::invalid_argument("isres: polish_max_evaluations = " +
                                std::to_string(o.polish_max_evaluations) + " is invalid; allowed: >= 1");
  if (!std::isfinite(o.xtol_rel) || o.xtol_rel < 0.0)
    throw std::invalid_argument("isres: xtol_rel = " + std::to_string(o.xtol_rel) +
                                " is invalid; allowed: finite, >= 0");
  if (!std::isfinite(o.polish_xtol_abs_rad) || o.polish_xtol_abs_rad <= 0.0)
    throw std::invalid_argument("isres: polish_xtol_abs_rad = " + std::to_string(o.polish_xtol_abs_rad) +
                                " is invalid; allowed: finite, > 0 rad");
}

PlanResult plan_isres(const SampledProblem& s, ObjectiveKind k, const EstimationConfig& ec,
                      const IsresOptions& o) {
  validate(s.problem);
  if (s.t_s.empty() || s.t_s.size() != s.r_chaser_p.size() || s.t_s.size() != s.b_r_p.size())
    throw std::invalid_argument("plan_isres: SampledProblem is not sampled (use sample())");
  validate(o);
  if (k == ObjectiveKind::kEstimation) validate(ec);
  const ObservabilityProblem& p = s.problem;

  PlanResult r;
  r.objective = k;
  r.history.reserve(static_cast<std::size_t>(o.max_evaluations) +
                    static_cast<std::size_t>(o.polish_max_evaluations));
  Context ctx{&s, &ec, k, &o, &r};
  const std::vector<double> lb{-p.eps_max_rad, p.theta_min_rad};
  const std::vector<double> ub{p.eps_max_rad, p.theta_max_rad};

  nlopt::srand(static_cast<unsigned long>(o.seed));
  nlopt::opt isres(nlopt::GN_ISRES, 2);
  isres.set_lower_bounds(lb);
  isres.set_upper_bounds(ub);
  isres.set_max_objective(nlopt_objective, &ctx);
  isres.set_maxeval(o.max_evaluations);
  if (o.population > 0) isres.set_population(static_cast<unsigned>(o.population));
  if (o.xtol_rel > 0.0) isres.set_xtol_rel(o.xtol_rel);
  std::vector<double> x{0.0, 0.5 * (p.theta_min_rad + p.theta_max_rad)};
  r.nlopt_result = run_stage(isres, x);
  r.isres_evaluations = ctx.evaluations;
  r.isres_eps_rad = ctx.best_eps;
  r.isres_theta_rad = ctx.best_theta;
  r.isres_value = score_of(k, ctx.best_score);

  if (o.polish != LocalPolish::kNone) {
    nlopt::opt local(o.polish == LocalPolish::kBobyqa ? nlopt::LN_BOBYQA : nlopt::LN_NELDERMEAD, 2);
    local.set_lower_bounds(lb);
    local.set_upper_bounds(ub);
    local.set_max_objective(nlopt_objective, &ctx);
    local.set_maxeval(o.polish_max_evaluations);
    local.set_xtol_abs(o.polish_xtol_abs_rad);
    // Initial step: a few mrad, inside the box (BOBYQA needs it smaller than the box).
    const double step_eps = std::max(1e-6, std::min(1e-2, 0.25 * (ub[0] - lb[0])));
    const double step_theta = std::min(1e-2, 0.25 * (ub[1] - lb[1]));
    local.set_initial_step(std::vector<double>{step_eps, step_theta});
    std::vector<double> xl{ctx.best_eps, ctx.best_theta};
    r.nlopt_result = run_stage(local, xl);
  }

  r.evaluations = ctx.evaluations;
  r.eps_rad = ctx.best_eps;
  r.theta_rad = ctx.best_theta;
  r.value = score_of(k, ctx.best_score);
  r.dv_p_mps = dv_paper_from_angles(r.eps_rad, r.theta_rad, p.dv_mps);
  r.dv_rsw_mps = rotation_rsw_to_paper() * r.dv_p_mps;
  return r;
}

}  // namespace evade::observability
