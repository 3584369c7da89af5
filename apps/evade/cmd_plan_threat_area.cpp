// `evade plan threat-area`: paper 001 (Yu, Wang, Sun 2017) — the chaser's potential threat area
// (sec. 2.2), the target's optimal evasive burn direction at fixed V_E (sec. 3, GA → ISRES),
// the smallest eliminating burn (sec. 4.2, Fig. 8 / Table 3), and the transfer-time study
// (Fig. 4). I/O only: the scenario is read by threat::read_threat_scenario and everything is
// computed by threat::run_threat_study (src/threat/); this file parses, prints and plots.
// --publish sends the evasive burn at V_E (threat::make_burn_plan: one RSW impulse at t0) as
// evade_burn_plan_t on LCM (plan_output.hpp, the same path as the other planners).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "run_program.hpp"
#include "evade/threat/burn_plan.hpp"
#include "plan_output.hpp"
#include "evade/threat/threat_scenario.hpp"
#include "evade/threat/threat_study.hpp"

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
  PlanOutputOptions out;
  CLI::Option* dv_opt = nullptr;
  CLI::Option* dt_opt = nullptr;
  CLI::Option* imp_opt = nullptr;
  CLI::Option* seed_opt = nullptr;
};

// Command-line overrides of scenario values; the library validates them like the scenario's
// (exit 2 on bad input).
void apply_overrides(const ThreatCmdOptions& o, ThreatScenario& in) {
  if (o.dv_opt->count() > 0) in.evasion_dv_mps = o.dv_mps;
  if (o.dt_opt->count() > 0) in.threat.transfer_s = o.dt_transfer_s;
  if (o.imp_opt->count() > 0) in.threat.impulses = o.impulses;
  if (o.seed_opt->count() > 0) in.evasion.seed = o.seed;
  if (!std::isfinite(in.evasion_dv_mps) || in.evasion_dv_mps < 0.0) {
    throw std::invalid_argument("--dv = " + std::to_string(in.evasion_dv_mps) +
                                " must be finite and >= 0");
  }
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

// The inputs and the chaser's cost at t0 without evasion.
nlohmann::json summary_json(const config::Scenario& sc, const ThreatScenario& in,
                            const ThreatStudy& s) {
  nlohmann::json j;
  j["scenario"] = sc.source();
  j["n_radps"] = in.geometry.n_radps;
  j["period_s"] = s.period_s;
  j["dt_transfer_s"] = in.threat.transfer_s;
  j["impulses"] = in.threat.impulses;
  j["dv_max_mps"] = in.threat.dv_max_mps;
  j["target_inclination_deg"] = in.target_inclination_deg;
  j["model"] =
      "HCW (RSW) about the target's original circular orbit; evaded target modelled by linear "
      "relative motion about that reference; chaser coasts then transfers in dt_transfer_s with "
      "the N-impulse minimum-dv plan; sweep over one chaser period from t0 (t0 included)";
  j["chaser_cost_t0_mps"] = s.chaser_cost_t0_mps;
  j["two_impulse_cost_t0_mps"] = s.two_impulse_cost_t0_mps;
  j["t0_bound_mps"] = s.t0_bound_mps;
  return j;
}

// How the direction search's result was certified.
nlohmann::json search_json(const EvasionResult& r, bool use_isres) {
  const SearchCertificate& c = r.certificate;
  const char* method = r.dv_mps == 0.0 ? "none (V_E = 0)" : use_isres ? "isres" : "sweep+bobyqa";
  return {{"method", method},
          {"grid_evaluations", c.grid_evaluations},
          {"local_evaluations", c.local_evaluations},
          {"local_starts", c.local_starts},
          {"local_spread_s", c.local_spread_s},
          {"lower_bound_arc_s", c.lower_bound_arc_s},
          {"bound_cells", c.bound_cells},
          {"open_cells", c.open_cells},
          {"certified", c.certified},
          {"certify_runtime_s", c.certify_runtime_s},
          {"evaluations", r.evaluations},
          {"wall_time_s", r.runtime_s}};
}

// The optimal direction at V_E.
void add_evasion_json(const ThreatStudy& s, bool use_isres, nlohmann::json& j) {
  const EvasionResult& r = s.evasion;
  j["runtime_s"] = s.runtime_s;
  j["dv_mps"] = r.dv_mps;
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
  j["search"] = search_json(r, use_isres);
}

void add_elimination_json(const ThreatStudy& s, nlohmann::json& j) {
  const EliminationResult& e = *s.elimination;
  j["eliminating_dv_mps"] = e.eliminating_dv_mps;
  j["eliminating_lower_bracket_mps"] = e.threatened_dv_mps;
  j["eliminating_alpha_rad"] = e.best.alpha_rad;
  j["eliminating_theta_rad"] = e.best.theta_rad;
  j["eliminating_dv_vvlh_mps"] = vec_json(e.best.dv_vvlh_mps);
  j["eliminating_to_dv_max_ratio"] = s.eliminating_to_dv_max_ratio;
  j["eliminating_over_t0_bound"] = s.eliminating_over_t0_bound;
  j["elimination_evaluations"] = e.evaluations;
  j["elimination_bisection_steps"] = e.bisection_steps;
  j["elimination_runtime_s"] = s.elimination_runtime_s;
}

nlohmann::json burn_row_json(const BurnSweepRow& row) {
  const EvasionResult& q = row.evasion;
  return {{"dv_mps", q.dv_mps},
          {"threat_arc_s", q.area.arc_s},
          {"threat_arc_deg", q.area.arc_deg},
          {"alpha_rad", q.alpha_rad},
          {"theta_rad", q.theta_rad},
          {"intervals", intervals_json(q.area)},
          {"evaluations", q.evaluations},
          {"runtime_s", row.runtime_s}};
}

nlohmann::json transfer_row_json(const TransferStudyRow& r) {
  nlohmann::json row = {{"dt_transfer_s", r.dt_transfer_s}};
  for (int n = 2; n <= 4; ++n) {
    row["cost_t0_mps_" + std::to_string(n) + "_impulses"] = r.cost_t0_mps[n - 2];
  }
  row["primer_max_t0"] = r.primer_max_t0;
  row["primer_lower_bound_t0_mps"] = r.primer_lower_bound_t0_mps;
  row["t0_bound_mps"] = r.t0_bound_mps;
  if (r.elimination) {
    row["eliminating_dv_mps"] = r.elimination->eliminating_dv_mps;
    row["eliminating_alpha_rad"] = r.elimination->best.alpha_rad;
    row["eliminating_theta_rad"] = r.elimination->best.theta_rad;
    row["runtime_s"] = r.elimination_runtime_s;
  }
  return row;
}

nlohmann::json study_json(const config::Scenario& sc, const ThreatScenario& in,
                          const ThreatStudy& s) {
  nlohmann::json j = summary_json(sc, in, s);
  add_evasion_json(s, in.evasion.use_isres, j);
  if (s.elimination) add_elimination_json(s, j);
  if (!s.sweep_dv.empty()) {
    j["sweep_dv"] = nlohmann::json::array();
    for (const auto& row : s.sweep_dv) j["sweep_dv"].push_back(burn_row_json(row));
  }
  if (!s.sweep_transfer.empty()) {
    j["sweep_transfer"] = nlohmann::json::array();
    for (const auto& row : s.sweep_transfer) j["sweep_transfer"].push_back(transfer_row_json(row));
  }
  j["total_runtime_s"] = s.total_runtime_s;
  j["parameters"] = sc.used();
  return j;
}

void progress_elim(double lo, double hi) {
  (void)std::fprintf(stderr, "  eliminating V_E in [%.3f, %.3f] m/s\n", lo, hi);
}

// Progress lines on stderr as each step finishes.
ThreatStudyProgress stderr_progress() {
  ThreatStudyProgress p;
  p.optimizing = [](double dv_mps, int evals) {
    (void)std::fprintf(stderr, "threat-area: optimizing the burn direction at V_E = %.3f m/s (<= %d evals)\n",
                       dv_mps, evals);
  };
  p.eliminating = [](double tol_mps) {
    (void)std::fprintf(stderr, "threat-area: bisection for the eliminating V_E (tol %.3f m/s)\n",
                       tol_mps);
  };
  p.bisection = progress_elim;
  p.burn_row = [](const BurnSweepRow& row) {
    const EvasionResult& q = row.evasion;
    (void)std::fprintf(stderr, "  V_E = %8.3f m/s: arc %9.2f s (%7.3f deg), alpha %.4f theta %.4f\n",
                       q.dv_mps, q.area.arc_s, q.area.arc_deg, q.alpha_rad, q.theta_rad);
  };
  p.transfer_row = [](const TransferStudyRow& r) {
    const std::string elim =
        r.elimination ? ", eliminating " + std::to_string(r.elimination->eliminating_dv_mps) + " m/s"
                      : "";
    (void)std::fprintf(stderr, "  dT = %7.1f s: J(t0) = %.3f m/s, bound %.3f m/s%s\n", r.dt_transfer_s,
                       r.j_t0_mps, r.t0_bound_mps, elim.c_str());
  };
  return p;
}

// Writes the JSON beside the PNG and runs scripts/plot_threat.py on it; false on failure.
bool write_plot(const std::string& png, const nlohmann::json& j) {
  const std::string tmp = png + ".json";
  std::ofstream(tmp) << j.dump(2) << "\n";
  const std::vector<std::string> argv = {python_interpreter(), plot_script("plot_threat.py"), tmp,
                                         png};
  if (run_program(argv, false) != 0) {
    (void)std::fprintf(stderr, "threat-area: plot failed: %s\n", command_line(argv).c_str());
    return false;
  }
  (void)std::fprintf(stderr, "threat-area: wrote %s (data %s)\n", png.c_str(), tmp.c_str());
  return true;
}

void print_text(const ThreatScenario& in, const ThreatStudy& s) {
  const EvasionResult& r = s.evasion;
  std::printf("threat area (paper 001): dT = %.1f s, %d impulses, dv_max = %.1f m/s\n",
              in.threat.transfer_s, in.threat.impulses, in.threat.dv_max_mps);
  std::printf("  chaser cost at t0 without evasion: %.3f m/s\n", s.chaser_cost_t0_mps);
  std::printf("  V_E = %.3f m/s: arc %.2f s (%.3f deg), alpha %.4f rad, theta %.4f rad, "
              "%ld evaluations, %.3f s\n",
              r.dv_mps, r.area.arc_s, r.area.arc_deg, r.alpha_rad, r.theta_rad, r.evaluations,
              s.runtime_s);
  const SearchCertificate& c = r.certificate;
  if (c.grid_evaluations > 0 && c.bound_cells > 0) {
    std::printf("  search: sweep %ld + BOBYQA %ld evaluations; no direction's arc is below "
                "%.2f s (%ld cells bounded, %s)\n",
                c.grid_evaluations, c.local_evaluations, c.lower_bound_arc_s, c.bound_cells,
                c.certified ? "certified" : "not certified within the tolerance");
  }
  if (s.elimination) {
    std::printf("  eliminating V_E = %.3f m/s (%.1f%% of dv_max; t0 bound %.3f m/s)\n",
                s.elimination->eliminating_dv_mps, 100.0 * s.eliminating_to_dv_max_ratio,
                s.t0_bound_mps);
  }
}

int run_threat_area(const ThreatCmdOptions& o) {
  const config::Scenario sc = load_scenario(o.common);
  ThreatScenario in = read_threat_scenario(sc);
  apply_overrides(o, in);
  ThreatStudyRequest request;
  request.eliminate = o.eliminate;
  request.sweep_dv_mps = o.sweep_dv;
  request.sweep_transfer_s = o.sweep_transfer;
  const ThreatStudy study = run_threat_study(in, request, stderr_progress());
  nlohmann::json j = study_json(sc, in, study);
  const int uplink_rc =
      plan_wanted(o.out) ? output_plan(o.out, make_burn_plan(study.evasion, plan_id(o.out)), &j) : 0;
  if (!o.plot.empty() && !write_plot(o.plot, j)) return 1;
  if (o.common.json) {
    print_json(j);
  } else {
    print_text(in, study);
  }
  return uplink_rc;  // 0, or the uplink's 3 (rejected) / 4 (no acknowledgement)
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<ThreatCmdOptions>();
  add_common_options(app, o->common);
  o->dv_opt = app.add_option("--dv", o->dv_mps, "evasion burn magnitude V_E [m/s]");
  o->dt_opt = app.add_option("--dt-transfer", o->dt_transfer_s, "chaser transfer time [s]");
  o->imp_opt = app.add_option("--impulses", o->impulses, "chaser impulses N (2..4) [-]");
  o->seed_opt = app.add_option("--seed", o->seed, "seed: ISRES RNG / the sweep's sample position in each cell [-]");
  app.add_flag("--eliminate", o->eliminate, "find the smallest V_E with no threat area");
  app.add_option("--sweep-dv", o->sweep_dv, "list of V_E [m/s]: arc for each (Fig. 8)")
      ->delimiter(',');
  app.add_option("--sweep-transfer", o->sweep_transfer,
                 "list of transfer times [s] (Fig. 4; with --eliminate: eliminating V_E)")
      ->delimiter(',');
  app.add_option("--plot", o->plot, "PNG file for the sweep plots (scripts/plot_threat.py)");
  add_plan_output_options(app, o->out);
  return [o]() { return run_threat_area(*o); };
}

const bool kRegistered = register_command(
    {{"plan", "threat-area"},
     "Threat-area evasive burn (paper 001): potential threat area, optimal direction, "
     "eliminating burn",
     &setup});

}  // namespace
}  // namespace evade::cli
