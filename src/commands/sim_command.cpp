// `evade sim` as a library call (sim_command.hpp): the closed-loop evasion simulation of
// paper 000 (Yao & Wang 2012, sec. 4 and Table 2), one run and an optional Monte Carlo over
// noise seeds, with the command's JSON and text forms.
#include "evade/commands/sim_command.hpp"

#include <cstdio>
#include <string>
#include <utility>

#include "evade/guidance/guidance_law.hpp"
#include "evade/commands/sim_overrides.hpp"

namespace evade::commands {
namespace {

SimParametersUsed parameters_used(const sim::SimConfig& cfg, const std::string& scenario) {
  SimParametersUsed p;
  p.max_accel_mps2 = cfg.guidance.max_accel_mps2;
  p.detect_before_tca_s = cfg.encounter.detect_before_tca_s;
  p.noise_rad = cfg.sensor.noise_rad;
  p.sensor_rate_hz = cfg.sensor.rate_hz;
  p.sensor_has_rates = cfg.sensor.has_rates;
  p.rate_noise_radps = cfg.sensor.rate_noise_radps;
  p.guidance_rate_hz = cfg.guidance.rate_hz;
  p.gravity = cfg.gravity;
  p.scenario = scenario;
  return p;
}

// A real-time run that fell behind the wall clock: how often and by how much.
std::string late_warning(const sim::RealtimeResult& r, double late_tolerance_s) {
  char buf[320];
  (void)std::snprintf(buf, sizeof buf,
                      "fell behind the wall clock in %ld of %ld steps (by more than "
                      "realtime.late_tolerance_s = %g s; worst %.3f ms); time was not slowed",
                      r.late_steps, r.steps, late_tolerance_s, r.late_max_ms);
  return buf;
}

// The single run: real-time against req.guidance's link, or lockstep against its endpoint
// (the in-process law when it has none).
void run_single(const SimCommandRequest& req, SimCommandResult* out) {
  const sim::SimGuidanceLink& g = req.guidance;
  if (g.make_realtime_link) {
    const std::unique_ptr<sim::RealtimeLink> link = g.make_realtime_link();
    out->realtime = sim::run_realtime_simulation(req.config, *link, req.on_sample);
    out->run = out->realtime->sim;
    if (out->realtime->late_steps > 0) {
      out->warnings.push_back(late_warning(*out->realtime, req.config.realtime.late_tolerance_s));
    }
    return;
  }
  const std::unique_ptr<sim::GuidanceEndpoint> endpoint =
      g.make_endpoint ? g.make_endpoint()
                      : sim::make_in_process_endpoint(req.config.guidance, req.config.guidance.armed);
  out->run = sim::run_simulation(req.config, *endpoint, req.on_sample);
}

sim::MonteCarloCampaign run_campaign(const SimCommandRequest& req) {
  if (req.monte_carlo) {
    return req.monte_carlo(req.config, req.runs, req.seed, req.threads, req.on_progress);
  }
  sim::MonteCarloCampaign c;
  c.result = sim::run_monte_carlo(req.config, req.runs, req.seed, req.threads, req.on_progress);
  return c;
}

nlohmann::json parameters_json(const SimParametersUsed& p) {
  // Each parameter under its own key (guidance.max_accel_mps2 is "guidance": {"max_accel_mps2"}).
  return {{"guidance", {{"max_accel_mps2", p.max_accel_mps2}, {"rate_hz", p.guidance_rate_hz}}},
          {"encounter", {{"detect_before_tca_s", p.detect_before_tca_s}}},
          {"sensor",
           {{"noise_rad", p.noise_rad},
            {"rate_hz", p.sensor_rate_hz},
            {"has_rates", p.sensor_has_rates},
            {"rate_noise_radps", p.rate_noise_radps}}},
          {"gravity", p.gravity == GravityModel::kTwoBody ? "two_body" : "two_body_j2"},
          {"scenario", p.scenario}};
}

void add_final_status(const guidance::GuidanceStatus& s, nlohmann::json* j) {
  (*j)["final_mode"] = guidance::mode_name(s.mode);
  (*j)["final_reason"] = guidance::reason_name(s.reason);
  (*j)["guidance_dv_used_mps"] = s.dv_used_mps;
  (*j)["meas_accepted"] = s.meas_accepted;
  (*j)["meas_rejected"] = s.meas_rejected;
  (*j)["filter_reinits"] = s.filter_reinits;
}

void add_realtime(const sim::RealtimeResult& r, nlohmann::json* j) {
  (*j)["command_age_ms_p50"] = r.command_age_ms_p50;
  (*j)["command_age_ms_p99"] = r.command_age_ms_p99;
  (*j)["command_age_ms_max"] = r.command_age_ms_max;
  (*j)["commands_received"] = r.commands_received;
  (*j)["commands_discarded_old"] = r.commands_discarded_old;
  (*j)["commands_discarded_malformed"] = r.commands_discarded_malformed;
  (*j)["command_timeouts"] = r.command_timeouts;
  (*j)["sim_steps"] = r.steps;
  (*j)["sim_late_steps"] = r.late_steps;
  (*j)["sim_late_max_ms"] = r.late_max_ms;
  (*j)["start_utime_us"] = r.start_utime_us;
}

void add_monte_carlo(const SimMonteCarloSummary& m, nlohmann::json* j) {
  (*j)["runs"] = m.runs;
  (*j)["ranks"] = m.ranks;
  (*j)["seed"] = m.seed;
  (*j)["miss_m_min"] = m.result.miss_min_m;
  (*j)["miss_m_p5"] = m.result.miss_p5_m;
  (*j)["miss_m_p50"] = m.result.miss_p50_m;
  (*j)["miss_m_p95"] = m.result.miss_p95_m;
  (*j)["miss_m_max"] = m.result.miss_max_m;
  (*j)["miss_m_mean"] = m.result.miss_mean_m;
}

}  // namespace

SimCommandRequest read_sim_command_request(const config::Scenario& sc) {
  SimCommandRequest req;
  req.config = read_sim_config(sc);
  req.scenario_source = sc.source();
  req.scenario_used = sc.used();
  return req;
}

SimCommandResult run_sim_command(const SimCommandRequest& req) {
  SimCommandResult out;
  out.guidance = req.guidance.name;
  out.sensors_signed = req.guidance.sensors_signed;
  out.parameters = parameters_used(req.config, req.scenario_source);
  out.scenario_used = req.scenario_used;
  run_single(req, &out);
  if (!out.run.closest_approach_found) {
    char buf[96];
    (void)std::snprintf(buf, sizeof buf, "no closest approach within %g s",
                        req.config.encounter.max_duration_s);
    out.warnings.emplace_back(buf);
    return out;
  }
  if (req.runs > 0) {
    sim::MonteCarloCampaign c = run_campaign(req);
    out.reporting = c.reporting;
    out.monte_carlo = SimMonteCarloSummary{req.runs, req.seed, c.ranks, std::move(c.result)};
  }
  return out;
}

nlohmann::json to_json(const SimCommandResult& r) {
  nlohmann::json j;
  j["miss_m"] = r.run.miss_m;
  j["tca_s"] = r.run.tca_s;
  j["dv_mps"] = r.run.dv_mps;
  j["burn_s"] = r.run.burn_s;
  j["cycles"] = r.run.cycles;
  j["start_s"] = r.run.start_s;
  j["nominal_tca_s"] = r.run.nominal_tca_s;
  j["nominal_miss_m"] = r.run.nominal_miss_m;
  j["measurements"] = r.run.measurements;
  j["dropouts"] = r.run.dropouts;
  j["guidance"] = r.guidance;
  if (r.sensors_signed) j["sensors_signed"] = *r.sensors_signed;
  if (r.run.has_final_status) add_final_status(r.run.final_status, &j);
  j["parameters"] = parameters_json(r.parameters);
  if (r.realtime) add_realtime(*r.realtime, &j);
  if (r.monte_carlo) add_monte_carlo(*r.monte_carlo, &j);
  j["scenario_used"] = r.scenario_used;
  return j;
}

std::string to_text(const SimCommandResult& r) {
  char buf[400];
  (void)std::snprintf(buf, sizeof buf,
                      "miss %.4f m at TCA %.6f s after the run start (nominal miss %.4f m); dv "
                      "%.4f m/s, burn %.3f s, %ld cycles\n",
                      r.run.miss_m, r.run.tca_s, r.run.nominal_miss_m, r.run.dv_mps,
                      r.run.burn_s, r.run.cycles);
  std::string text = buf;
  if (r.monte_carlo) {
    const sim::MonteCarloResult& m = r.monte_carlo->result;
    (void)std::snprintf(buf, sizeof buf,
                        "monte carlo %d runs: miss p5 %.4f p50 %.4f p95 %.4f (min %.4f max "
                        "%.4f) m\n",
                        r.monte_carlo->runs, m.miss_p5_m, m.miss_p50_m, m.miss_p95_m,
                        m.miss_min_m, m.miss_max_m);
    text += buf;
  }
  return text;
}

}  // namespace evade::commands
