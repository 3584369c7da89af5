// `evade plan observability` as a library call (include/evade/observability/
// observability_command.hpp): paper 004 (Yu, Wang, Zhou, "Anti-rendezvous evasive maneuver
// considering spatial geometry"; eq. 23 and §3). The scenario reader, the run (sample, ISRES
// plan, comparison with the paper's directions) and the command's JSON and text.
#include "evade/commands/observability_command.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "evade/config/json_values.hpp"
#include "evade/config/read_params.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/earth_params.hpp"
#include "evade/observability/observability_params.hpp"

namespace evade::commands {
namespace {

// config::read_params over every row of `table` but the one at `key` (left as *cfg holds it).
template <class Cfg>
void read_params_except(const config::Scenario& sc, const std::string& prefix,
                        const ParamTable<Cfg>& table, const std::string& key, Cfg* cfg) {
  std::vector<Param<Cfg>> rows;
  for (const Param<Cfg>& p : table) {
    if (key != p.spec.key) rows.push_back(p);
  }
  config::read_params(sc, prefix, ParamTable<Cfg>{rows.data(), rows.size()}, cfg);
}

// μ and Re through the one Earth table (core/earth_params.hpp). J2 is no part of the HCW
// model of paper 004, so earth.j2 is neither read nor echoed (nor accepted).
EarthModel read_hcw_earth(const config::Scenario& sc) {
  EarthModel earth = kEarthDefault;
  read_params_except(sc, "earth.", earth_params(), "j2", &earth);
  return earth;
}

// The table; with a --seed override isres.seed is only marked used (not echoed), as before.
observability::ObservabilityParams read_observability_table(const config::Scenario& sc, long seed_override) {
  observability::ObservabilityParams p;
  config::require_params(sc, "", observability::observability_params(), p);
  if (seed_override < 0) {
    config::read_params(sc, "", observability::observability_params(), &p);
    return p;
  }
  if (seed_override > 2147483647L)
    throw std::invalid_argument("--seed " + std::to_string(seed_override) +
                                " is invalid: expected an integer in [0, 2147483647]");
  p.isres.seed = static_cast<int>(seed_override);
  sc.mark_used("isres.seed");
  read_params_except(sc, "", observability::observability_params(), "isres.seed", &p);
  return p;
}

observability::ObjectiveKind read_objective(const config::Scenario& sc, const std::string& override_name) {
  if (!override_name.empty()) {
    sc.mark_used("objective.name");
    return observability::parse_objective(override_name);
  }
  return observability::parse_objective(
      sc.get_enum("objective.name", {"paper", "los-change", "estimation"}, "paper"));
}

// estimation.prior_sigma_m / _mps: sqrt(diag P0), position then velocity (paper Table 1).
void read_prior_sigma(const config::Scenario& sc, observability::EstimationConfig* ec) {
  if (sc.has("estimation.prior_sigma_m"))
    ec->prior_sigma.head<3>() = sc.get_vec3("estimation.prior_sigma_m", 1e-6, 1e9);
  if (sc.has("estimation.prior_sigma_mps"))
    ec->prior_sigma.tail<3>() = sc.get_vec3("estimation.prior_sigma_mps", 1e-9, 1e5);
}

// compare.a_eps_theta_rad, compare.b_eps_theta_rad ([ε, θ] of directions A and B), and the
// paper's optimum from the table.
observability::PaperDirections read_paper(const config::Scenario& sc, const observability::ObservabilityParams& p) {
  const auto a = sc.get_double_list("compare.a_eps_theta_rad", -kTwoPi, kTwoPi, 2);
  const auto b = sc.get_double_list("compare.b_eps_theta_rad", -kTwoPi, kTwoPi, 2);
  if (a.size() != 2 || b.size() != 2)
    throw config::ConfigError(sc.source() +
                              ": compare.a_eps_theta_rad / b_eps_theta_rad: expected [eps, theta]");
  observability::PaperDirections d;
  d.a_eps_rad = a[0];
  d.a_theta_rad = a[1];
  d.b_eps_rad = b[0];
  d.b_theta_rad = b[1];
  d.optimum_theta_rad = p.paper.theta_rad;
  d.optimum_eps_rad = p.paper.eps_rad;
  return d;
}

// Every field of one direction (optimum, no burn, A, B), with the chosen objective's value.
nlohmann::json summary_json(const observability::DirectionSummary& d) {
  const bool burn = d.direction.burn;
  nlohmann::json j;
  j["name"] = d.direction.name;
  j["objective"] = observability::objective_name(d.objective);
  j["value"] = d.value;
  j["theta_rad"] = burn ? nlohmann::json(d.direction.theta_rad) : nlohmann::json(nullptr);
  j["eps_rad"] = burn ? nlohmann::json(d.direction.eps_rad) : nlohmann::json(nullptr);
  j["dv_lvlh_mps"] = config::vec_json(d.dv_lvlh_mps);
  j["dv_paper_mps"] = config::vec_json(d.dv_paper_mps);
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

nlohmann::json isres_json(const ObservabilityResult& r) {
  const observability::PlanResult& res = r.plan;
  return {{"seed", r.isres.seed},
          {"population", r.isres.population},
          {"max_evaluations", r.isres.max_evaluations},
          {"evaluations", res.isres_evaluations},
          {"raw_value", res.isres_value},
          {"raw_theta_rad", res.isres_theta_rad},
          {"raw_eps_rad", res.isres_eps_rad},
          {"polish", observability::polish_name(r.isres.polish)},
          {"nlopt_result", res.nlopt_result},
          {"runtime_s", r.runtime_s}};
}

}  // namespace

ObservabilityRequest read_observability_request(const config::Scenario& sc,
                                                const ObservabilityOverrides& overrides) {
  const EarthModel earth = read_hcw_earth(sc);
  const observability::ObservabilityParams p = read_observability_table(sc, overrides.seed);
  Vec6 x_chaser_p0;
  x_chaser_p0 << sc.get_vec3("chaser.r_paper_m", -1e8, 1e8),
      sc.get_vec3("chaser.v_paper_mps", -1e4, 1e4);
  ObservabilityRequest req;
  req.problem = p.problem(earth, x_chaser_p0);
  req.objective = read_objective(sc, overrides.objective);
  req.problem.k0 = sc.get_enum("objective.k0_term", {"zero", "limit"}, "zero") == "limit"
                       ? observability::K0Term::kLimit
                       : observability::K0Term::kZero;
  req.estimation = p.estimation_config();
  read_prior_sigma(sc, &req.estimation);
  req.isres = p.isres_options();
  req.isres.polish =
      observability::parse_polish(sc.get_enum("isres.polish", {"none", "bobyqa", "nelder-mead"}, "bobyqa"));
  req.paper = read_paper(sc, p);
  req.paper_f = p.paper.f;
  sc.check_all_used();
  req.scenario = sc.source();
  req.used = sc.used();
  return req;
}

ObservabilityResult run_observability(const ObservabilityRequest& req) {
  // sample validates the problem (std::invalid_argument naming the field).
  const observability::SampledProblem s = observability::sample(req.problem);
  validate(req.estimation);
  ObservabilityResult r;
  r.objective = req.objective;
  r.isres = req.isres;
  r.isres.progress_every = req.objective == observability::ObjectiveKind::kEstimation ? 100 : 1000;
  const auto t0 = std::chrono::steady_clock::now();
  r.plan = observability::plan_isres(s, req.objective, req.estimation, r.isres);
  r.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.comparison = observability::compare_with_paper(s, req.objective, req.estimation, r.plan, req.paper);
  r.paper = req.paper;
  r.paper_f = req.paper_f;
  r.samples = s.t_s.size();
  r.scenario = req.scenario;
  r.used = req.used;
  return r;
}

nlohmann::json to_json(const ObservabilityResult& r) {
  nlohmann::json j = summary_json(r.comparison.optimum);
  j["evaluations"] = r.plan.evaluations;
  j["isres"] = isres_json(r);
  // Convergence history: best value (own sense) after every 100th evaluation and the last.
  nlohmann::json hist = nlohmann::json::array();
  for (const observability::ConvergencePoint& h : r.comparison.history)
    hist.push_back({{"evaluations", h.evaluations}, {"best", h.best}});
  j["history"] = hist;
  j["compare"] = nlohmann::json::array();
  for (const observability::DirectionSummary& d : r.comparison.compare) j["compare"].push_back(summary_json(d));
  j["paper"] = {{"theta_rad", r.paper.optimum_theta_rad},
                {"eps_rad", r.paper.optimum_eps_rad},
                {"f", r.paper_f}};
  j["frame"] = "dv_lvlh_mps: RSW (x radial out, y along track, z normal); theta/eps and "
               "dv_paper_mps: paper frame (x to Earth centre, y = -along track, z normal)";
  j["samples"] = r.samples;
  j["scenario"] = r.scenario;
  j["used"] = r.used;
  return j;
}

std::string to_text(const ObservabilityResult& r) {
  const observability::PlanResult& res = r.plan;
  std::array<char, 320> line{};
  (void)std::snprintf(line.data(), line.size(),
                      "objective %s = %.9g (%d evaluations) at theta = %.6f rad, eps = %.6f "
                      "rad (paper frame P: x to Earth centre, y = -along track, z normal)\n",
                      observability::objective_name(r.objective).c_str(), res.value, res.evaluations,
                      res.theta_rad, res.eps_rad);
  std::string text = line.data();
  (void)std::snprintf(line.data(), line.size(),
                      "dv_lvlh_mps = [%.6f, %.6f, %.6f] (RSW: x radial out, y along track, "
                      "z normal; one impulse at t0)\n",
                      res.dv_rsw_mps.x(), res.dv_rsw_mps.y(), res.dv_rsw_mps.z());
  text += line.data();
  for (const observability::DirectionSummary& d : r.comparison.compare) {
    (void)std::snprintf(line.data(), line.size(),
                        "  %-14s value %.9g  max |d azimuth| %.6g rad  major axis %.1f m\n",
                        d.direction.name.c_str(), d.value, d.los_change.max_azimuth_change_rad,
                        d.estimation.major_axis_m);
    text += line.data();
  }
  return text;
}

}  // namespace evade::commands
