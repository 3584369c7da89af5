// `evade sim --plan FILE` as a library call (sim_plan_command.hpp): a burn-plan file flown
// by the in-process guidance law + plan executor on a scenario's objects, planned against
// delivered Δv per impulse.
#include "evade/commands/sim_plan_command.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "evade/config/json_values.hpp"
#include "evade/commands/plan_file.hpp"
#include "evade/sim/plan_run.hpp"
#include "evade/commands/sim_overrides.hpp"

namespace evade::commands {
namespace {

ImpulseFlown impulse_flown(const ImpulsiveBurn& p, double epoch_s, const sim::DeliveredBurn* b) {
  ImpulseFlown i;
  i.t_planned_s = epoch_s + p.t_s;
  i.dv_planned_mps = p.dv_rsw_mps.norm();
  i.dv_planned_rsw_mps = p.dv_rsw_mps;
  if (b == nullptr) return i;
  i.delivered = true;
  i.t_start_s = b->t_start_s;
  i.t_end_s = b->t_end_s;
  i.centre_offset_s = 0.5 * (b->t_start_s + b->t_end_s) - (epoch_s + p.t_s);
  i.dv_delivered_mps = b->dv_eci_mps.norm();
  i.dv_delivered_eci_mps = b->dv_eci_mps;
  return i;
}

nlohmann::json impulse_json(const ImpulseFlown& i) {
  nlohmann::json j = {{"t_planned_s", i.t_planned_s},
                      {"dv_planned_mps", i.dv_planned_mps},
                      {"dv_planned_rsw_mps", config::vec_json(i.dv_planned_rsw_mps)}};
  j["delivered"] = i.delivered;
  if (!i.delivered) return j;
  j["t_start_s"] = i.t_start_s;
  j["t_end_s"] = i.t_end_s;
  j["centre_offset_s"] = i.centre_offset_s;
  j["dv_delivered_mps"] = i.dv_delivered_mps;
  j["dv_delivered_eci_mps"] = config::vec_json(i.dv_delivered_eci_mps);
  return j;
}

// The run; the executor's rejection names the file and the plan's epoch.
sim::PlanRunResult fly(const SimPlanRequest& req, const PlanFile& f, const sim::PlanRunConfig& run_cfg) {
  const std::int64_t epoch_us =
      sim::kPlanRunUtime0 + static_cast<std::int64_t>(std::llround(req.plan_epoch_s * 1e6));
  const auto endpoint = sim::make_in_process_plan_endpoint(req.config.guidance, f.plan, epoch_us, f.frame);
  try {
    return sim::run_plan_simulation(run_cfg, *endpoint);
  } catch (const std::invalid_argument& e) {  // the executor's rejection reason
    throw std::invalid_argument(std::string(e.what()) + " (plan file '" + req.plan_file +
                                "', its t = 0 at " + std::to_string(req.plan_epoch_s) +
                                " s into the run; --plan-epoch-s S starts it later)");
  }
}

}  // namespace

SimPlanRequest read_sim_plan_request(const config::Scenario& sc) {
  SimPlanRequest req;
  req.config = read_sim_config(sc);
  req.scenario_source = sc.source();
  req.scenario_used = sc.used();
  return req;
}

SimPlanResult run_sim_plan(const SimPlanRequest& req) {
  const PlanFile f = read_plan_file(req.plan_file);
  const sim::PlanRunConfig run_cfg = sim::plan_run_config(req.config, f.plan, req.plan_epoch_s, req.after_s);
  const sim::PlanRunResult run = fly(req, f, run_cfg);
  SimPlanResult r;
  r.plan_file = req.plan_file;
  r.plan_id = f.plan.plan_id;
  r.frame = f.frame;
  r.plan_epoch_s = req.plan_epoch_s;
  for (int i = 0; i < f.plan.n_impulses; ++i) {
    const auto k = static_cast<std::size_t>(i);
    r.impulses.push_back(impulse_flown(f.plan.impulses[k], req.plan_epoch_s,
                                       k < run.burns.size() ? &run.burns[k] : nullptr));
  }
  r.burns_delivered = run.burns.size();
  r.all_delivered = run.burns.size() == static_cast<std::size_t>(f.plan.n_impulses);
  r.cycles = run.cycles;
  r.duration_s = run_cfg.duration_s;
  r.guidance_rate_hz = run_cfg.rate_hz;
  r.scenario_source = req.scenario_source;
  r.scenario_used = req.scenario_used;
  if (!r.all_delivered) {
    r.warnings.push_back(std::to_string(run.burns.size()) + " burns delivered for a plan of " +
                         std::to_string(f.plan.n_impulses) + " impulses");
  }
  return r;
}

nlohmann::json to_json(const SimPlanResult& r) {
  nlohmann::json j;
  nlohmann::json impulses = nlohmann::json::array();
  for (const ImpulseFlown& i : r.impulses) impulses.push_back(impulse_json(i));
  j["guidance"] = "in_process_plan";
  j["plan"] = {{"file", r.plan_file},
               {"plan_id", r.plan_id},
               {"frame", r.frame == guidance::PlanFrame::kEci ? "eci" : "rsw"},
               {"epoch_s", r.plan_epoch_s}};
  j["impulses"] = impulses;
  j["burns_delivered"] = r.burns_delivered;
  j["cycles"] = r.cycles;
  j["duration_s"] = r.duration_s;
  j["guidance_rate_hz"] = r.guidance_rate_hz;
  j["scenario"] = r.scenario_source;
  j["scenario_used"] = r.scenario_used;
  return j;
}

std::string to_text(const SimPlanResult& r) {
  std::string text;
  char buf[256];
  for (const ImpulseFlown& i : r.impulses) {
    if (!i.delivered) {
      (void)std::snprintf(buf, sizeof buf, "impulse at %.3f s: NOT delivered\n", i.t_planned_s);
    } else {
      (void)std::snprintf(buf, sizeof buf,
                          "impulse at %.3f s: planned %.9f m/s, delivered %.9f m/s over [%.3f, "
                          "%.3f] s (centre %+.3f s)\n",
                          i.t_planned_s, i.dv_planned_mps, i.dv_delivered_mps, i.t_start_s,
                          i.t_end_s, i.centre_offset_s);
    }
    text += buf;
  }
  return text;
}

}  // namespace evade::commands
