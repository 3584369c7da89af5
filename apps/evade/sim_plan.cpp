// `evade sim --plan FILE` (sim_plan.hpp).
#include "sim_plan.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "evade/sim/plan_file.hpp"
#include "evade/sim/plan_run.hpp"

namespace evade::cli {
namespace {

nlohmann::json vec_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json impulse_json(const ImpulsiveBurn& p, double epoch_s, const sim::DeliveredBurn* b) {
  nlohmann::json i = {{"t_planned_s", epoch_s + p.t_s},
                      {"dv_planned_mps", p.dv_rsw_mps.norm()},
                      {"dv_planned_rsw_mps", vec_json(p.dv_rsw_mps)}};
  if (b == nullptr) {
    i["delivered"] = false;
    return i;
  }
  i["delivered"] = true;
  i["t_start_s"] = b->t_start_s;
  i["t_end_s"] = b->t_end_s;
  i["centre_offset_s"] = 0.5 * (b->t_start_s + b->t_end_s) - (epoch_s + p.t_s);
  i["dv_delivered_mps"] = b->dv_eci_mps.norm();
  i["dv_delivered_eci_mps"] = vec_json(b->dv_eci_mps);
  return i;
}

}  // namespace

int run_sim_plan(const SimPlanOptions& o, const sim::SimConfig& cfg, nlohmann::json* j) {
  const sim::PlanFile f = sim::read_plan_file(o.plan_file);
  const sim::PlanRunConfig run_cfg = sim::plan_run_config(cfg, f.plan, o.epoch_s, o.after_s);
  const std::int64_t epoch_us =
      sim::kPlanRunUtime0 + static_cast<std::int64_t>(std::llround(o.epoch_s * 1e6));
  const auto endpoint =
      sim::make_in_process_plan_endpoint(cfg.guidance, f.plan, epoch_us, f.frame);
  sim::PlanRunResult r;
  try {
    r = sim::run_plan_simulation(run_cfg, *endpoint);
  } catch (const std::invalid_argument& e) {  // the executor's rejection reason
    throw std::invalid_argument(std::string(e.what()) + " (plan file '" + o.plan_file +
                                "', its t = 0 at " + std::to_string(o.epoch_s) +
                                " s into the run; --plan-epoch-s S starts it later)");
  }
  nlohmann::json imp = nlohmann::json::array();
  for (int i = 0; i < f.plan.n_impulses; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    imp.push_back(impulse_json(f.plan.impulses[k], o.epoch_s, k < r.burns.size() ? &r.burns[k] : nullptr));
  }
  (*j)["guidance"] = "in_process_plan";
  (*j)["plan"] = {{"file", o.plan_file},
                  {"plan_id", f.plan.plan_id},
                  {"frame", f.frame == guidance::PlanFrame::kEci ? "eci" : "rsw"},
                  {"epoch_s", o.epoch_s}};
  (*j)["impulses"] = imp;
  (*j)["burns_delivered"] = r.burns.size();
  (*j)["cycles"] = r.cycles;
  (*j)["duration_s"] = run_cfg.duration_s;
  (*j)["guidance_rate_hz"] = run_cfg.rate_hz;
  if (r.burns.size() == static_cast<std::size_t>(f.plan.n_impulses)) return 0;
  (void)std::fprintf(stderr, "evade sim: %zu burns delivered for a plan of %d impulses\n",
                     r.burns.size(), f.plan.n_impulses);
  return 1;
}

void print_sim_plan(const nlohmann::json& j) {
  for (const nlohmann::json& i : j["impulses"]) {
    if (!i["delivered"].get<bool>()) {
      std::printf("impulse at %.3f s: NOT delivered\n", i["t_planned_s"].get<double>());
      continue;
    }
    std::printf("impulse at %.3f s: planned %.9f m/s, delivered %.9f m/s over [%.3f, %.3f] s "
                "(centre %+.3f s)\n",
                i["t_planned_s"].get<double>(), i["dv_planned_mps"].get<double>(),
                i["dv_delivered_mps"].get<double>(), i["t_start_s"].get<double>(),
                i["t_end_s"].get<double>(), i["centre_offset_s"].get<double>());
  }
}

}  // namespace evade::cli
