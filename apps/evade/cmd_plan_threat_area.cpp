// `evade plan threat-area`: paper 001 (Yu, Wang, Sun 2017) — the chaser's potential threat area
// (sec. 2.2), the target's optimal evasive burn direction at fixed V_E (sec. 3, GA → ISRES),
// the smallest eliminating burn (sec. 4.2, Fig. 8 / Table 3), and the transfer-time study
// (Fig. 4). I/O only; the algorithms are in src/threat/.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "cli.hpp"
#include "evade/core/constants.hpp"
#include "evade/threat/evasion.hpp"

namespace evade::cli {
namespace {

using namespace evade::threat;

struct ThreatCmdOptions {
  CommonOptions common;
  double dv_mps = 0.0;
  double dt_transfer_s = 0.0;
  int impulses = 0;
  unsigned seed = 0;
  bool eliminate = false;
  std::vector<double> sweep_dv;
  std::vector<double> sweep_transfer;
  std::string plot;
  CLI::Option* dv_opt = nullptr;
  CLI::Option* dt_opt = nullptr;
  CLI::Option* imp_opt = nullptr;
  CLI::Option* seed_opt = nullptr;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

nlohmann::json vec_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json counts_json(const DecisionCounts& c) {
  return {{"two_impulse_accept", c.two_impulse_accept},
          {"bound_reject", c.bound_reject},
          {"sqp_threat", c.sqp_threat},
          {"sqp_safe", c.sqp_safe},
          {"plan_accept", c.plan_accept},
          {"total", c.total()}};
}

nlohmann::json intervals_json(const ThreatArea& a) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& iv : a.intervals) j.push_back({iv.start_s, iv.end_s});
  return j;
}

void progress_elim(double lo, double hi) {
  std::fprintf(stderr, "  eliminating V_E in [%.3f, %.3f] m/s\n", lo, hi);
}

std::string find_plot_script() {
  if (const char* env = std::getenv("EVADE_SCRIPT_DIR"); env && *env) {
    return std::string(env) + "/plot_threat.py";
  }
  for (const auto& d : config::scenario_search_dirs()) {
    const std::string p = d + "/../scripts/plot_threat.py";
    if (std::ifstream(p).good()) return p;
  }
  return "scripts/plot_threat.py";
}

int run_threat_area(const ThreatCmdOptions& o) {
  const config::Scenario sc = load_scenario(o.common);
  const double mu = sc.get_double("earth.mu_m3ps2", 1e13, 1e15, 3.986005e14);
  const double re = sc.get_double("earth.re_m", 1e6, 1e7, 6371110.0);
  const double alt = sc.get_double("target.altitude_m", 1e5, 1e8);
  const double incl_deg = sc.get_double("target.inclination_deg", 0.0, 180.0, 0.0);
  ThreatGeometry g;
  const double a_m = re + alt;
  g.n_radps = std::sqrt(mu / (a_m * a_m * a_m));
  g.chaser0_rsw << sc.get_vec3("chaser.relative_rsw_m", -1e8, 1e8),
      sc.get_vec3("chaser.relative_rsw_mps", -1e4, 1e4);
  ThreatOptions to;
  to.dv_max_mps = sc.get_double("chaser.dv_max_mps", 1e-6, 1e5);
  to.transfer_s = sc.get_double("transfer.dt_s", 1e-3, 1e6);
  to.impulses = static_cast<int>(sc.get_int("transfer.impulses", 2, 4));
  to.step_s = sc.get_double("sweep.step_s", 1e-3, 1e5, 5.0);
  to.edge_tol_s = sc.get_double("sweep.edge_tol_s", 0.0, 1e4, 0.05);
  to.threads = static_cast<int>(sc.get_int("sweep.threads", 1, 64, 2));
  double dv_mps = sc.get_double("evasion.dv_mps", 0.0, 1e5, 20.0);
  EvasionOptions eo;
  eo.population = static_cast<int>(sc.get_int("evasion.population", 2, 100000, 60));
  eo.max_evaluations = static_cast<int>(sc.get_int("evasion.max_evaluations", 1, 100000000, 1200));
  eo.seed = static_cast<std::uint32_t>(sc.get_int("evasion.seed", 0, 4294967295L, 1));
  eo.alpha_min_rad = sc.get_double("evasion.alpha_min_deg", -90.0, 90.0, -90.0) * kDegToRad;
  eo.alpha_max_rad = sc.get_double("evasion.alpha_max_deg", -90.0, 90.0, 90.0) * kDegToRad;
  eo.theta_min_rad = sc.get_double("evasion.theta_min_deg", -180.0, 180.0, -180.0) * kDegToRad;
  eo.theta_max_rad = sc.get_double("evasion.theta_max_deg", -180.0, 180.0, 180.0) * kDegToRad;
  const double elim_tol = sc.get_double("elimination.tol_mps", 1e-6, 1e3, 0.05);
  sc.mark_used("description");
  sc.check_all_used();
  // Command-line overrides go through the same validation in the library (exit 2 on bad).
  if (o.dv_opt->count() > 0) dv_mps = o.dv_mps;
  if (o.dt_opt->count() > 0) to.transfer_s = o.dt_transfer_s;
  if (o.imp_opt->count() > 0) to.impulses = o.impulses;
  if (o.seed_opt->count() > 0) eo.seed = o.seed;
  if (!std::isfinite(dv_mps) || dv_mps < 0.0) {
    throw std::invalid_argument("--dv = " + std::to_string(dv_mps) + " must be finite and >= 0");
  }

  const auto t_all = std::chrono::steady_clock::now();
  const ThreatAreaSolver solver(g, to);
  nlohmann::json j;
  j["scenario"] = sc.source();
  j["n_radps"] = g.n_radps;
  j["period_s"] = solver.period_s();
  j["dt_transfer_s"] = to.transfer_s;
  j["impulses"] = to.impulses;
  j["dv_max_mps"] = to.dv_max_mps;
  j["target_inclination_deg"] = incl_deg;
  j["model"] =
      "HCW (RSW) about the target's original circular orbit; evaded target modelled by linear "
      "relative motion about that reference; chaser coasts then transfers in dt_transfer_s with "
      "the N-impulse minimum-dv plan; sweep over one chaser period from t0 (t0 included)";
  const RendezvousPlan plan0 = solver.min_cost_plan(0.0, Vec3::Zero());
  j["chaser_cost_t0_mps"] = plan0.cost_mps;
  j["two_impulse_cost_t0_mps"] = solver.transfer().two_impulse_cost(
      solver.required_change(0.0, Vec3::Zero()));
  j["t0_bound_mps"] = to.dv_max_mps - plan0.cost_mps;

  std::fprintf(stderr, "threat-area: optimizing the burn direction at V_E = %.3f m/s (%d evals)\n",
               dv_mps, eo.max_evaluations);
  const auto t_opt = std::chrono::steady_clock::now();
  const EvasionResult r = optimize_evasion(solver, dv_mps, eo);
  j["runtime_s"] = seconds_since(t_opt);
  j["dv_mps"] = dv_mps;
  j["threat_arc_s"] = r.area.arc_s;
  j["threat_arc_deg"] = r.area.arc_deg;
  j["grid_arc_s"] = r.area.grid_arc_s;
  j["intervals"] = intervals_json(r.area);
  j["alpha_rad"] = r.alpha_rad;
  j["theta_rad"] = r.theta_rad;
  j["dv_vvlh_mps"] = vec_json(r.dv_vvlh_mps);
  j["dv_rsw_mps"] = vec_json(r.dv_rsw_mps);
  j["evaluations"] = r.evaluations;
  j["decisions"] = counts_json(r.counts);

  if (o.eliminate) {
    std::fprintf(stderr, "threat-area: bisection for the eliminating V_E (tol %.3f m/s)\n",
                 elim_tol);
    const auto t_el = std::chrono::steady_clock::now();
    const EliminationResult e = find_eliminating_dv(solver, eo, elim_tol, progress_elim);
    j["eliminating_dv_mps"] = e.eliminating_dv_mps;
    j["eliminating_lower_bracket_mps"] = e.threatened_dv_mps;
    j["eliminating_alpha_rad"] = e.best.alpha_rad;
    j["eliminating_theta_rad"] = e.best.theta_rad;
    j["eliminating_dv_vvlh_mps"] = vec_json(e.best.dv_vvlh_mps);
    j["eliminating_to_dv_max_ratio"] = e.eliminating_dv_mps / to.dv_max_mps;
    j["eliminating_over_t0_bound"] = e.eliminating_dv_mps / e.bound_mps;
    j["elimination_evaluations"] = e.evaluations;
    j["elimination_bisection_steps"] = e.bisection_steps;
    j["elimination_runtime_s"] = seconds_since(t_el);
  }

  if (!o.sweep_dv.empty()) {
    nlohmann::json rows = nlohmann::json::array();
    for (double v : o.sweep_dv) {
      const auto t1 = std::chrono::steady_clock::now();
      const EvasionResult q = optimize_evasion(solver, v, eo);
      std::fprintf(stderr, "  V_E = %8.3f m/s: arc %9.2f s (%7.3f deg), alpha %.4f theta %.4f\n",
                   v, q.area.arc_s, q.area.arc_deg, q.alpha_rad, q.theta_rad);
      rows.push_back({{"dv_mps", v},
                      {"threat_arc_s", q.area.arc_s},
                      {"threat_arc_deg", q.area.arc_deg},
                      {"alpha_rad", q.alpha_rad},
                      {"theta_rad", q.theta_rad},
                      {"intervals", intervals_json(q.area)},
                      {"evaluations", q.evaluations},
                      {"runtime_s", seconds_since(t1)}});
    }
    j["sweep_dv"] = rows;
  }

  if (!o.sweep_transfer.empty()) {
    nlohmann::json rows = nlohmann::json::array();
    for (double T : o.sweep_transfer) {
      ThreatOptions tt = to;
      tt.transfer_s = T;
      const ThreatAreaSolver s2(g, tt);
      nlohmann::json row = {{"dt_transfer_s", T}};
      const Vec6 d0 = s2.required_change(0.0, Vec3::Zero());
      for (int n = 2; n <= 4; ++n) {
        SqpOptions so;
        so.impulses = n;
        so.starts = 8;
        row["cost_t0_mps_" + std::to_string(n) + "_impulses"] =
            optimize_rendezvous(s2.transfer(), d0, so).cost_mps;
      }
      const PrimerBound pb = s2.transfer().primer_bound(d0);
      row["primer_max_t0"] = pb.primer_max;
      row["primer_lower_bound_t0_mps"] = pb.lower_bound_mps;
      const double jt0 = s2.min_cost_plan(0.0, Vec3::Zero()).cost_mps;
      row["t0_bound_mps"] = tt.dv_max_mps - jt0;
      if (o.eliminate) {
        const auto t1 = std::chrono::steady_clock::now();
        const EliminationResult e = find_eliminating_dv(s2, eo, elim_tol, nullptr);
        row["eliminating_dv_mps"] = e.eliminating_dv_mps;
        row["eliminating_alpha_rad"] = e.best.alpha_rad;
        row["eliminating_theta_rad"] = e.best.theta_rad;
        row["runtime_s"] = seconds_since(t1);
      }
      std::fprintf(stderr, "  dT = %7.1f s: J(t0) = %.3f m/s, bound %.3f m/s%s\n", T, jt0,
                   tt.dv_max_mps - jt0,
                   o.eliminate ? (", eliminating " +
                                  std::to_string(row["eliminating_dv_mps"].get<double>()) +
                                  " m/s").c_str()
                               : "");
      rows.push_back(row);
    }
    j["sweep_transfer"] = rows;
  }
  j["total_runtime_s"] = seconds_since(t_all);
  j["parameters"] = sc.used();

  if (!o.plot.empty()) {
    const std::string tmp = o.plot + ".json";
    std::ofstream(tmp) << j.dump(2) << "\n";
    const std::string cmd = "/usr/bin/python3 '" + find_plot_script() + "' '" + tmp + "' '" +
                            o.plot + "'";
    if (std::system(cmd.c_str()) != 0) {
      std::fprintf(stderr, "threat-area: plot failed: %s\n", cmd.c_str());
      return 1;
    }
    std::fprintf(stderr, "threat-area: wrote %s (data %s)\n", o.plot.c_str(), tmp.c_str());
  }

  if (o.common.json) {
    print_json(j);
  } else {
    std::printf("threat area (paper 001): dT = %.1f s, %d impulses, dv_max = %.1f m/s\n",
                to.transfer_s, to.impulses, to.dv_max_mps);
    std::printf("  chaser cost at t0 without evasion: %.3f m/s\n", plan0.cost_mps);
    std::printf("  V_E = %.3f m/s: arc %.2f s (%.3f deg), alpha %.4f rad, theta %.4f rad, "
                "%ld evaluations, %.3f s\n",
                dv_mps, r.area.arc_s, r.area.arc_deg, r.alpha_rad, r.theta_rad, r.evaluations,
                j["runtime_s"].get<double>());
    if (o.eliminate) {
      std::printf("  eliminating V_E = %.3f m/s (%.1f%% of dv_max; t0 bound %.3f m/s)\n",
                  j["eliminating_dv_mps"].get<double>(),
                  100.0 * j["eliminating_to_dv_max_ratio"].get<double>(),
                  j["t0_bound_mps"].get<double>());
    }
  }
  return 0;
}

const bool kRegistered = register_command(
    {"plan", "threat-area"},
    "Threat-area evasive burn (paper 001): potential threat area, optimal direction, "
    "eliminating burn",
    [](CLI::App& app) {
      auto o = std::make_shared<ThreatCmdOptions>();
      add_common_options(app, o->common);
      o->dv_opt = app.add_option("--dv", o->dv_mps, "evasion burn magnitude V_E [m/s]");
      o->dt_opt = app.add_option("--dt-transfer", o->dt_transfer_s, "chaser transfer time [s]");
      o->imp_opt = app.add_option("--impulses", o->impulses, "chaser impulses N (2..4)");
      o->seed_opt = app.add_option("--seed", o->seed, "ISRES random seed");
      app.add_flag("--eliminate", o->eliminate, "find the smallest V_E with no threat area");
      app.add_option("--sweep-dv", o->sweep_dv, "list of V_E [m/s]: arc for each (Fig. 8)")
          ->delimiter(',');
      app.add_option("--sweep-transfer", o->sweep_transfer,
                     "list of transfer times [s] (Fig. 4; with --eliminate: eliminating V_E)")
          ->delimiter(',');
      app.add_option("--plot", o->plot, "PNG file for the sweep plots (scripts/plot_threat.py)");
      return [o]() { return run_threat_area(*o); };
    });

}  // namespace
}  // namespace evade::cli
