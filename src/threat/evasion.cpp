// Optimal evasive burn direction (min threat arc) and the smallest eliminating burn.
// Paper 001 (Yu, Wang, Sun 2017) sec. 3.1 (eq. 4: ΔV_opt from V_E, α, θ in VVLH; eq. 7: arc
// objective) and sec. 3.2 (GA: NLopt GN_ISRES as an option; by default the sweep search of
// evade/threat/direction_search.hpp). See evade/threat/evasion.hpp.
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <nlopt.hpp>

#include "evade/core/constants.hpp"
#include "evade/core/frames.hpp"
#include "evade/threat/direction_search.hpp"
#include "evade/threat/evasion.hpp"

namespace evade::threat {
namespace {

struct Objective {
  const ThreatAreaSolver* solver = nullptr;
  double dv_mps = 0.0;
  long evaluations = 0;
  DecisionCounts counts;
  double best_arc = 1e300;
  double best_alpha = 0.0, best_theta = 0.0;
  ThreatArea best_area;
};

double arc_objective(unsigned, const double* x, double*, void* data) {
  auto* o = static_cast<Objective*>(data);
  const ThreatArea a = o->solver->evaluate(evasion_dv_rsw(o->dv_mps, x[0], x[1]));
  ++o->evaluations;
  o->counts += a.counts;
  if (a.arc_s < o->best_arc) {
    o->best_arc = a.arc_s;
    o->best_alpha = x[0];
    o->best_theta = x[1];
    o->best_area = a;
  }
  return a.arc_s;
}

[[noreturn]] void bad(const std::string& f, double v, const std::string& allowed) {
  throw std::invalid_argument("evasion optimizer: " + f + " = " + std::to_string(v) +
                              " is invalid; allowed: " + allowed);
}

// The (α, θ) box of the search.
void check_box(const EvasionOptions& opt) {
  if (!(opt.alpha_min_rad < opt.alpha_max_rad) || opt.alpha_min_rad < -(0.5 * kPi) ||
      opt.alpha_max_rad > (0.5 * kPi)) {
    bad("alpha_min_rad", opt.alpha_min_rad, "-pi/2 <= alpha_min < alpha_max <= pi/2");
  }
  if (!(opt.theta_min_rad < opt.theta_max_rad) || opt.theta_min_rad < -kPi - 1e-12 ||
      opt.theta_max_rad > kPi + 1e-12) {
    bad("theta_min_rad", opt.theta_min_rad, "-pi <= theta_min < theta_max <= pi");
  }
}

void check_options(const EvasionOptions& opt) {
  if (opt.population < 2) bad("population", opt.population, ">= 2");
  if (opt.max_evaluations < 1) bad("max_evaluations", opt.max_evaluations, ">= 1");
  check_box(opt);
  if (opt.sweep_alpha_cells < 1) bad("sweep_alpha_cells", opt.sweep_alpha_cells, ">= 1");
  if (opt.sweep_theta_cells < 4) bad("sweep_theta_cells", opt.sweep_theta_cells, ">= 4");
  if (opt.local_starts < 0) bad("local_starts", opt.local_starts, ">= 0");
  if (!(opt.local_xtol_rad > 0.0)) bad("local_xtol_rad", opt.local_xtol_rad, "> 0");
  if (opt.certify_max_cells < 0) bad("certify_max_cells", opt.certify_max_cells, ">= 0");
  if (!(opt.certify_rel_tol > 0.0 && opt.certify_rel_tol < 1.0)) {
    bad("certify_rel_tol", opt.certify_rel_tol, "0 < tol < 1");
  }
}

// GN_ISRES over (α, θ) from the box's centre; the objective keeps the best point.
void isres_search(const EvasionOptions& opt, Objective& obj) {
  nlopt::srand(opt.seed);
  nlopt::opt o(nlopt::GN_ISRES, 2);
  o.set_lower_bounds({opt.alpha_min_rad, opt.theta_min_rad});
  o.set_upper_bounds({opt.alpha_max_rad, opt.theta_max_rad});
  o.set_population(static_cast<unsigned>(opt.population));
  o.set_maxeval(opt.max_evaluations);
  if (opt.stop_arc_s >= 0.0) o.set_stopval(opt.stop_arc_s);
  o.set_min_objective(arc_objective, &obj);
  std::vector<double> x = {0.5 * (opt.alpha_min_rad + opt.alpha_max_rad),
                           0.5 * (opt.theta_min_rad + opt.theta_max_rad)};
  double f = 0.0;
  try {
    o.optimize(x, f);
  } catch (const nlopt::roundoff_limited&) {
    // best point is tracked in obj
  }
}

}  // namespace

Vec3 evasion_dv_vvlh(double dv_mps, double alpha_rad, double theta_rad) {
  const double ca = std::cos(alpha_rad);
  return dv_mps * Vec3(ca * std::cos(theta_rad), ca * std::sin(theta_rad), -std::sin(alpha_rad));
}

Vec3 evasion_dv_rsw(double dv_mps, double alpha_rad, double theta_rad) {
  return rotation_rsw_to_vvlh().transpose() * evasion_dv_vvlh(dv_mps, alpha_rad, theta_rad);
}

EvasionResult optimize_evasion(const ThreatAreaSolver& solver, double dv_mps,
                               const EvasionOptions& opt) {
  if (!std::isfinite(dv_mps) || dv_mps < 0.0) {
    throw std::invalid_argument("evasion optimizer: dv_mps = " + std::to_string(dv_mps) +
                                " is invalid; allowed: finite, >= 0");
  }
  check_options(opt);
  const auto t0 = std::chrono::steady_clock::now();
  auto finish = [&](EvasionResult r) {
    r.dv_vvlh_mps = evasion_dv_vvlh(dv_mps, r.alpha_rad, r.theta_rad);
    r.dv_rsw_mps = evasion_dv_rsw(dv_mps, r.alpha_rad, r.theta_rad);
    r.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  };
  if (dv_mps > 0.0 && !opt.use_isres) return finish(sweep_direction_search(solver, dv_mps, opt));
  Objective obj;
  obj.solver = &solver;
  obj.dv_mps = dv_mps;
  if (dv_mps == 0.0) {
    const double x[2] = {0.0, 0.0};
    arc_objective(2, x, nullptr, &obj);
  } else {
    isres_search(opt, obj);
  }
  EvasionResult r;
  r.dv_mps = dv_mps;
  r.alpha_rad = obj.best_alpha;
  r.theta_rad = obj.best_theta;
  r.area = obj.best_area;
  r.evaluations = obj.evaluations;
  r.counts = obj.counts;
  return finish(r);
}

EliminationResult find_eliminating_dv(const ThreatAreaSolver& solver, const EvasionOptions& opt,
                                      double tol_mps, void (*progress)(double, double)) {
  if (!std::isfinite(tol_mps) || tol_mps <= 0.0) {
    throw std::invalid_argument("find_eliminating_dv: tol_mps = " + std::to_string(tol_mps) +
                                " is invalid; allowed: finite, > 0");
  }
  EliminationResult out;
  out.j_t0_mps = solver.min_cost_plan(0.0, Vec3::Zero()).cost_mps;
  out.bound_mps = solver.options().dv_max_mps - out.j_t0_mps;
  EvasionOptions o = opt;
  o.stop_arc_s = 0.0;
  auto eliminated = [&](double v, EvasionResult& r) {
    r = optimize_evasion(solver, v, o);
    out.evaluations += r.evaluations;
    return r.area.intervals.empty();
  };
  EvasionResult r;
  double lo = 0.0;
  if (eliminated(0.0, r)) {  // no threat even without evasion
    out.best = std::move(r);
    return out;
  }
  const double vmax = solver.options().dv_max_mps;
  double hi = vmax;
  while (!eliminated(hi, r)) {
    lo = hi;
    hi *= 1.5;
    if (progress != nullptr) progress(lo, hi);
    if (hi > 10.0 * vmax) {
      throw std::runtime_error("find_eliminating_dv: no burn up to 10 dv_max eliminates the "
                               "threat area");
    }
  }
  out.best = r;
  while (hi - lo > tol_mps) {
    const double mid = 0.5 * (lo + hi);
    if (eliminated(mid, r)) {
      hi = mid;
      out.best = r;
    } else {
      lo = mid;
    }
    ++out.bisection_steps;
    if (progress != nullptr) progress(lo, hi);
  }
  out.eliminating_dv_mps = hi;
  out.threatened_dv_mps = lo;
  return out;
}

}  // namespace evade::threat
