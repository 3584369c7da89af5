// `evade plan threat-area` as a library call: the request read from the scenario, the study
// run, its JSON (the keys, order and numbers the command has always printed) and its text.
// Paper 001 (Yu Dateng, Wang Hua, Sun Fuyu, "Optimal evasive maneuver strategy with potential
// threatening area being considered", 2017); see evade/commands/threat_area_command.hpp.
#include "evade/commands/threat_area_command.hpp"

#include <string>

#include "evade/config/json_values.hpp"

namespace evade::commands {
namespace {

using config::vec_json;

nlohmann::json counts_json(const threat::DecisionCounts& c) {
  return {{"two_impulse_accept", c.two_impulse_accept},
          {"bound_reject", c.bound_reject},
          {"sqp_threat", c.sqp_threat},
          {"sqp_safe", c.sqp_safe},
          {"plan_accept", c.plan_accept},
          {"total", c.total()}};
}

nlohmann::json intervals_json(const threat::ThreatArea& a) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& iv : a.intervals) j.push_back({iv.start_s, iv.end_s});
  return j;
}

// The inputs and the chaser's cost at t0 without evasion.
nlohmann::json threat_summary_json(const ThreatAreaResult& r) {
  const threat::ThreatScenario& in = r.scenario;
  const threat::ThreatStudy& s = r.study;
  nlohmann::json j;
  j["scenario"] = r.scenario_source;
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
nlohmann::json search_json(const threat::EvasionResult& r, bool use_isres) {
  const threat::SearchCertificate& c = r.certificate;
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
void add_evasion_json(const threat::ThreatStudy& s, bool use_isres, nlohmann::json& j) {
  const threat::EvasionResult& r = s.evasion;
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

void add_elimination_json(const threat::ThreatStudy& s, const threat::EliminationResult& e, nlohmann::json& j) {
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

nlohmann::json burn_row_json(const threat::BurnSweepRow& row) {
  const threat::EvasionResult& q = row.evasion;
  return {{"dv_mps", q.dv_mps},
          {"threat_arc_s", q.area.arc_s},
          {"threat_arc_deg", q.area.arc_deg},
          {"alpha_rad", q.alpha_rad},
          {"theta_rad", q.theta_rad},
          {"intervals", intervals_json(q.area)},
          {"evaluations", q.evaluations},
          {"runtime_s", row.runtime_s}};
}

nlohmann::json transfer_row_json(const threat::TransferStudyRow& r) {
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

}  // namespace

ThreatAreaRequest read_threat_area_request(const config::Scenario& sc) {
  ThreatAreaRequest req;
  req.scenario = read_threat_scenario(sc);
  req.scenario_source = sc.source();
  req.scenario_used = sc.used();
  return req;
}

ThreatAreaResult run_threat_area(const ThreatAreaRequest& req) {
  ThreatAreaResult r;
  r.scenario_source = req.scenario_source;
  r.scenario_used = req.scenario_used;
  r.scenario = req.scenario;
  r.study = threat::run_threat_study(req.scenario, req.study, req.progress);
  return r;
}

nlohmann::json to_json(const ThreatAreaResult& r) {
  const threat::ThreatStudy& s = r.study;
  nlohmann::json j = threat_summary_json(r);
  add_evasion_json(s, r.scenario.evasion.use_isres, j);
  if (s.elimination) add_elimination_json(s, *s.elimination, j);
  if (!s.sweep_dv.empty()) {
    j["sweep_dv"] = nlohmann::json::array();
    for (const auto& row : s.sweep_dv) j["sweep_dv"].push_back(burn_row_json(row));
  }
  if (!s.sweep_transfer.empty()) {
    j["sweep_transfer"] = nlohmann::json::array();
    for (const auto& row : s.sweep_transfer) j["sweep_transfer"].push_back(transfer_row_json(row));
  }
  j["total_runtime_s"] = s.total_runtime_s;
  j["parameters"] = r.scenario_used;
  return j;
}

}  // namespace evade::commands
