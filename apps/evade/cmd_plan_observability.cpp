// `evade plan observability`: the observability-minimizing evasive burn of paper 004 (Yu,
// Wang, Zhou; eq. 23 and §3). Reads the scenario (scenarios/seed4.yaml), plans with NLopt
// ISRES (+ local polish) over the chosen objective, compares with no burn and the paper's
// directions A and B (evade::observability::compare_with_paper), prints JSON, and with
// --publish sends the plan (observability::make_burn_plan) as evade_burn_plan_t on LCM
// (plan_output.hpp, shared by the planners); the library evade::observability stays LCM-free.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "plan_output.hpp"
#include "evade/core/constants.hpp"
#include "evade/observability/burn_plan.hpp"
#include "evade/observability/comparison.hpp"
#include "evade/observability/planner.hpp"

namespace evade::cli {
namespace {

using namespace evade::observability;

struct Options {
  CommonOptions common;
  std::string objective;   // overrides objective.name when given
  long seed = -1;          // overrides isres.seed when >= 0
  PlanOutputOptions out;
};

// Everything the command reads from the scenario (and the --objective / --seed overrides).
struct Inputs {
  ObservabilityProblem problem;
  std::string objective;
  EstimationConfig estimation;
  IsresOptions isres;
  PaperDirections paper;
  double paper_f = 0.0;  // the paper's value of eq. 23 at its optimum (echoed)
};

// earth.*, evader.altitude_m, chaser.*, burn.*, observation.* (in this order).
void read_problem(config::Scenario& sc, ObservabilityProblem* p) {
  const double mu = sc.get_double("earth.mu_m3ps2", 1e13, 1e15, 3.986004418e14);
  const double re = sc.get_double("earth.re_m", 1e6, 1e7, 6378137.0);
  const double alt = sc.get_double("evader.altitude_m", 1e5, 1e8);
  p->n_radps = std::sqrt(mu / std::pow(re + alt, 3));
  const Vec3 r = sc.get_vec3("chaser.r_paper_m", -1e8, 1e8);
  const Vec3 v = sc.get_vec3("chaser.v_paper_mps", -1e4, 1e4);
  p->x_chaser_p0 << r, v;
  p->dv_mps = sc.get_double("burn.dv_mps", 1e-6, 1e4);
  p->theta_min_rad = sc.get_double("burn.theta_min_rad", -2.0 * kTwoPi, 2.0 * kTwoPi);
  p->theta_max_rad = sc.get_double("burn.theta_max_rad", -2.0 * kTwoPi, 2.0 * kTwoPi);
  p->eps_max_rad = sc.get_double("burn.eps_max_rad", 0.0, 0.5 * kPi);
  p->dt_obs_s = sc.get_double("observation.dt_s", 1e-3, 1e5);
  p->t_obs_s = sc.get_double("observation.window_s", 1e-3, 1e7);
}

EstimationConfig read_estimation(config::Scenario& sc) {
  EstimationConfig ec;
  ec.sigma_rad = sc.get_double("estimation.sigma_rad", 1e-12, 1.0, ec.sigma_rad);
  if (sc.has("estimation.prior_sigma_m"))
    ec.prior_sigma.head<3>() = sc.get_vec3("estimation.prior_sigma_m", 1e-6, 1e9);
  if (sc.has("estimation.prior_sigma_mps"))
    ec.prior_sigma.tail<3>() = sc.get_vec3("estimation.prior_sigma_mps", 1e-9, 1e5);
  ec.estimator_knows_burn = sc.get_bool("estimation.estimator_knows_burn", false);
  ec.max_iterations = static_cast<int>(sc.get_int("estimation.max_iterations", 1, 10000, 50));
  return ec;
}

IsresOptions read_isres(config::Scenario& sc, long seed) {
  IsresOptions io;
  io.seed = static_cast<std::uint64_t>(seed >= 0 ? (sc.mark_used("isres.seed"), seed)
                                                 : sc.get_int("isres.seed", 0, 2147483647L, 1));
  io.population = static_cast<int>(sc.get_int("isres.population", 0, 100000, 80));
  io.max_evaluations = static_cast<int>(sc.get_int("isres.max_evaluations", 1, 100000000L, 2400));
  io.xtol_rel = sc.get_double("isres.xtol_rel", 0.0, 1.0, 0.0);
  io.polish = parse_polish(sc.get_enum("isres.polish", {"none", "bobyqa", "nelder-mead"}, "bobyqa"));
  io.polish_max_evaluations = static_cast<int>(sc.get_int("isres.polish_max_evaluations", 1, 1000000, 400));
  return io;
}

// compare.a_eps_theta_rad, compare.b_eps_theta_rad, paper.* (in this order).
void read_paper(config::Scenario& sc, Inputs* in) {
  const auto a = sc.get_double_list("compare.a_eps_theta_rad", -kTwoPi, kTwoPi, 2);
  const auto b = sc.get_double_list("compare.b_eps_theta_rad", -kTwoPi, kTwoPi, 2);
  if (a.size() != 2 || b.size() != 2)
    throw config::ConfigError(sc.source() + ": compare.a_eps_theta_rad / b_eps_theta_rad: expected [eps, theta]");
  in->paper.a_eps_rad = a[0];
  in->paper.a_theta_rad = a[1];
  in->paper.b_eps_rad = b[0];
  in->paper.b_theta_rad = b[1];
  in->paper.optimum_theta_rad = sc.get_double("paper.theta_rad", -kTwoPi, kTwoPi, -3.231);
  in->paper.optimum_eps_rad = sc.get_double("paper.eps_rad", -kPi, kPi, 0.0);
  in->paper_f = sc.get_double("paper.f", -1e9, 1e9, 100.9991);
}

Inputs read_inputs(config::Scenario& sc, const Options& o) {
  Inputs in;
  read_problem(sc, &in.problem);
  in.objective = o.objective.empty()
      ? sc.get_enum("objective.name", {"paper", "los-change", "estimation"}, "paper")
      : (sc.mark_used("objective.name"), o.objective);
  in.problem.k0 = sc.get_enum("objective.k0_term", {"zero", "limit"}, "zero") == "limit"
                      ? K0Term::kLimit
                      : K0Term::kZero;
  in.estimation = read_estimation(sc);
  in.isres = read_isres(sc, o.seed);
  read_paper(sc, &in);
  sc.check_all_used();
  return in;
}

nlohmann::json vec_json(const Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

// Every field of one direction (optimum, no burn, A, B), with the chosen objective's value.
nlohmann::json summary_json(const DirectionSummary& d) {
  const bool burn = d.direction.burn;
  nlohmann::json j;
  j["name"] = d.direction.name;
  j["objective"] = objective_name(d.objective);
  j["value"] = d.value;
  j["theta_rad"] = burn ? nlohmann::json(d.direction.theta_rad) : nlohmann::json(nullptr);
  j["eps_rad"] = burn ? nlohmann::json(d.direction.eps_rad) : nlohmann::json(nullptr);
  j["dv_lvlh_mps"] = vec_json(d.dv_lvlh_mps);
  j["dv_paper_mps"] = vec_json(d.dv_paper_mps);
  j["paper_f"] = d.paper_f;
  j["los_change_sum_rad"] = d.los_change.sum_rad;
  j["max_azimuth_change_rad"] = d.los_change.max_azimuth_change_rad;
  j["max_elevation_change_rad"] = d.los_change.max_elevation_change_rad;
  j["estimation"] = {{"major_axis_m", d.estimation.major_axis_m},
                     {"in_plane_major_axis_m", d.estimation.in_plane_major_axis_m},
                     {"error_tf_m", d.estimation.error_tf_m},
                     {"converged", d.estimation.converged},
                     {"iterations", d.estimation.iterations}};
  return j;
}

// ISRES with progress on stderr; returns the wall time of the plan [s].
double plan_timed(const SampledProblem& s, ObjectiveKind kind, Inputs* in, PlanResult* res) {
  in->isres.progress_every = kind == ObjectiveKind::kEstimation ? 100 : 1000;
  in->isres.progress = [](int n, double best) {
    (void)std::fprintf(stderr, "plan observability: %d evaluations, best %.9g\n", n, best);
  };
  const auto t0 = std::chrono::steady_clock::now();
  *res = plan_isres(s, kind, in->estimation, in->isres);
  const double runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  (void)std::fprintf(stderr, "plan observability: done, %d evaluations in %.3f s\n", res->evaluations, runtime_s);
  return runtime_s;
}

nlohmann::json result_json(const Inputs& in, const PlanResult& res, const PlanComparison& c,
                           double runtime_s) {
  nlohmann::json j = summary_json(c.optimum);
  j["evaluations"] = res.evaluations;
  j["isres"] = {{"seed", in.isres.seed},
                {"population", in.isres.population},
                {"max_evaluations", in.isres.max_evaluations},
                {"evaluations", res.isres_evaluations},
                {"raw_value", res.isres_value},
                {"raw_theta_rad", res.isres_theta_rad},
                {"raw_eps_rad", res.isres_eps_rad},
                {"polish", polish_name(in.isres.polish)},
                {"nlopt_result", res.nlopt_result},
                {"runtime_s", runtime_s}};
  // Convergence history: best value (own sense) after every 100th evaluation and the last.
  nlohmann::json hist = nlohmann::json::array();
  for (const ConvergencePoint& h : c.history)
    hist.push_back({{"evaluations", h.evaluations}, {"best", h.best}});
  j["history"] = hist;
  j["compare"] = nlohmann::json::array();
  for (const DirectionSummary& d : c.compare) j["compare"].push_back(summary_json(d));
  j["paper"] = {{"theta_rad", in.paper.optimum_theta_rad},
                {"eps_rad", in.paper.optimum_eps_rad},
                {"f", in.paper_f}};
  j["frame"] = "dv_lvlh_mps: RSW (x radial out, y along track, z normal); theta/eps and "
               "dv_paper_mps: paper frame (x to Earth centre, y = -along track, z normal)";
  return j;
}

void print_text(const std::string& objective, const PlanResult& res, const PlanComparison& c) {
  std::printf("objective %s = %.9g at theta = %.6f rad, eps = %.6f rad (%d evaluations)\n",
              objective.c_str(), res.value, res.theta_rad, res.eps_rad, res.evaluations);
  std::printf("dv_lvlh_mps = [%.6f, %.6f, %.6f]\n", res.dv_rsw_mps.x(), res.dv_rsw_mps.y(),
              res.dv_rsw_mps.z());
  for (const DirectionSummary& d : c.compare)
    std::printf("  %-14s value %.9g  max |d azimuth| %.6g rad  major axis %.1f m\n",
                d.direction.name.c_str(), d.value, d.los_change.max_azimuth_change_rad,
                d.estimation.major_axis_m);
}

int run(const Options& o) {
  config::Scenario sc = load_scenario(o.common);
  Inputs in = read_inputs(sc, o);

  const ObjectiveKind kind = parse_objective(in.objective);
  const SampledProblem s = sample(in.problem);  // validates (std::invalid_argument -> exit 2)
  validate(in.estimation);
  PlanResult res;
  const double runtime_s = plan_timed(s, kind, &in, &res);
  const PlanComparison c = compare_with_paper(s, kind, in.estimation, res, in.paper);

  nlohmann::json j = result_json(in, res, c, runtime_s);
  j["samples"] = s.t_s.size();
  j["scenario"] = sc.source();
  j["used"] = sc.used();

  const int uplink_rc =
      plan_wanted(o.out) ? output_plan(o.out, make_burn_plan(res, plan_id(o.out)), &j) : 0;

  if (o.common.json) {
    print_json(j);
  } else {
    print_text(in.objective, res, c);
  }
  return uplink_rc;  // 0, or the uplink's 3 (rejected) / 4 (no acknowledgement)
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_common_options(app, o->common, "seed4");
  app.add_option("--objective", o->objective, "paper | los-change | estimation (default: scenario)")
      ->check(CLI::IsMember({"paper", "los-change", "estimation"}));
  app.add_option("--seed", o->seed, "ISRES seed [-] (default: scenario isres.seed)")
      ->check(CLI::Range(0L, 2147483647L));
  add_plan_output_options(app, o->out);
  return [o]() { return run(*o); };
}

const bool kRegistered = register_command(
    {{"plan", "observability"}, "Observability-minimizing evasive burn (paper 004)", &setup});

}  // namespace
}  // namespace evade::cli
