// `evade plan observability`: the observability-minimizing evasive burn of paper 004 (Yu,
// Wang, Zhou; eq. 23 and §3). Reads the scenario (scenarios/seed4.yaml), plans with NLopt
// ISRES (+ local polish) over the chosen objective, compares with no burn and the paper's
// directions A and B, prints JSON, and with --publish sends the plan as evade_burn_plan_t on
// LCM (evade::lcm_link::publish_burn_plan); the library evade::observability stays LCM-free.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "evade/core/constants.hpp"
#include "evade/lcm_link/burn_plan_publisher.hpp"
#include "evade/observability/burn_plan.hpp"
#include "evade/observability/planner.hpp"

namespace evade::cli {
namespace {

using namespace evade::observability;

struct Options {
  CommonOptions common;
  std::string objective;   // overrides objective.name when given
  long seed = -1;          // overrides isres.seed when >= 0
  bool publish = false;
  std::string lcm_url;     // empty: LCM default (LCM_DEFAULT_URL or udpm)
  std::string channel = "EVADE_BURN_PLAN";
  long seq = 0;
};

nlohmann::json vec_json(const Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

// Every field of one direction (optimum, no burn, A, B), with the chosen objective's value.
nlohmann::json describe(const std::string& name, const SampledProblem& s, ObjectiveKind k,
                        const EstimationConfig& ec, bool burn, double eps, double theta) {
  const Vec3 dv_p = burn ? dv_paper_from_angles(eps, theta, s.problem.dv_mps) : Vec3::Zero();
  const LosChange lc = los_change_dv(s, dv_p);
  const double f = burn ? paper_objective(s, eps, theta) : 0.0;  // no burn: every OA'_k = 0
  const EstimationResult est = estimate_angles_only(s, ec, dv_p);
  double value = 0.0;
  switch (k) {
    case ObjectiveKind::kPaper: value = f; break;
    case ObjectiveKind::kLosChange: value = lc.sum_rad; break;
    case ObjectiveKind::kEstimation: value = est.major_axis_m; break;
  }
  nlohmann::json j;
  j["name"] = name;
  j["objective"] = objective_name(k);
  j["value"] = value;
  j["theta_rad"] = burn ? nlohmann::json(theta) : nlohmann::json(nullptr);
  j["eps_rad"] = burn ? nlohmann::json(eps) : nlohmann::json(nullptr);
  j["dv_lvlh_mps"] = vec_json(rotation_rsw_to_paper() * dv_p);
  j["dv_paper_mps"] = vec_json(dv_p);
  j["paper_f"] = f;
  j["los_change_sum_rad"] = lc.sum_rad;
  j["max_azimuth_change_rad"] = lc.max_azimuth_change_rad;
  j["max_elevation_change_rad"] = lc.max_elevation_change_rad;
  j["estimation"] = {{"major_axis_m", est.major_axis_m},
                     {"in_plane_major_axis_m", est.in_plane_major_axis_m},
                     {"error_tf_m", est.error_tf_m},
                     {"converged", est.converged},
                     {"iterations", est.iterations}};
  return j;
}

int run(const Options& o) {
  config::Scenario sc = load_scenario(o.common);
  ObservabilityProblem p;
  const double mu = sc.get_double("earth.mu_m3ps2", 1e13, 1e15, 3.986004418e14);
  const double re = sc.get_double("earth.re_m", 1e6, 1e7, 6378137.0);
  const double alt = sc.get_double("evader.altitude_m", 1e5, 1e8);
  p.n_radps = std::sqrt(mu / std::pow(re + alt, 3));
  const Vec3 r = sc.get_vec3("chaser.r_paper_m", -1e8, 1e8);
  const Vec3 v = sc.get_vec3("chaser.v_paper_mps", -1e4, 1e4);
  p.x_chaser_p0 << r, v;
  p.dv_mps = sc.get_double("burn.dv_mps", 1e-6, 1e4);
  p.theta_min_rad = sc.get_double("burn.theta_min_rad", -2.0 * kTwoPi, 2.0 * kTwoPi);
  p.theta_max_rad = sc.get_double("burn.theta_max_rad", -2.0 * kTwoPi, 2.0 * kTwoPi);
  p.eps_max_rad = sc.get_double("burn.eps_max_rad", 0.0, 0.5 * kPi);
  p.dt_obs_s = sc.get_double("observation.dt_s", 1e-3, 1e5);
  p.t_obs_s = sc.get_double("observation.window_s", 1e-3, 1e7);
  const std::string objective = o.objective.empty()
      ? sc.get_enum("objective.name", {"paper", "los-change", "estimation"}, "paper")
      : (sc.mark_used("objective.name"), o.objective);
  p.k0 = sc.get_enum("objective.k0_term", {"zero", "limit"}, "zero") == "limit" ? K0Term::kLimit
                                                                                : K0Term::kZero;
  EstimationConfig ec;
  ec.sigma_rad = sc.get_double("estimation.sigma_rad", 1e-12, 1.0, ec.sigma_rad);
  if (sc.has("estimation.prior_sigma_m"))
    ec.prior_sigma.head<3>() = sc.get_vec3("estimation.prior_sigma_m", 1e-6, 1e9);
  if (sc.has("estimation.prior_sigma_mps"))
    ec.prior_sigma.tail<3>() = sc.get_vec3("estimation.prior_sigma_mps", 1e-9, 1e5);
  ec.estimator_knows_burn = sc.get_bool("estimation.estimator_knows_burn", false);
  ec.max_iterations = static_cast<int>(sc.get_int("estimation.max_iterations", 1, 10000, 50));
  IsresOptions io;
  io.seed = static_cast<std::uint64_t>(o.seed >= 0 ? (sc.mark_used("isres.seed"), o.seed)
                                                   : sc.get_int("isres.seed", 0, 2147483647L, 1));
  io.population = static_cast<int>(sc.get_int("isres.population", 0, 100000, 80));
  io.max_evaluations = static_cast<int>(sc.get_int("isres.max_evaluations", 1, 100000000L, 2400));
  io.xtol_rel = sc.get_double("isres.xtol_rel", 0.0, 1.0, 0.0);
  io.polish = parse_polish(sc.get_enum("isres.polish", {"none", "bobyqa", "nelder-mead"}, "bobyqa"));
  io.polish_max_evaluations = static_cast<int>(sc.get_int("isres.polish_max_evaluations", 1, 1000000, 400));
  const auto a = sc.get_double_list("compare.a_eps_theta_rad", -kTwoPi, kTwoPi, 2);
  const auto b = sc.get_double_list("compare.b_eps_theta_rad", -kTwoPi, kTwoPi, 2);
  if (a.size() != 2 || b.size() != 2)
    throw config::ConfigError(sc.source() + ": compare.a_eps_theta_rad / b_eps_theta_rad: expected [eps, theta]");
  const double paper_theta = sc.get_double("paper.theta_rad", -kTwoPi, kTwoPi, -3.231);
  const double paper_eps = sc.get_double("paper.eps_rad", -kPi, kPi, 0.0);
  const double paper_f = sc.get_double("paper.f", -1e9, 1e9, 100.9991);
  sc.check_all_used();

  const ObjectiveKind kind = parse_objective(objective);
  const SampledProblem s = sample(p);  // validates (std::invalid_argument -> exit 2)
  validate(ec);
  io.progress_every = kind == ObjectiveKind::kEstimation ? 100 : 1000;
  io.progress = [](int n, double best) {
    std::fprintf(stderr, "plan observability: %d evaluations, best %.9g\n", n, best);
  };

  const auto t0 = std::chrono::steady_clock::now();
  const PlanResult res = plan_isres(s, kind, ec, io);
  const double runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::fprintf(stderr, "plan observability: done, %d evaluations in %.3f s\n", res.evaluations, runtime_s);

  nlohmann::json j = describe("optimum", s, kind, ec, true, res.eps_rad, res.theta_rad);
  j["value"] = res.value;
  j["evaluations"] = res.evaluations;
  j["isres"] = {{"seed", io.seed},
                {"population", io.population},
                {"max_evaluations", io.max_evaluations},
                {"evaluations", res.isres_evaluations},
                {"raw_value", res.isres_value},
                {"raw_theta_rad", res.isres_theta_rad},
                {"raw_eps_rad", res.isres_eps_rad},
                {"polish", polish_name(io.polish)},
                {"nlopt_result", res.nlopt_result},
                {"runtime_s", runtime_s}};
  // Convergence history: best value (own sense) after every 100th evaluation and the last.
  nlohmann::json hist = nlohmann::json::array();
  for (std::size_t i = 0; i < res.history.size(); ++i)
    if ((i + 1) % 100 == 0 || i + 1 == res.history.size())
      hist.push_back({{"evaluations", i + 1}, {"best", res.history[i]}});
  j["history"] = hist;
  j["compare"] = nlohmann::json::array({
      describe("no-burn", s, kind, ec, false, 0.0, 0.0),
      describe("paper-optimum", s, kind, ec, true, paper_eps, paper_theta),
      describe("A", s, kind, ec, true, a[0], a[1]),
      describe("B", s, kind, ec, true, b[0], b[1])});
  j["paper"] = {{"theta_rad", paper_theta}, {"eps_rad", paper_eps}, {"f", paper_f}};
  j["frame"] = "dv_lvlh_mps: RSW (x radial out, y along track, z normal); theta/eps and "
               "dv_paper_mps: paper frame (x to Earth centre, y = -along track, z normal)";
  j["samples"] = s.t_s.size();
  j["scenario"] = sc.source();
  j["used"] = sc.used();

  if (o.publish) {
    const std::int64_t utime =
        lcm_link::publish_burn_plan(o.lcm_url, o.channel, make_burn_plan(res, o.seq), o.seq);
    j["published"] = {{"channel", o.channel}, {"seq", o.seq}, {"utime", utime}};
  }

  if (o.common.json) {
    print_json(j);
  } else {
    std::printf("objective %s = %.9g at theta = %.6f rad, eps = %.6f rad (%d evaluations)\n",
                objective.c_str(), res.value, res.theta_rad, res.eps_rad, res.evaluations);
    std::printf("dv_lvlh_mps = [%.6f, %.6f, %.6f]\n", res.dv_rsw_mps.x(), res.dv_rsw_mps.y(),
                res.dv_rsw_mps.z());
    for (const auto& c : j["compare"])
      std::printf("  %-14s value %.9g  max |d azimuth| %.6g rad  major axis %.1f m\n",
                  c["name"].get<std::string>().c_str(), c["value"].get<double>(),
                  c["max_azimuth_change_rad"].get<double>(),
                  c["estimation"]["major_axis_m"].get<double>());
  }
  return 0;
}

const bool kRegistered = register_command(
    {"plan", "observability"}, "Observability-minimizing evasive burn (paper 004)",
    [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      add_common_options(app, o->common, "seed4");
      app.add_option("--objective", o->objective, "paper | los-change | estimation (default: scenario)")
          ->check(CLI::IsMember({"paper", "los-change", "estimation"}));
      app.add_option("--seed", o->seed, "ISRES seed (default: scenario isres.seed)")
          ->check(CLI::Range(0L, 2147483647L));
      app.add_flag("--publish", o->publish, "publish the plan as evade_burn_plan_t on LCM");
      app.add_option("--lcm-url", o->lcm_url, "LCM URL for --publish (default: LCM_DEFAULT_URL)");
      app.add_option("--channel", o->channel, "LCM channel for --publish")->capture_default_str();
      app.add_option("--seq", o->seq, "seq field of the published plan")->check(CLI::NonNegativeNumber);
      return [o]() { return run(*o); };
    });

}  // namespace
}  // namespace evade::cli
